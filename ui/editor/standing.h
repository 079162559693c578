#pragma once
// What an object stands on: the planes and the faces of boxes it touches from their outer
// side. Placing puts an object on such a surface; a move keeps the objects from passing through
// the surfaces they stood on at the press, and a cylinder given a length keeps its foot on the
// surface under it.

#include "sim/model/scene.h"
#include "ui/editor/object_ref.h"

#include <optional>
#include <vector>

namespace carom::editor {

struct Surface {
  Vec3 point;
  Vec3 normal;  // unit, out of the solid
};

// The surfaces object `ref` of `scene` stands on: those whose plane its lowest point along their
// normal touches, a box's face only when the object's centre is over it. The objects `ignored`
// names (the ones moved with it) carry none.
std::vector<Surface> surfacesUnder(const Scene& scene, const ObjectRef& ref,
                                   const Selection& ignored);

// `cylinder` given the length `length` (none: infinite). Standing on a surface of `scene` along
// its axis (a capped one's cap on it, an infinite one's point on it), it keeps its foot there: a
// capped one rises from it, an infinite one has its point there. Any other keeps its point, the
// middle of a capped one.
Cylinder withLength(const Scene& scene, const Cylinder& cylinder, std::optional<double> length);

}  // namespace carom::editor
