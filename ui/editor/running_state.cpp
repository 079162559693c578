#include "ui/editor/running_state.h"

#include <optional>

namespace carom::ui {
namespace {

// For each ball of `edited`, the index of the same ball in `shown` when the edit left it alone.
std::vector<std::optional<std::size_t>> matchUnchangedBalls(const std::vector<Ball>& shown,
                                                            const std::vector<Ball>& edited) {
  std::vector<std::optional<std::size_t>> match(edited.size());
  if (edited.size() >= shown.size()) {
    for (std::size_t i = 0; i < shown.size(); ++i)
      if (shown[i] == edited[i]) match[i] = i;
    return match;
  }
  std::size_t j = 0;
  for (std::size_t i = 0; i < edited.size(); ++i) {
    while (j < shown.size() && !(shown[j] == edited[i])) ++j;  // removed
    if (j == shown.size()) break;
    match[i] = j++;
  }
  return match;
}

}  // namespace

Scene withRunningBalls(const Scene& shown, const Scene& edited, const std::vector<Vec3>& positions,
                       const std::vector<Vec3>& velocities) {
  Scene start = edited;
  const std::vector<std::optional<std::size_t>> running =
      matchUnchangedBalls(shown.balls, edited.balls);
  for (std::size_t i = 0; i < start.balls.size(); ++i) {
    if (!running[i] || *running[i] >= positions.size() || *running[i] >= velocities.size())
      continue;
    start.balls[i].position = positions[*running[i]];
    start.balls[i].velocity = velocities[*running[i]];
  }
  return start;
}

}  // namespace carom::ui
