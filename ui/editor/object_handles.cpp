#include "ui/editor/object_handles.h"

#include "sim/geometry/shapes.h"
#include "ui/editor/object_kinds.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>

namespace carom::editor {
namespace {

// The commands are the editing tools', in their words.
QString toolsText(const char* text) {
  return QCoreApplication::translate("carom::editor::EditorTools", text);
}

// `rotation` followed by a turn of `degrees` about the unit `axis`. A turn about the axis the
// box already turns about (always the case for an upright box turned about y) only changes its
// degrees, so that the file keeps the numbers the user expects.
Rotation turnedAbout(const std::optional<Rotation>& rotation, const Vec3& axis, double degrees) {
  if (!rotation) return Rotation{axis, degrees};
  const Vec3 own = rotation->axis.normalized();
  if (std::abs(own.dot(axis)) > 1.0 - 1e-12)
    return Rotation{rotation->axis, rotation->degrees + (own.dot(axis) > 0 ? degrees : -degrees)};
  constexpr double kRadians = std::numbers::pi / 180.0;
  const Eigen::AngleAxisd turned(Eigen::AngleAxisd(degrees * kRadians, axis) *
                                 Eigen::AngleAxisd(rotation->degrees * kRadians, own));
  return Rotation{turned.axis(), turned.angle() / kRadians};
}

std::vector<Handle> handlesOf(const Ball& ball, double) {
  if (ball.velocity.isZero()) return {};
  return {{ball.position, ball.position + kArrowSeconds * ball.velocity}};
}

std::vector<Handle> handlesOf(const Plane& plane, double arrow) {
  return {{plane.point, plane.point + arrow * plane.normal.normalized()}};
}

std::vector<Handle> handlesOf(const Cylinder& cylinder, double arrow) {
  const Vec3 axis = cylinder.axis.normalized();
  if (!cylinder.length) return {{cylinder.point, cylinder.point + arrow * axis}};
  std::vector<Handle> arrows;
  for (const int side : {1, -1}) {
    const Vec3 end = cylinder.point + side * 0.5 * *cylinder.length * axis;
    arrows.push_back({end, end + side * arrow * axis, HandleRole::CylinderEnd, 0, side});
  }
  // The turn goes on from the end's arrow, so that the two tips stay an arrow apart however
  // short the cylinder is.
  const Vec3 beyond = arrows.front().tip;
  arrows.push_back({beyond, beyond + arrow * axis});
  return arrows;
}

std::vector<Handle> handlesOf(const Box& box, double arrow) {
  const BoxShape shape = boxShape(box);
  std::vector<Handle> arrows;
  for (int k = 0; k < 3; ++k) {
    for (const int side : {1, -1}) {
      const Vec3 along = side * shape.axes.col(k);
      const Vec3 face = box.center + box.halfExtents[k] * along;
      arrows.push_back({face, face + arrow * along, HandleRole::BoxFace, k, side});
    }
  }
  const Vec3 top = box.center + box.halfExtents.y() * shape.axes.col(1);
  const Vec3 toCorner =
      box.halfExtents.x() * shape.axes.col(0) + box.halfExtents.z() * shape.axes.col(2);
  arrows.push_back({top, top + toCorner + arrow * toCorner.normalized(), HandleRole::BoxTurn, 1});
  return arrows;
}

QString dragged(Ball& ball, const HandleDrag& drag) {
  ball.velocity = (drag.point - ball.position) / kArrowSeconds;
  return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Change Velocity"));
}

QString dragged(Plane& plane, const HandleDrag& drag) {
  const Vec3 direction = drag.point - plane.point;
  if (direction.norm() > 0.0) plane.normal = direction.normalized();
  return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Turn Plane"));
}

QString dragged(Cylinder& cylinder, const HandleDrag& drag) {
  if (drag.grabbed.role == HandleRole::CylinderEnd) {
    const Vec3 along = drag.grabbed.side * cylinder.axis.normalized();
    const Vec3 fixedEnd = cylinder.point - 0.5 * *cylinder.length * along;
    // The end follows the tip; the validation refuses a length of zero or less.
    cylinder.length = drag.size(*cylinder.length + along.dot(drag.point - drag.from));
    cylinder.point = fixedEnd + 0.5 * *cylinder.length * along;
    return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Resize Cylinder"));
  }
  const Vec3 direction = drag.point - cylinder.point;
  if (direction.norm() > 0.0) cylinder.axis = direction.normalized();
  return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Turn Cylinder"));
}

QString dragged(Box& box, const HandleDrag& drag) {
  const BoxShape shape = boxShape(box);
  if (drag.grabbed.role == HandleRole::BoxTurn) {
    // The angle the tip has swept about the up axis through the centre since the press.
    const Vec3 up = shape.axes.col(1);
    Vec3 from = drag.from - box.center;
    Vec3 to = drag.point - box.center;
    from -= up.dot(from) * up;
    to -= up.dot(to) * up;
    const double radians = std::atan2(up.dot(from.cross(to)), from.dot(to));
    box.rotation = turnedAbout(box.rotation, up, radians * 180.0 / std::numbers::pi);
    return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Turn Box"));
  }
  const int k = drag.grabbed.axis;
  const Vec3 along = drag.grabbed.side * shape.axes.col(k);
  const Vec3 fixedFace = box.center - box.halfExtents[k] * along;
  // The face follows the tip; the validation refuses a box turned inside out.
  box.halfExtents[k] =
      0.5 * drag.size(2.0 * box.halfExtents[k] + along.dot(drag.point - drag.from));
  box.center = fixedFace + box.halfExtents[k] * along;
  return toolsText(QT_TRANSLATE_NOOP("carom::editor::EditorTools", "Resize Box"));
}

}  // namespace

std::vector<Handle> objectHandles(const Scene& scene, const ObjectRef& ref, double arrow) {
  return visitObjects(scene, ref.kind,
                      [&](const auto& objects) { return handlesOf(objects[ref.index], arrow); });
}

QString dragHandle(Scene& scene, const ObjectRef& ref, const HandleDrag& drag) {
  return visitObjects(scene, ref.kind,
                      [&](auto& objects) { return dragged(objects[ref.index], drag); });
}

}  // namespace carom::editor
