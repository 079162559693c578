#pragma once
// Rays against the scene's true shapes (not the view's triangles): what an editor needs to pick
// the object under the mouse and to place or drag objects on a plane.

#include "sim/model/scene.h"

#include <Eigen/Geometry>

#include <optional>

namespace carom {

enum class ShapeKind { Ball, Plane, Cylinder, Box };

struct RayHit {
  ShapeKind kind = ShapeKind::Ball;
  int index = -1;         // in the scene's vector of that kind
  double distance = 0.0;  // along the unit direction, > 0
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // unit, facing the side the ray came from
};

// The nearest object that the ray from `origin` along `direction` (any non-zero length) enters
// at a distance > 0, or none.
//
// Only entries count: a ray that starts inside a ball, a cylinder or a box ignores that object
// (it cannot be clicked from inside), and a plane counts only when the ray meets its front, the
// side balls live on, since the view does not draw its back. Rays within about 1e-12 radians of
// parallel to a plane or a cylinder's axis never meet it: they would do so only absurdly far away.
//
// The view draws the infinite shapes clipped to a box; with `clip`, hits that the view does not
// draw are ignored and the ray goes on to what lies behind: a plane hit farther than
// `clipMargin` outside the box, and a cylinder hit whose axis point (the view draws the tube
// around the axis clipped to the box) is. Rounding never clips a shape lying on the box's face.
// Balls and boxes, being finite, are never clipped.
std::optional<RayHit> castRay(const Scene& scene, const Vec3& origin, const Vec3& direction,
                              const Eigen::AlignedBox3d* clip = nullptr, double clipMargin = 0.0);

// Distance along the unit direction at which the ray meets the plane, from either side; none when
// it is parallel to the plane (to within about 1e-12 radians) or meets it only behind the origin
// or at it. For placing objects on the ground and dragging them in a plane facing the camera.
std::optional<double> rayPlaneDistance(const Vec3& origin, const Vec3& direction,
                                       const Vec3& planePoint, const Vec3& planeNormal);

}  // namespace carom
