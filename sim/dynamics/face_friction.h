#pragma once
// A ball's lasting contact with a flat face (a plane, a box's face, a capped cylinder's cap) with
// friction (docs/physics.md, "Friction and spin"): the phases sliding, rolling and still, each a
// constant acceleration of the centre and a constant angular acceleration, so that every path is
// a polynomial in time that the contact solvers take as they are; and the spin about the face's
// normal, which spinning friction takes down linearly to zero whatever the phase.
//
// Gravity presses the ball on the face with g_n = -g·n and pulls it along with g_t. With slip
// u = v - r ω×n (the contact point's velocity), a sliding ball feels -μ·g_n·û, and u changes at
// g_t - 7/2·μ·g_n·û; a rolling one (u = 0) accelerates at 5/7·g_t less the rolling resistance
// μ_r·g_n along its velocity, and holds only while 2/7·|g_t| ≤ μ·g_n.

#include "sim/model/scene.h"

#include <cstdint>
#include <limits>

namespace carom {

enum class FacePhase : std::uint8_t { Sliding, Rolling, Still };

// The face's frame for a ball on it.
struct FaceFrame {
  Vec3 normal;      // unit, towards the ball
  double pressing;  // g_n, > 0 on a face the ball rests on
  Vec3 along;       // g_t
  static FaceFrame of(const Vec3& normal, const Vec3& gravity) {
    const double g = gravity.dot(normal);
    return {normal, -g, gravity - g * normal};
  }
};

struct FaceMotion {
  FacePhase phase = FacePhase::Sliding;
  Vec3 acceleration = Vec3::Zero();         // of the centre, constant over the phase
  Vec3 angularAcceleration = Vec3::Zero();  // of ω's part along the face, constant over it
  // How long the phase lasts from now: until the slip stops (sliding) or the ball stops
  // (rolling); infinity when it does not end by itself.
  double duration = std::numeric_limits<double>::infinity();
  // The slip or the rolling velocity turns on the face (a slide or a roll with resistance across
  // a tilted face): no polynomial path, but a closed form (TurningFacePath), whose acceleration,
  // angular acceleration and duration then replace the ones above, which hold only at the start.
  bool turning = false;
};

// The phase a ball with velocity `v` (along the face) and angular velocity `w` is in now, and its
// motion. `v` and `w` are as they are; for a rolling ball, `w`'s part along the face is taken as
// the one of rolling without slip (rollingSpin).
FaceMotion faceMotion(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                      const ContactFriction& friction);

// ω's part along the face for rolling without slip at `v`: n × v / r.
inline Vec3 rollingSpin(const Vec3& v, const Vec3& normal, double radius) {
  return normal.cross(v) / radius;
}

// The slip of the contact point on a face with unit normal `normal`, from the velocity's part
// along it `alongFace`: that less r·ω×n, of ω's part along the face only. The spin about the normal
// moves the contact point nowhere; its cross product with n is round-off, which would be a slip of
// its own on a ball nearly still that spins about the normal (one that never ends: each end of that
// slide finds it again at the same instant).
inline Vec3 faceSlip(const Vec3& alongFace, const Vec3& w, const Vec3& normal, double radius) {
  return alongFace - radius * (w - w.dot(normal) * normal).cross(normal);
}

// The rate at which spinning friction takes down the spin about the face's normal: the torque
// μ_sp·N·r over the moment 2/5·m·r².
inline double spinDecayRate(const FaceFrame& face, const ContactFriction& friction, double radius) {
  return 2.5 * friction.spinning * face.pressing / radius;
}

// A ball's angular velocity during a phase: its part along the face changes at `acceleration`,
// and its part about `normal` runs down at `normalDecay` to zero and stays there.
struct SpinPath {
  Vec3 spin = Vec3::Zero();  // at `since`
  Vec3 acceleration = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // zero off any face
  double normalDecay = 0.0;
  double since = 0.0;
  Vec3 at(double t) const;
};

// One time step's friction for a stepped method at a contact with unit normal `n` (towards the
// ball) whose normal impulse per unit mass was `normalChange` (the step's share of the pressing
// force, or an impact): Coulomb's tangential impulse towards -β times the slip, limited by μ
// times the normal impulse; then, on a ball that rolls, rolling resistance taking up to
// μ_r·normalChange off its speed; and spinning friction taking up to 5/2·μ_sp·normalChange/r off
// its spin about n. Box2D's and MuJoCo's soft contacts scale friction by the normal impulse the
// same way.
void applySteppedFriction(Vec3& v, Vec3& w, double radius, const Vec3& n, double normalChange,
                          const ContactFriction& friction, double tangentialRestitution);

}  // namespace carom
