#include "ui/editor/object_kinds.h"

#include <QCoreApplication>

namespace carom::editor {
namespace {

// In ObjectKind's order.
constexpr ObjectKindInfo kKinds[kObjectKindCount] = {
    {QT_TRANSLATE_NOOP("ObjectRef", "Ball"), QT_TRANSLATE_NOOP("ObjectRef", "Balls"), "balls",
     ShapeKind::Ball, ValidationSubject::Balls, &SceneObjectIndices::balls},
    {QT_TRANSLATE_NOOP("ObjectRef", "Plane"), QT_TRANSLATE_NOOP("ObjectRef", "Planes"), "planes",
     ShapeKind::Plane, ValidationSubject::Planes, &SceneObjectIndices::planes},
    {QT_TRANSLATE_NOOP("ObjectRef", "Cylinder"), QT_TRANSLATE_NOOP("ObjectRef", "Cylinders"),
     "cylinders", ShapeKind::Cylinder, ValidationSubject::Cylinders,
     &SceneObjectIndices::cylinders},
    {QT_TRANSLATE_NOOP("ObjectRef", "Box"), QT_TRANSLATE_NOOP("ObjectRef", "Boxes"), "boxes",
     ShapeKind::Box, ValidationSubject::Boxes, &SceneObjectIndices::boxes},
};

}  // namespace

const ObjectKindInfo& kindInfo(ObjectKind kind) {
  return kKinds[static_cast<int>(kind)];
}

ObjectKind kindOfShape(ShapeKind shape) {
  for (ObjectKind kind : kObjectKinds)
    if (kindInfo(kind).shape == shape) return kind;
  return ObjectKind::Ball;
}

std::optional<ObjectKind> kindOfSubject(ValidationSubject subject) {
  for (ObjectKind kind : kObjectKinds)
    if (kindInfo(kind).subject == subject) return kind;
  return std::nullopt;
}

}  // namespace carom::editor
