#include "sim/dynamics/turning_face_path.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {
namespace {

Vec3 alongFace(const Vec3& a, const Vec3& n) {
  return a - a.dot(n) * n;
}

}  // namespace

TurningFacePath::Turning TurningFacePath::turningOf(const Vec3& v, const Vec3& w, double radius,
                                                    const FaceFrame& face,
                                                    const ContactFriction& friction, bool sliding) {
  const Vec3 vt = alongFace(v, face.normal);
  if (sliding) {
    const double force = friction.sliding * face.pressing;
    return {faceSlip(vt, w, face.normal, radius), face.along, 3.5 * force, force};
  }
  const double resistance = friction.rolling * face.pressing;
  return {vt, 5.0 / 7.0 * face.along, resistance, resistance};
}

TurningFacePath::TurningFacePath(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                                 const ContactFriction& friction, FacePhase phase)
    : sliding_(phase == FacePhase::Sliding),
      turning_(turningOf(v, w, radius, face, friction, sliding_)),
      drag_(turning_.from, turning_.pull, turning_.drag),
      velocity_(alongFace(v, face.normal)),
      along_(face.along),
      normal_(face.normal),
      radius_(radius) {}

TurningFacePath::State TurningFacePath::at(double t) const {
  const TurningDrag::State d = drag_.at(t);
  if (!sliding_) return {d.integral, d.value, normal_.cross(d.value) / radius_};
  // v - 2/7·u changes at 5/7·g_t whatever the slip does.
  const Vec3 velocity = velocity_ + 2.0 / 7.0 * (d.value - turning_.from) + 5.0 / 7.0 * t * along_;
  const Vec3 displacement =
      t * velocity_ + 2.0 / 7.0 * (d.integral - t * turning_.from) + 5.0 / 14.0 * t * t * along_;
  return {displacement, velocity, normal_.cross(velocity - d.value) / radius_};
}

double TurningFacePath::deviationBound(double t) const {
  const double swept = drag_.startAngle() - drag_.at(t).angle;
  return turning_.centreDrag * swept * t * t / 8.0;
}

TurningFacePath::Segment TurningFacePath::segment(double deviation, double shortest) const {
  // A first guess from the turn at the start (the angle swept about rate·t), then halved until
  // the bound holds; the turn may speed up as the slip shrinks.
  double t = std::cbrt(8.0 * deviation / (turning_.centreDrag * drag_.startTurnRate()));
  t = std::min({t, end(), std::numeric_limits<double>::max()});
  for (int halving = 0; halving < 1100 && deviationBound(t) > deviation; ++halving) t *= 0.5;
  t = std::min(std::max(t, shortest), end());
  const State start = at(0.0), there = at(t);
  return {t, 2.0 * (there.displacement - t * velocity_) / (t * t),
          (there.spinAlong - start.spinAlong) / t};
}

}  // namespace carom
