#pragma once
// `swept` (straight sweeps kicked by an integrator under gravity): between two events of a
// ball, physics keeps its energy, but the integrator's kicks and the straight sweep's chord
// below the true parabola do not, and the errors of successive flights add up (the magic room
// gained 96 % in 2,000 s). A contact first gives the ball back the energy it had after its
// last event, by changing its speed along gravity, so the error never outlives one flight.
// These are the books of that energy, per unit mass, kept by the event engine; they keep
// nothing for true paths (`exact`) or without gravity.

#include "sim/core/memory_bytes.h"
#include "sim/dynamics/response.h"
#include "sim/geometry/motion.h"

#include <cstddef>
#include <vector>

namespace carom {

class EnergyBooks {
 public:
  EnergyBooks(bool straightPaths, const Vec3& gravity, int ballCount)
      : restores_(straightPaths && !gravity.isZero()), gravity_(gravity) {
    if (!restores_) return;
    energy_.resize(ballCount);
    excess_.assign(ballCount, 0.0);
  }

  // Ball i's energy is what it has now, moving as `m`.
  void record(int i, const Motion& m) {
    if (!restores_) return;
    energy_[i] = 0.5 * m.velocity.squaredNorm() - gravity_.dot(m.position) - excess_[i];
    excess_[i] = 0.0;
  }
  // Gives ball i, moving as `m`, back the energy it had after its last event.
  void restore(int i, Motion& m) {
    if (!restores_) return;
    excess_[i] = restoreSpecificEnergy(m.velocity, m.position, gravity_, energy_[i]);
  }

  // An event starts; each restitution of its contacts is noted.
  void startEvent() { inelasticEvent_ = false; }
  void noteRestitution(double restitution) {
    inelasticEvent_ = inelasticEvent_ || restitution < 1.0;
  }
  // An impact with friction moves energy between translation and rotation (and may lose some),
  // which these books of translation cannot follow: the event is recorded as it leaves the ball.
  void noteFriction() { inelasticEvent_ = true; }
  // The books after ball i's event, which left it moving as `m`. An elastic event keeps what
  // physics keeps: the ball's energy, changed only by `exchanged` (its share of a ball pair's
  // exchange). What the rest policy's guards gave or took in it (a slide's capture, a rest, a
  // minimum separation) stays owed, and the ball's next contact settles it, so guards make and
  // lose nothing over time. An event with an inelastic contact records the ball as it is: the
  // guards model its collapse.
  void close(int i, double exchanged, const Motion& m) {
    if (!restores_) return;
    if (inelasticEvent_) {
      record(i, m);
      return;
    }
    energy_[i] += exchanged;
    excess_[i] = 0.0;
  }

  std::size_t memoryBytes() const {
    return carom::memoryBytes(energy_) + carom::memoryBytes(excess_);
  }

 private:
  bool restores_;
  Vec3 gravity_;
  bool inelasticEvent_ = false;  // the event being processed has an inelastic contact
  std::vector<double> energy_;   // per unit mass, after each ball's last event
  // What a ball's restore could not take (it was higher than its energy allows), still owed.
  std::vector<double> excess_;
};

}  // namespace carom
