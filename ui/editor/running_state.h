#pragma once
// Edits applied to a running simulation: the balls an edit left alone keep where the run has
// taken them.

#include "sim/scene.h"

#include <vector>

namespace carom::ui {

// `edited`, with each ball the edit left alone (found in `shown`, the scene the run started
// from) at the run's `positions` and `velocities`, given in `shown`'s order. Every edit keeps
// the order of the balls it does not touch and changes balls in place, appends them or removes
// some, so one pass in step finds them.
Scene withRunningBalls(const Scene& shown, const Scene& edited, const std::vector<Vec3>& positions,
                       const std::vector<Vec3>& velocities);

}  // namespace carom::ui
