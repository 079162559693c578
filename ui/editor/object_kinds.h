#pragma once
// What differs by kind of object, in one table, as Box2D registers its shape pairs in one: where
// a scene keeps each kind, and what each kind is called. Code that does one thing to any object
// writes an overload per object type and reaches it through visitObjects() or forEachKind(),
// instead of a switch on ObjectKind of its own.

#include "sim/geometry/ray_cast.h"
#include "sim/model/scene.h"
#include "sim/validation/validation.h"
#include "ui/editor/object_ref.h"

#include <bit>
#include <cstddef>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace carom::editor {

// The scene's array of each kind, in ObjectKind's order.
inline constexpr auto kObjectArrays =
    std::make_tuple(&Scene::balls, &Scene::planes, &Scene::cylinders, &Scene::boxes);

// What each kind is called, by the user and by the simulation.
struct ObjectKindInfo {
  const char* name;        // "Ball", translated in the "ObjectRef" context
  const char* pluralName;  // "Balls", the Outline's group
  const char* list;        // the scene file's list, "balls", as the validation's messages name it
  ShapeKind shape;         // as ray casts name it
  ValidationSubject subject;
  std::vector<std::size_t> SceneObjectIndices::*validated;  // its list for validateObjects()
};
const ObjectKindInfo& kindInfo(ObjectKind kind);
ObjectKind kindOfShape(ShapeKind shape);
// None for the world and the tolerances.
std::optional<ObjectKind> kindOfSubject(ValidationSubject subject);

// A set of kinds as bits: each kind's is 1 << ObjectKind.
inline int kindBit(ObjectKind kind) {
  return 1 << static_cast<int>(kind);
}
// The kind of a set that holds one.
inline ObjectKind kindOfBit(int bits) {
  return static_cast<ObjectKind>(std::countr_zero(static_cast<unsigned>(bits)));
}

// `visit(array, kind)` for each kind, in ObjectKind's order, with the member pointer to the
// scene's array of it (scene.*array).
template <typename Visit>
void forEachKind(Visit&& visit) {
  [&]<std::size_t... k>(std::index_sequence<k...>) {
    (visit(std::get<k>(kObjectArrays), kObjectKinds[k]), ...);
  }
  (std::make_index_sequence<kObjectKindCount>());
}

// `visit(objects)` on `scene`'s array of `kind`: its balls, planes, cylinders or boxes.
template <std::size_t k = 0, typename SceneType, typename Visit>
decltype(auto) visitObjects(SceneType& scene, ObjectKind kind, Visit&& visit) {
  if constexpr (k + 1 < kObjectKindCount) {
    if (kind != kObjectKinds[k])
      return visitObjects<k + 1>(scene, kind, std::forward<Visit>(visit));
  }
  return visit(scene.*std::get<k>(kObjectArrays));
}

}  // namespace carom::editor
