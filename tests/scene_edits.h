#pragma once
// Tests write an edit as the whole scene after it; this turns that into the document's own
// edit (objects changed in place, objects appended or removed from the end, or the world).

#include "ui/editor/scene_document.h"

#include <QString>

#include <algorithm>
#include <vector>

namespace carom::testing {

namespace detail {

template <typename T>
void compareObjects(const std::vector<T>& before, const std::vector<T>& after,
                    editor::ObjectKind kind, editor::Selection& changed, std::vector<T>& values,
                    std::vector<T>& appended, editor::Selection& removed) {
  const std::size_t common = std::min(before.size(), after.size());
  for (std::size_t i = 0; i < common; ++i) {
    if (before[i] == after[i]) continue;
    changed.push_back({kind, static_cast<int>(i)});
    values.push_back(after[i]);
  }
  for (std::size_t i = common; i < after.size(); ++i) appended.push_back(after[i]);
  for (std::size_t i = common; i < before.size(); ++i)
    removed.push_back({kind, static_cast<int>(i)});
}

}  // namespace detail

// One command for `edited`, which differs from the document's scene in one way only: some
// objects changed, some appended, some removed from the end, or the world.
inline QString applyEdit(editor::SceneDocument& document, const Scene& edited,
                         const QString& text) {
  const Scene& scene = document.scene();
  if (!(edited.world == scene.world)) return document.editWorld(edited.world, text);
  editor::Selection changed, removed;
  Scene values, appended;
  detail::compareObjects(scene.balls, edited.balls, editor::ObjectKind::Ball, changed, values.balls,
                         appended.balls, removed);
  detail::compareObjects(scene.planes, edited.planes, editor::ObjectKind::Plane, changed,
                         values.planes, appended.planes, removed);
  detail::compareObjects(scene.cylinders, edited.cylinders, editor::ObjectKind::Cylinder, changed,
                         values.cylinders, appended.cylinders, removed);
  detail::compareObjects(scene.boxes, edited.boxes, editor::ObjectKind::Box, changed, values.boxes,
                         appended.boxes, removed);
  if (!changed.empty()) return document.editObjects(changed, values, text);
  if (!removed.empty()) return document.removeObjects(removed, text);
  return document.addObjects(appended, text);
}

}  // namespace carom::testing
