#include "sim/dynamics/face_friction.h"

#include "sim/core/tolerances.h"
#include "sim/dynamics/response.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>

namespace carom {
namespace {

// The part of `a` across unit direction `d`.
Vec3 across(const Vec3& a, const Vec3& d) {
  return a - a.dot(d) * d;
}

// Marks a phase whose direction turns: one with an acceleration across it (`turning`) beyond
// the round-off of `scale`, the acceleration's size.
void markTurning(FaceMotion& m, const Vec3& turning, double scale) {
  if (turning.norm() > tolerance::kRollingSlipFraction * scale) m.turning = true;
}

// A slide with slip `slip` long along unit direction `d`.
FaceMotion sliding(const Vec3& d, double slip, double radius, const FaceFrame& face,
                   double friction) {
  FaceMotion m;
  m.phase = FacePhase::Sliding;
  const double force = friction * face.pressing;  // per unit mass
  m.acceleration = face.along - force * d;
  m.angularAcceleration = (2.5 * force / radius) * face.normal.cross(d);
  // The slip changes at g_t - 7/2·μ·g_n·d: along d at this rate, across it by turning.
  const double rate = face.along.dot(d) - 3.5 * force;
  // Without friction nothing happens when the slip passes zero.
  if (force > 0.0 && rate < 0.0) m.duration = slip / -rate;
  if (force > 0.0) markTurning(m, across(face.along, d), face.along.norm());
  return m;
}

}  // namespace

FaceMotion faceMotion(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                      const ContactFriction& friction) {
  const Vec3& n = face.normal;
  const Vec3 vt = across(v, n);
  const Vec3 slip = faceSlip(vt, w, n, radius);
  const double scale = vt.norm() + radius * w.norm();
  const double slipSize = slip.norm();
  if (slipSize > tolerance::kRollingSlipFraction * scale)
    return sliding(slip / slipSize, slipSize, radius, face, friction.sliding);
  const double pull = face.along.norm();
  const Vec3 downhill = pull > 0.0 ? Vec3(face.along / pull) : Vec3::Zero();
  // Static friction cannot hold the roll: the slip grows down the fall line from zero.
  if (2.0 / 7.0 * pull > friction.sliding * face.pressing)
    return sliding(downhill, 0.0, radius, face, friction.sliding);
  FaceMotion m;
  m.phase = FacePhase::Rolling;
  const double resistance = friction.rolling * face.pressing;
  const double speed = vt.norm();
  if (speed > 0.0) {
    const Vec3 d = vt / speed;
    m.acceleration = 5.0 / 7.0 * face.along - resistance * d;
    const double rate = 5.0 / 7.0 * face.along.dot(d) - resistance;
    if (rate < 0.0) m.duration = speed / -rate;
    if (resistance > 0.0) markTurning(m, across(5.0 / 7.0 * face.along, d), pull);
  } else if (5.0 / 7.0 * pull > resistance) {
    m.acceleration = 5.0 / 7.0 * face.along - resistance * downhill;  // rolls off from rest
  } else {
    m.phase = FacePhase::Still;
    return m;
  }
  m.angularAcceleration = n.cross(m.acceleration) / radius;
  return m;
}

Vec3 SpinPath::at(double t) const {
  const double dt = t - since;
  Vec3 w = spin + dt * acceleration;
  if (normalDecay > 0.0) {
    const double about = spin.dot(normal);
    const double left = std::max(std::abs(about) - normalDecay * dt, 0.0);
    w += (std::copysign(left, about) - about) * normal;
  }
  return w;
}

void applySteppedFriction(Vec3& v, Vec3& w, double radius, const Vec3& n, double normalChange,
                          const ContactFriction& friction, double tangentialRestitution) {
  if (!(normalChange > 0.0)) return;
  if (friction.sliding > 0.0)
    applyImpactFriction(v, w, radius, n, normalChange, {friction.sliding, tangentialRestitution});
  if (friction.rolling > 0.0) {
    const Vec3 vt = across(v, n);
    const Vec3 slip = faceSlip(vt, w, n, radius);
    const double speed = vt.norm();
    const double scale = speed + radius * w.norm();
    if (speed > 0.0 && slip.norm() <= tolerance::kRollingSlipFraction * scale) {
      const Vec3 slower = vt * (std::max(speed - friction.rolling * normalChange, 0.0) / speed);
      v += slower - vt;
      w = w.dot(n) * n + rollingSpin(slower, n, radius);
    }
  }
  if (friction.spinning > 0.0) {
    const double about = w.dot(n);
    const double cut = std::min(2.5 * friction.spinning * normalChange / radius, std::abs(about));
    w -= std::copysign(cut, about) * n;
  }
}

}  // namespace carom
