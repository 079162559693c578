#include "ui/editor/object_ref.h"

#include <QCoreApplication>
#include <QFontMetrics>

#include <algorithm>
#include <utility>

namespace carom::editor {

Selection normalized(Selection selection) {
  std::sort(selection.begin(), selection.end());
  selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
  return selection;
}

int objectCount(const Scene& scene, ObjectKind kind) {
  switch (kind) {
    case ObjectKind::Ball:
      return static_cast<int>(scene.balls.size());
    case ObjectKind::Plane:
      return static_cast<int>(scene.planes.size());
    case ObjectKind::Cylinder:
      return static_cast<int>(scene.cylinders.size());
    case ObjectKind::Box:
      return static_cast<int>(scene.boxes.size());
  }
  return 0;
}

bool exists(const Scene& scene, const ObjectRef& ref) {
  return ref.index >= 0 && ref.index < objectCount(scene, ref.kind);
}

const ObjectInfo& objectInfo(const Scene& scene, const ObjectRef& ref) {
  switch (ref.kind) {
    case ObjectKind::Plane:
      return scene.planes[ref.index];
    case ObjectKind::Cylinder:
      return scene.cylinders[ref.index];
    case ObjectKind::Box:
      return scene.boxes[ref.index];
    case ObjectKind::Ball:
      break;
  }
  return scene.balls[ref.index];
}

ObjectInfo& objectInfo(Scene& scene, const ObjectRef& ref) {
  return const_cast<ObjectInfo&>(objectInfo(std::as_const(scene), ref));
}

// In ObjectKind's order.
constexpr const char* kKindNames[] = {
    QT_TRANSLATE_NOOP("ObjectRef", "Ball"), QT_TRANSLATE_NOOP("ObjectRef", "Plane"),
    QT_TRANSLATE_NOOP("ObjectRef", "Cylinder"), QT_TRANSLATE_NOOP("ObjectRef", "Box")};
constexpr const char* kKindPluralNames[] = {
    QT_TRANSLATE_NOOP("ObjectRef", "Balls"), QT_TRANSLATE_NOOP("ObjectRef", "Planes"),
    QT_TRANSLATE_NOOP("ObjectRef", "Cylinders"), QT_TRANSLATE_NOOP("ObjectRef", "Boxes")};

QString kindName(ObjectKind kind) {
  return QCoreApplication::translate("ObjectRef", kKindNames[static_cast<int>(kind)]);
}

QString kindPluralName(ObjectKind kind) {
  return QCoreApplication::translate("ObjectRef", kKindPluralNames[static_cast<int>(kind)]);
}

QString objectLabel(const Scene& scene, const ObjectRef& ref) {
  const std::string& name = objectInfo(scene, ref).name;
  if (!name.empty()) return QString::fromStdString(name);
  // Numbered as in the validation's messages ("balls[3].radius").
  return QCoreApplication::translate("ObjectRef", "%1 %2").arg(kindName(ref.kind)).arg(ref.index);
}

QString elidedName(const QString& name, const QFont& font) {
  const QFontMetrics metrics(font);
  return metrics.elidedText(name, Qt::ElideMiddle, kShownNameWidth * metrics.averageCharWidth());
}

Vec3 objectPosition(const Scene& scene, const ObjectRef& ref) {
  switch (ref.kind) {
    case ObjectKind::Plane:
      return scene.planes[ref.index].point;
    case ObjectKind::Cylinder:
      return scene.cylinders[ref.index].point;
    case ObjectKind::Box:
      return scene.boxes[ref.index].center;
    case ObjectKind::Ball:
      break;
  }
  return scene.balls[ref.index].position;
}

void setObjectPosition(Scene& scene, const ObjectRef& ref, const Vec3& position) {
  switch (ref.kind) {
    case ObjectKind::Plane:
      scene.planes[ref.index].point = position;
      return;
    case ObjectKind::Cylinder:
      scene.cylinders[ref.index].point = position;
      return;
    case ObjectKind::Box:
      scene.boxes[ref.index].center = position;
      return;
    case ObjectKind::Ball:
      scene.balls[ref.index].position = position;
      return;
  }
}

Scene extract(const Scene& scene, const Selection& selection) {
  Scene part;
  part.world = scene.world;
  for (const ObjectRef& ref : selection) {
    if (!exists(scene, ref)) continue;
    switch (ref.kind) {
      case ObjectKind::Ball:
        part.balls.push_back(scene.balls[ref.index]);
        break;
      case ObjectKind::Plane:
        part.planes.push_back(scene.planes[ref.index]);
        break;
      case ObjectKind::Cylinder:
        part.cylinders.push_back(scene.cylinders[ref.index]);
        break;
      case ObjectKind::Box:
        part.boxes.push_back(scene.boxes[ref.index]);
        break;
    }
  }
  return part;
}

Selection append(Scene& scene, const Scene& objects) {
  Selection added;
  for (const Plane& plane : objects.planes) {
    added.push_back({ObjectKind::Plane, static_cast<int>(scene.planes.size())});
    scene.planes.push_back(plane);
  }
  for (const Cylinder& cylinder : objects.cylinders) {
    added.push_back({ObjectKind::Cylinder, static_cast<int>(scene.cylinders.size())});
    scene.cylinders.push_back(cylinder);
  }
  for (const Box& box : objects.boxes) {
    added.push_back({ObjectKind::Box, static_cast<int>(scene.boxes.size())});
    scene.boxes.push_back(box);
  }
  for (const Ball& ball : objects.balls) {
    added.push_back({ObjectKind::Ball, static_cast<int>(scene.balls.size())});
    scene.balls.push_back(ball);
  }
  return normalized(added);
}

Selection extractedRefs(const Selection& selection) {
  int next[kObjectKindCount] = {};
  Selection refs;
  for (const ObjectRef& ref : normalized(selection))
    refs.push_back({ref.kind, next[int(ref.kind)]++});
  return refs;
}

namespace {

template <typename T>
void assignIndices(std::vector<T>& items, const Selection& selection, ObjectKind kind,
                   const std::vector<T>& values) {
  std::size_t next = 0;
  for (const ObjectRef& ref : selection) {
    if (ref.kind != kind || next >= values.size()) continue;
    if (ref.index >= 0 && ref.index < static_cast<int>(items.size()))
      items[ref.index] = values[next];
    ++next;
  }
}

template <typename T>
void insertIndices(std::vector<T>& items, const Selection& selection, ObjectKind kind,
                   const std::vector<T>& values) {
  std::vector<int> places;
  for (const ObjectRef& ref : selection)
    if (ref.kind == kind) places.push_back(ref.index);
  if (places.empty()) return;
  if (places.front() >= static_cast<int>(items.size())) {
    // All after the last (an addition redone): appended, without rebuilding the array.
    items.insert(items.end(), values.begin(), values.end());
    return;
  }
  std::vector<T> merged;
  merged.reserve(items.size() + values.size());
  std::size_t kept = 0, inserted = 0;
  while (kept < items.size() || inserted < values.size()) {
    const bool insertHere = inserted < values.size() && inserted < places.size() &&
                            places[inserted] <= static_cast<int>(merged.size());
    if (insertHere || kept == items.size())
      merged.push_back(values[inserted++]);
    else
      merged.push_back(std::move(items[kept++]));
  }
  items = std::move(merged);
}

template <typename T>
void eraseIndices(std::vector<T>& items, const Selection& selection, ObjectKind kind) {
  std::vector<bool> doomed(items.size(), false);
  for (const ObjectRef& ref : selection)
    if (ref.kind == kind && ref.index >= 0 && ref.index < static_cast<int>(items.size()))
      doomed[ref.index] = true;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (doomed[i]) continue;
    // Never onto itself: a self-move leaves the strings (name, colour) empty.
    if (kept != i) items[kept] = std::move(items[i]);
    ++kept;
  }
  items.resize(kept);
}

}  // namespace

void assign(Scene& scene, const Selection& selection, const Scene& objects) {
  const Selection sorted = normalized(selection);
  assignIndices(scene.balls, sorted, ObjectKind::Ball, objects.balls);
  assignIndices(scene.planes, sorted, ObjectKind::Plane, objects.planes);
  assignIndices(scene.cylinders, sorted, ObjectKind::Cylinder, objects.cylinders);
  assignIndices(scene.boxes, sorted, ObjectKind::Box, objects.boxes);
}

void remove(Scene& scene, const Selection& selection) {
  eraseIndices(scene.balls, selection, ObjectKind::Ball);
  eraseIndices(scene.planes, selection, ObjectKind::Plane);
  eraseIndices(scene.cylinders, selection, ObjectKind::Cylinder);
  eraseIndices(scene.boxes, selection, ObjectKind::Box);
}

void insert(Scene& scene, const Selection& selection, const Scene& objects) {
  const Selection sorted = normalized(selection);
  insertIndices(scene.balls, sorted, ObjectKind::Ball, objects.balls);
  insertIndices(scene.planes, sorted, ObjectKind::Plane, objects.planes);
  insertIndices(scene.cylinders, sorted, ObjectKind::Cylinder, objects.cylinders);
  insertIndices(scene.boxes, sorted, ObjectKind::Box, objects.boxes);
}

}  // namespace carom::editor
