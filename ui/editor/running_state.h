#pragma once
// Edits applied to a running simulation: the balls an edit left alone keep where the run has
// taken them.

#include "sim/model/scene.h"
#include "ui/editor/scene_change.h"

#include <vector>

namespace carom::editor {

// `edited` (the scene after `change`), with each ball the change left alone at the run's
// `positions`, `velocities` and (when given) `angularVelocities`, in the order of the scene
// before the change. The balls the change edited or inserted keep the edit's values; a replaced
// scene is returned as it is.
Scene withRunningBalls(const Scene& edited, const SceneChange& change,
                       const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                       const std::vector<Vec3>& angularVelocities = {});

}  // namespace carom::editor
