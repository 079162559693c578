#include "ui/editor/running_state.h"

#include <algorithm>

namespace carom::editor {
namespace {

std::vector<int> ballIndices(const Selection& refs) {
  std::vector<int> indices;
  for (const ObjectRef& ref : refs)
    if (ref.kind == ObjectKind::Ball) indices.push_back(ref.index);
  std::sort(indices.begin(), indices.end());
  return indices;
}

bool contains(const std::vector<int>& sorted, int index) {
  return std::binary_search(sorted.begin(), sorted.end(), index);
}

}  // namespace

Scene withRunningBalls(const Scene& edited, const SceneChange& change,
                       const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                       const std::vector<Vec3>& angularVelocities) {
  Scene start = edited;
  if (change.replaced) return start;
  const std::vector<int> removed = ballIndices(change.removed);
  const std::vector<int> inserted = ballIndices(change.inserted);
  const std::vector<int> changed = ballIndices(change.edited);
  // One pass in step: `before` walks the balls of the scene before the change, skipping those
  // removed; `after` walks the edited scene, skipping those inserted.
  int before = 0;
  for (int after = 0; after < static_cast<int>(start.balls.size()); ++after) {
    if (contains(inserted, after)) continue;
    while (contains(removed, before)) ++before;
    const std::size_t running = static_cast<std::size_t>(before++);
    if (contains(changed, after) || running >= positions.size() || running >= velocities.size())
      continue;
    start.balls[after].position = positions[running];
    start.balls[after].velocity = velocities[running];
    if (running < angularVelocities.size())
      start.balls[after].angularVelocity = angularVelocities[running];
  }
  return start;
}

}  // namespace carom::editor
