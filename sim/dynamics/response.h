#pragma once
// Collision response: new velocities for a contact, for any masses, with restitution.

#include "sim/core/tolerances.h"
#include "sim/model/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace carom {

// The speed at which a contact separates: restitution times the approach speed, but never less
// than `minimum` (the rest policy's floor, see docs/physics.md), and restitution takes nothing of
// an approach below `lossless` nor cuts a faster one below it (rule 8 of rest_policy.h).
inline double separationSpeed(double approach, double restitution, double minimum,
                              double lossless = 0.0) {
  double s = restitution * approach;
  const double kept = approach < lossless ? approach : lossless;
  if (s < kept) s = kept;
  return s < minimum ? minimum : s;
}

// The unit normal along `offset` (from one ball's centre to another's, `distance` long), or
// along `fallback` when the centres coincide: positions far out round to more than a small
// ball's radius (1e-7 m at 1e9 m from the origin), and balls meeting there may share a centre.
inline Vec3 pairNormal(const Vec3& offset, double distance, const Vec3& fallback) {
  if (distance > 0.0) return offset / distance;
  const double length = fallback.norm();
  return length > 0.0 ? Vec3(fallback / length) : Vec3::UnitY();
}

// Two balls touching along unit normal `n` (from a to b). Inverse masses may be zero for an
// immovable ball. Only the normal components change; momentum is conserved for finite masses.
// Returns the approach speed.
double resolveBallBall(Vec3& va, Vec3& vb, double inverseMassA, double inverseMassB, const Vec3& n,
                       double restitution, double minimumSeparation, double lossless = 0.0);

// A ball against an immovable surface with unit normal `n` pointing to the ball. When the
// minimum separation speed exceeds what restitution gives, the extra normal speed is taken from
// the tangential motion where it has enough, so the floor never adds energy in that case.
// Returns true when it had to add energy (the ball was too slow in every direction).
bool resolveAgainstSurface(Vec3& v, const Vec3& n, double restitution, double minimumSeparation);

// An elastic ball between two planes that meet at a narrow angle (a wedge): it reflects off one
// and the other in turn, each pair turning its velocity across their crease by twice the wedge's
// angle θ, about π/θ times in all, until it points out of the wedge. This gives where it ends in
// closed form, for any θ: its velocity, and how many reflections it took off each plane, with
// the approach speed of the first off each. Empty when the ball moves into neither plane, or the
// planes are parallel (no crease).
struct WedgeReflections {
  Vec3 velocity;
  std::uint64_t count[2] = {0, 0};
  double approach[2] = {0.0, 0.0};
};
std::optional<WedgeReflections> reflectInWedge(const Vec3& v, const Vec3& n0, const Vec3& n1);

// Contacts with several immovable surfaces at one instant (the bottom of a narrow V, a crease):
// reflects `v` off each of `surfaces` (items with a unit `normal` towards the ball and a
// `restitution`) that it moves into, in turn and with no minimum separation, until it moves into
// none. Calls reflected(k, approach, times) for the reflections off surfaces[k]: `times` of them,
// the first at speed `approach`. False when `limit` reflections did not suffice (a ball jammed
// between parallel walls). Two elastic planes that take more than kLoopReflections reflections
// (a V narrower than about π/64 rad) are solved in closed form (reflectInWedge), so that a V of
// any angle returns the ball; shallower ones keep the loop's arithmetic.
// An approach within the round-off of v (a ball sliding along a surface, its velocity off the
// surface by a few ulps) is none: reflecting it leaves v as it was, and looping on it would not
// end. Skipping it changes no energy, since the reflection changes nothing. Nor does the loop
// go on past kMaxCollisionsInBurst reflections in a row whose approaches are all within
// kTangentRateFraction of the speed: an inelastic ball in the crease of two planes came to
// move along it with v changed by an ulp at each reflection, off one plane into the other and
// back, ten million times a step under `discrete`.
template <typename Surfaces, typename OnReflect>
bool reflectOffEach(Vec3& v, const Surfaces& surfaces, long limit, OnReflect&& reflected) {
  if (surfaces.size() == 2 && surfaces[0].restitution == 1.0 && surfaces[1].restitution == 1.0) {
    const std::optional<WedgeReflections> wedge =
        reflectInWedge(v, surfaces[0].normal, surfaces[1].normal);
    if (wedge && wedge->count[0] + wedge->count[1] > tolerance::kLoopReflections) {
      v = wedge->velocity;
      for (std::size_t k = 0; k < 2; ++k)
        if (wedge->count[k] > 0) reflected(k, wedge->approach[k], wedge->count[k]);
      return true;
    }
  }
  int roundOffInARow = 0;
  for (long reflections = 0; reflections < limit;) {
    bool any = false;
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
      const double approach = -v.dot(surfaces[k].normal);
      if (approach <= 0.0) continue;
      const Vec3 before = v;
      resolveAgainstSurface(v, surfaces[k].normal, surfaces[k].restitution, 0.0);
      if (v == before) continue;
      reflected(k, approach, std::uint64_t(1));
      any = true;
      ++reflections;
      const bool roundOff = approach <= tolerance::kTangentRateFraction * before.norm();
      roundOffInARow = roundOff ? roundOffInARow + 1 : 0;
      if (roundOffInARow > tolerance::kMaxCollisionsInBurst) return true;
    }
    if (!any) return true;
  }
  return false;
}

// Walton's impact law (docs/physics.md, "Friction and spin"), applied after the normal impulse
// of an impact between uniform solid spheres (moment of inertia 2/5·m·r²): a tangential impulse
// that would turn the contact point's tangential velocity u into -β·u, limited by μ times the
// normal impulse (the contact slides when the limit binds). `normalChange` is the change in
// relative normal speed that the normal impulse made (its impulse times the pair's inverse mass).
//
// Two balls touching along unit normal `n` (from a to b), with angular velocities wa and wb and
// radii ra and rb. Inverse masses may be zero for an immovable ball.
void applyImpactFriction(Vec3& va, Vec3& wa, Vec3& vb, Vec3& wb, double ra, double rb,
                         double inverseMassA, double inverseMassB, const Vec3& n,
                         double normalChange, const ImpactFriction& law);
// A ball of radius r against an immovable surface with unit normal `n` pointing to the ball.
void applyImpactFriction(Vec3& v, Vec3& w, double r, const Vec3& n, double normalChange,
                         const ImpactFriction& law);

// Sets velocity `v` of a ball at `position` so that its energy per unit mass,
// |v|²/2 - gravity . position, is `energy`: the errors of a stepped method (integrator kicks, a
// straight chord below the parabola, an overlap pushed out) are along gravity, so the velocity
// along gravity takes the change; only when that is not enough does the sideways motion slow
// down. A ball higher than `energy` allows stops, and the excess it still has is returned
// (else 0), to be taken at its next contact.
double restoreSpecificEnergy(Vec3& v, const Vec3& position, const Vec3& gravity, double energy);

}  // namespace carom
