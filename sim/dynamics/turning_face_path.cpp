#include "sim/dynamics/turning_face_path.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>

namespace carom {
namespace {

Vec3 alongFace(const Vec3& a, const Vec3& n) {
  return a - a.dot(n) * n;
}

// What turns: the slip u = v - r·ω×n of a slide, pulled by g_t and held back by 7/2·μ·g_n (the
// force μ·g_n on the centre and its torque on the spin); the velocity of a roll, pulled by
// 5/7·g_t and held back by μ_r·g_n.
struct Turning {
  Vec3 from, pull;
  double drag, centreDrag;
};
Turning turningOf(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                  const ContactFriction& friction, bool sliding) {
  const Vec3 vt = alongFace(v, face.normal);
  if (sliding) {
    const double force = friction.sliding * face.pressing;
    return {vt - radius * w.cross(face.normal), face.along, 3.5 * force, force};
  }
  const double resistance = friction.rolling * face.pressing;
  return {vt, 5.0 / 7.0 * face.along, resistance, resistance};
}

}  // namespace

TurningFacePath::TurningFacePath(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                                 const ContactFriction& friction, FacePhase phase)
    : drag_([&] {
        const Turning t = turningOf(v, w, radius, face, friction, phase == FacePhase::Sliding);
        return TurningDrag(t.from, t.pull, t.drag);
      }()),
      sliding_(phase == FacePhase::Sliding),
      velocity_(alongFace(v, face.normal)),
      along_(face.along),
      normal_(face.normal),
      radius_(radius) {
  const Turning t = turningOf(v, w, radius, face, friction, sliding_);
  slip_ = t.from;
  centreDrag_ = t.centreDrag;
}

TurningFacePath::State TurningFacePath::at(double t) const {
  const TurningDrag::State d = drag_.at(t);
  if (!sliding_) return {d.integral, d.value, normal_.cross(d.value) / radius_};
  // v - 2/7·u changes at 5/7·g_t whatever the slip does.
  const Vec3 velocity = velocity_ + 2.0 / 7.0 * (d.value - slip_) + 5.0 / 7.0 * t * along_;
  const Vec3 displacement =
      t * velocity_ + 2.0 / 7.0 * (d.integral - t * slip_) + 5.0 / 14.0 * t * t * along_;
  return {displacement, velocity, normal_.cross(velocity - d.value) / radius_};
}

double TurningFacePath::deviationBound(double t) const {
  const double swept = drag_.startAngle() - drag_.at(t).angle;
  return centreDrag_ * swept * t * t / 8.0;
}

TurningFacePath::Segment TurningFacePath::segment(double deviation) const {
  // A first guess from the turn at the start (the angle swept about rate·t), then halved until
  // the bound holds; the turn may speed up as the slip shrinks.
  double t = std::cbrt(8.0 * deviation / (centreDrag_ * drag_.startTurnRate()));
  t = std::min(t, end());
  for (int halving = 0; halving < 1100 && deviationBound(t) > deviation; ++halving) t *= 0.5;
  const State start = at(0.0), there = at(t);
  return {t, 2.0 * (there.displacement - t * start.velocity) / (t * t),
          (there.spinAlong - start.spinAlong) / t};
}

}  // namespace carom
