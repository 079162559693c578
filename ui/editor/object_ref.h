#pragma once
// Names one object of a scene by kind and index, as the editor's selection and commands do.

#include "sim/model/scene.h"

#include <QString>

#include <compare>
#include <vector>

class QFont;

namespace carom::editor {

enum class ObjectKind { Ball, Plane, Cylinder, Box };
inline constexpr int kObjectKindCount = 4;
// Every kind, in ObjectKind's order (the outline's groups, a sorted selection's).
inline constexpr ObjectKind kObjectKinds[kObjectKindCount] = {
    ObjectKind::Ball, ObjectKind::Plane, ObjectKind::Cylinder, ObjectKind::Box};

struct ObjectRef {
  ObjectKind kind = ObjectKind::Ball;
  int index = 0;
  auto operator<=>(const ObjectRef&) const = default;
};

// Sorted by kind, then index; no repeats.
using Selection = std::vector<ObjectRef>;

Selection normalized(Selection selection);
// Whether `ref` names an object `scene` has.
bool exists(const Scene& scene, const ObjectRef& ref);
int objectCount(const Scene& scene, ObjectKind kind);
// The shared fields of any object: name, colour, restitution, unknown keys.
const ObjectInfo& objectInfo(const Scene& scene, const ObjectRef& ref);
ObjectInfo& objectInfo(Scene& scene, const ObjectRef& ref);
// The point an object is placed and dragged by: a ball's or box's centre, a plane's or
// cylinder's point.
Vec3 objectPosition(const Scene& scene, const ObjectRef& ref);
void setObjectPosition(Scene& scene, const ObjectRef& ref, const Vec3& position);

// "Ball", "Plane", "Cylinder", "Box", and the plural for groups, translated.
QString kindName(ObjectKind kind);
QString kindPluralName(ObjectKind kind);
// What the editor calls an object: its name, or its kind and index ("Ball 3") when it has none.
QString objectLabel(const Scene& scene, const ObjectRef& ref);
// A name (or label) as headings, legends and messages show it in `font`: elided in its middle,
// which keeps its start and a numbered end, to at most kShownNameWidth average characters, so
// that no name, even of the longest the format allows in wide letters, widens what shows it.
inline constexpr int kShownNameWidth = 24;
QString elidedName(const QString& name, const QFont& font);

// The selected objects copied into a scene of their own (world settings kept), and the reverse:
// `objects`' planes, cylinders, boxes and balls appended to `scene`, returning the new references.
Scene extract(const Scene& scene, const Selection& selection);
Selection append(Scene& scene, const Scene& objects);
// Where extract() puts each selected object: the same kinds, numbered from 0 per kind.
Selection extractedRefs(const Selection& selection);
// The reverse of extract(): the selected objects take the values `objects` holds for them.
void assign(Scene& scene, const Selection& selection, const Scene& objects);
// Removes the selected objects.
void remove(Scene& scene, const Selection& selection);
// The reverse of remove(): `objects`, as extract() took them, go back to the selected places.
void insert(Scene& scene, const Selection& selection, const Scene& objects);

}  // namespace carom::editor
