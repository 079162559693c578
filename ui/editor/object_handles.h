#pragma once
// The arrows a single selected object shows, and the edit a drag of one's tip makes, for each
// type of object: a ball's velocity (none at rest), a plane's normal from its point, an infinite
// cylinder's axis from its point; a capped cylinder's two ends, and the axis beyond the end its
// axis points to; a box's six faces, and over its top, out past a corner, the handle that turns
// it.

#include "sim/model/scene.h"
#include "ui/editor/object_ref.h"

#include <QString>

#include <functional>
#include <vector>

namespace carom::editor {

// What dragging a handle's tip does: point the object's direction at the cursor (a ball's
// velocity, a plane's normal, a cylinder's axis), move a box's face or a capped cylinder's end
// along its line with the opposite one fixed, or turn a box about its own up axis. With
// snapping on, a moved face or end makes the box's size or the cylinder's length a whole
// number of grid steps.
enum class HandleRole { Direction, BoxFace, CylinderEnd, BoxTurn };
struct Handle {
  Vec3 base;
  Vec3 tip;
  HandleRole role = HandleRole::Direction;
  int axis = 0;  // the box's own x, y or z: a face's, or y, the axis a turn is about
  int side = 1;  // a face or an end: +1 on the side its axis points to, -1 on the other
};

// A ball's velocity arrow is this many seconds of its flight long.
inline constexpr double kArrowSeconds = 0.5;

// The handles of `ref` in `scene`; a direction's arrow is `arrow` long.
std::vector<Handle> objectHandles(const Scene& scene, const ObjectRef& ref, double arrow);

// A drag of `grabbed`'s tip from `from`, where it was grabbed, to `point`. `size` gives the
// size or length a moved face or end makes (on the grid when snapping).
struct HandleDrag {
  Handle grabbed;
  Vec3 from;
  Vec3 point;
  std::function<double(double)> size;
};
// The edit `drag` makes of `ref` in `scene`, which holds the object as it was at the press;
// returns the command's text.
QString dragHandle(Scene& scene, const ObjectRef& ref, const HandleDrag& drag);

}  // namespace carom::editor
