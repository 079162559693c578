#include "ui/editor/object_ref.h"

#include "ui/editor/object_kinds.h"

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

namespace {

// The member each type of object is placed and dragged by.
constexpr auto placePoint(const Ball&) {
  return &Ball::position;
}
constexpr auto placePoint(const Plane&) {
  return &Plane::point;
}
constexpr auto placePoint(const Cylinder&) {
  return &Cylinder::point;
}
constexpr auto placePoint(const Box&) {
  return &Box::center;
}

}  // namespace

int objectCount(const Scene& scene, ObjectKind kind) {
  return visitObjects(scene, kind,
                      [](const auto& objects) { return static_cast<int>(objects.size()); });
}

bool exists(const Scene& scene, const ObjectRef& ref) {
  return ref.index >= 0 && ref.index < objectCount(scene, ref.kind);
}

const ObjectInfo& objectInfo(const Scene& scene, const ObjectRef& ref) {
  return visitObjects(scene, ref.kind,
                      [&](const auto& objects) -> const ObjectInfo& { return objects[ref.index]; });
}

ObjectInfo& objectInfo(Scene& scene, const ObjectRef& ref) {
  return const_cast<ObjectInfo&>(objectInfo(std::as_const(scene), ref));
}

QString kindName(ObjectKind kind) {
  return QCoreApplication::translate("ObjectRef", kindInfo(kind).name);
}

QString kindPluralName(ObjectKind kind) {
  return QCoreApplication::translate("ObjectRef", kindInfo(kind).pluralName);
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
  return visitObjects(scene, ref.kind, [&](const auto& objects) {
    const auto& object = objects[ref.index];
    return object.*placePoint(object);
  });
}

void setObjectPosition(Scene& scene, const ObjectRef& ref, const Vec3& position) {
  visitObjects(scene, ref.kind, [&](auto& objects) {
    auto& object = objects[ref.index];
    object.*placePoint(object) = position;
  });
}

Scene extract(const Scene& scene, const Selection& selection) {
  Scene part;
  part.world = scene.world;
  for (const ObjectRef& ref : selection) {
    if (!exists(scene, ref)) continue;
    forEachKind([&](auto array, ObjectKind kind) {
      if (kind == ref.kind) (part.*array).push_back((scene.*array)[ref.index]);
    });
  }
  return part;
}

Selection append(Scene& scene, const Scene& objects) {
  Selection added;
  forEachKind([&](auto array, ObjectKind kind) {
    for (const auto& object : objects.*array) {
      added.push_back({kind, static_cast<int>((scene.*array).size())});
      (scene.*array).push_back(object);
    }
  });
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
  forEachKind([&](auto array, ObjectKind kind) {
    assignIndices(scene.*array, sorted, kind, objects.*array);
  });
}

void remove(Scene& scene, const Selection& selection) {
  forEachKind([&](auto array, ObjectKind kind) { eraseIndices(scene.*array, selection, kind); });
}

void insert(Scene& scene, const Selection& selection, const Scene& objects) {
  const Selection sorted = normalized(selection);
  forEachKind([&](auto array, ObjectKind kind) {
    insertIndices(scene.*array, sorted, kind, objects.*array);
  });
}

}  // namespace carom::editor
