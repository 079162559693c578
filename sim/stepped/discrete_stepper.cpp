// `discrete`: each step the integrator moves every ball, then overlaps are found and resolved
// (pushed apart, approaching pairs bounced). Cheapest, and it can tunnel: a ball fast enough to
// cross another ball or a cylinder within a step is never seen touching it. The run report's
// penetration and escape figures show what it got wrong.

#include "sim/core/tolerances.h"
#include "sim/dynamics/face_friction.h"
#include "sim/dynamics/response.h"
#include "sim/dynamics/stepper.h"
#include "sim/stepped/broad_phase.h"
#include "sim/stepped/integrator.h"
#include "sim/stepped/step_clock.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdint>
#include <optional>

namespace carom {
namespace {

// A push out of a static shape above this many times the step's support against gravity is an
// impact's, and friction takes its measure from it (pushOut).
constexpr double kImpactPushFactor = 2.0;

struct StaticOverlap {
  Vec3 normal;  // out of the shape, towards the ball
  double depth;
  double restitution;
  ContactKind kind;
  int other;
};

// The smallest move d with n·d >= depth for every overlap, when the overlaps are few (a ball in
// a V or a corner): the best over each set of them taken as touching exactly, d a non-negative
// combination of their normals. Empty when there are too many or no move clears them all.
std::optional<Vec3> smallestMoveOut(const std::vector<StaticOverlap>& overlaps) {
  const int count = static_cast<int>(overlaps.size());
  if (count > 4) return std::nullopt;
  std::optional<Vec3> best;
  for (unsigned subset = 1; subset < (1u << count); ++subset) {
    std::vector<int> active;
    for (int k = 0; k < count; ++k)
      if (subset & (1u << k)) active.push_back(k);
    const int size = static_cast<int>(active.size());
    Eigen::MatrixXd normals(size, 3);
    Eigen::VectorXd depths(size);
    for (int a = 0; a < size; ++a) {
      normals.row(a) = overlaps[active[a]].normal.transpose();
      depths[a] = overlaps[active[a]].depth;
    }
    const Eigen::MatrixXd gram = normals * normals.transpose();
    const Eigen::VectorXd weights = gram.colPivHouseholderQr().solve(depths);
    // A V of angle θ makes the system as ill-conditioned as 1/θ²: whether the move clears every
    // overlap (to a part in a million, which the next pass takes) is what decides.
    if (!weights.allFinite() || weights.minCoeff() < 0.0) continue;
    const Vec3 move = normals.transpose() * weights;
    bool clears = true;
    for (const StaticOverlap& o : overlaps)
      clears = clears && o.normal.dot(move) >= o.depth * (1.0 - 1e-6);
    if (clears && (!best || move.norm() < best->norm())) best = move;
  }
  return best;
}

class DiscreteStepper final : public Stepper {
 public:
  DiscreteStepper(const Bodies& bodies, const StepperSettings& settings,
                  const std::vector<BallState>& state, double now)
      : bodies_(bodies), settings_(settings), clock_(now, settings.timeStep) {
    for (const BallState& s : state) {
      positions_.push_back(s.position);
      velocities_.push_back(s.velocity);
      spins_.push_back(s.angularVelocity);
    }
    if (!settings_.gravity.isZero()) {
      energy_.resize(positions_.size());
      energyExcess_.assign(positions_.size(), 0.0);
      for (int i = 0; i < static_cast<int>(positions_.size()); ++i) recordEnergy(i);
    }
  }

  void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) override {
    clock_.advanceTo(end, [&](double h, double stepEnd) { step(h, stepEnd, stats, log); });
  }
  void advanceSteps(std::uint64_t count, RunStats& stats,
                    std::vector<CollisionRecord>* log) override {
    clock_.advanceSteps(count, [&](double h, double stepEnd) { step(h, stepEnd, stats, log); });
  }
  double now() const override { return clock_.now(); }
  std::vector<BallState> state() const override {
    std::vector<BallState> state(positions_.size());
    for (std::size_t i = 0; i < state.size(); ++i)
      state[i] = {positions_[i], velocities_[i] + pendingKick_ * settings_.gravity, false,
                  spins_[i]};
    if (held_ >= 0) state[held_].velocity = velocities_[held_];
    return state;
  }
  std::unique_ptr<Stepper> clone() const override {
    return std::make_unique<DiscreteStepper>(*this);
  }
  std::size_t memoryBytes() const override {
    return sizeof(*this) + carom::memoryBytes(overlaps_) + carom::memoryBytes(energy_) +
           carom::memoryBytes(energyExcess_) + carom::memoryBytes(positions_) +
           carom::memoryBytes(velocities_) + carom::memoryBytes(spins_) +
           carom::memoryBytes(pushes_) + carom::memoryBytes(touched_) +
           carom::memoryBytes(pushedTwice_) + carom::memoryBytes(lookedAt_) + bins_.memoryBytes();
  }
  // The held ball's velocity is kept without the kick owed to the others.
  void hold(int ball, const Vec3& velocity, RunStats&) override {
    if (held_ >= 0 && held_ != ball) release(Vec3::Zero());
    held_ = ball;
    velocities_[ball] = velocity;
  }
  void release(const Vec3& velocity) override {
    if (held_ < 0) return;
    const int i = held_;
    held_ = -1;
    velocities_[i] = velocity;
    recordEnergy(i);
    fromStepEnd(i);
  }
  void place(const Vec3& position) override {
    if (held_ >= 0) positions_[held_] = position;
  }
  std::optional<GrabStop> takeGrabStop() override {
    std::optional<GrabStop> stop;
    stop.swap(grabStop_);
    return stop;
  }
  std::vector<std::string> notes() const override {
    return {std::string("discrete: ") + std::string(integratorName(settings_.integrator)) +
                " steps, overlaps resolved after each step (can tunnel)",
            "all balls integrated every step; nothing rests"};
  }

 private:
  void step(double h, double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    const KickSplit split = kickSplit(settings_.integrator);
    const Vec3 before = (pendingKick_ + split.before * h) * settings_.gravity;
    pendingKick_ = split.after * h;
    stepSeconds_ = h;
    const int n = static_cast<int>(positions_.size());
    for (int i = 0; i < n; ++i) {
      if (i != held_) velocities_[i] += before;
      positions_[i] += h * velocities_[i];
    }
    pushes_.assign(n, 0);
    lookedAt_.assign(n, 0);
    touched_.clear();
    pushedTwice_.clear();
    for (int i = 0; i < n; ++i) resolveStatics(i, time, stats, log);
    bins_.build(positions_, bodies_.radius, 0.0);
    bins_.forEachCandidatePair([&](int i, int j) { resolvePair(i, j, time, stats, log); });
    // A push out of one overlap can make another (a column of balls on a floor: the pair above
    // pushes the bottom ball back into the floor, and a single pass a step let the column sink
    // through it). Further passes look again at the balls pushed out of two overlaps or more,
    // pressed between things, until there is none. A ball pushed out of one overlap only (most
    // of a gas's) is left to the next step: looking again at all of them cost a fifth of
    // `discrete`'s speed in the bench.
    for (int pass = 1; pass < tolerance::kMaxOverlapPasses && !pushedTwice_.empty(); ++pass) {
      std::vector<int> again;
      again.swap(pushedTwice_);
      std::sort(again.begin(), again.end());  // the same order whatever pushed them first
      for (int i : touched_) pushes_[i] = 0;
      touched_.clear();
      for (int i : again) lookedAt_[i] = 1;  // so that a pair of two is seen once
      for (int i : again) resolveStatics(i, time, stats, log);
      for (int i : again)
        bins_.forEachCandidateOf(i, [&](int j) {
          if (!lookedAt_[j] || i < j) resolvePair(i, j, time, stats, log);
        });
      for (int i : again) lookedAt_[i] = 0;
    }
    if (held_ >= 0) stopCrushingGrab(time, stats, log);
    ++stats.steps;
    stats.ballSteps += n;
  }

  // The held ball pushes the balls it touches out of its way, also into static shapes, after
  // their own pushes out of those: each is pushed out of them again, and one that then
  // overlaps the held ball was pressed into it by something that does not give way. The grab
  // stops, and the held ball steps back to touching it.
  void stopCrushingGrab(double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    const int h = held_;
    bins_.forEachCandidateOf(h, [&](int o) {
      const double radiusSum = bodies_.radius[h] + bodies_.radius[o];
      const double reach = radiusSum * (1.0 + tolerance::kTouchFraction);
      if ((positions_[o] - positions_[h]).squaredNorm() > reach * reach) return;
      resolveStatics(o, time, stats, log);
      const Vec3 d = positions_[o] - positions_[h];
      const double distance = d.norm();
      if (distance >= radiusSum * (1.0 - tolerance::kTouchFraction) || distance == 0.0) return;
      positions_[h] -= (radiusSum - distance) * (d / distance);
      velocities_[h] = Vec3::Zero();
      if (!grabStop_) grabStop_ = GrabStop{GrabStopKind::Crush, h, o, time};
    });
  }

  double inverseMassOf(int i) const { return i == held_ ? 0.0 : bodies_.inverseMass[i]; }

  void resolveStatics(int i, double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    const double r = bodies_.radius[i];
    overlaps_.clear();
    for (int k = 0; k < static_cast<int>(bodies_.planes.size()); ++k) {
      const PlaneShape& plane = bodies_.planes[k];
      const double gap = plane.gap(positions_[i], r);
      if (gap >= 0.0) continue;
      overlaps_.push_back({plane.normal, -gap,
                           std::min(bodies_.restitution[i], bodies_.planeRestitution[k]),
                           ContactKind::BallPlane, k});
    }
    for (int k = 0; k < static_cast<int>(bodies_.cylinders.size()); ++k) {
      // Out by the closest point of side, cap or rim.
      const CylinderShape::Contact contact = bodies_.cylinders[k].contact(positions_[i], r);
      if (contact.gap >= 0.0) continue;
      overlaps_.push_back({contact.normal, -contact.gap,
                           std::min(bodies_.restitution[i], bodies_.cylinderRestitution[k]),
                           ContactKind::BallCylinder, k});
    }
    for (int k = 0; k < static_cast<int>(bodies_.boxes.size()); ++k) {
      // Out by the closest point (out of the nearest face for a centre inside).
      const BoxShape::Contact contact = bodies_.boxes[k].contact(positions_[i], r);
      if (contact.gap >= 0.0) continue;
      overlaps_.push_back({contact.normal, -contact.gap,
                           std::min(bodies_.restitution[i], bodies_.boxRestitution[k]),
                           ContactKind::BallBox, k});
    }
    // The held ball bounces off nothing: it slides along what it meets.
    if (i == held_)
      for (StaticOverlap& o : overlaps_) o.restitution = 0.0;
    if (overlaps_.size() > 1 && pushOutOfSeveral(i, time, stats, log)) return;
    for (const StaticOverlap& o : overlaps_)
      pushOut(i, o.normal, o.depth, o.restitution, o.kind, o.other, time, stats, log);
  }

  // A ball in several static shapes at once (the bottom of a narrow V, a corner) moves by the
  // smallest move that clears them all, and reflects off each it still moves into, in turn, as
  // EventEngine::leaveTouchingStatics does. Pushed out of one after the other instead, a ball in
  // a V of 1e-4 rad went from wall to wall a little higher each pass and stayed stuck below its
  // jam. False when no such move is found (the shapes leave the ball no room).
  bool pushOutOfSeveral(int i, double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    const std::optional<Vec3> move = smallestMoveOut(overlaps_);
    if (!move) return false;
    for (const StaticOverlap& o : overlaps_)
      stats.maxPenetration = std::max(stats.maxPenetration, o.depth);
    positions_[i] += *move;
    notePush(i, move->norm(), 2);
    toStepEnd(i);
    restoreEnergy(i);
    reflectOffEach(velocities_[i], overlaps_, tolerance::kMaxSimultaneousReflections,
                   [&](std::size_t k, double approach, std::uint64_t times) {
                     const StaticOverlap& o = overlaps_[k];
                     stats.collisions.add(o.kind, times);
                     if (log)
                       log->push_back({time, o.kind, i, o.other,
                                       positions_[i] - bodies_.radius[i] * o.normal, approach});
                   });
    recordEnergy(i);
    fromStepEnd(i);
    return true;
  }

  void pushOut(int i, const Vec3& n, double overlap, double restitution, ContactKind kind,
               int other, double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    stats.maxPenetration = std::max(stats.maxPenetration, overlap);
    positions_[i] += overlap * n;
    notePush(i, overlap, 2);
    toStepEnd(i);
    restoreEnergy(i);
    const double approach = -velocities_[i].dot(n);
    double push = 0.0;  // the impact's, per unit mass
    if (approach > 0.0) {
      resolveAgainstSurface(velocities_[i], n, restitution, 0.0);
      push = velocities_[i].dot(n) + approach;
    }
    // Friction's measure: the normal impulse. A ball lying on the shape (on a floor it meets it
    // with no approach left once its energy is restored, on an incline the restore shifts its
    // approach) is held against gravity's push into it, the step's support; a push of more than
    // kImpactPushFactor times that is an impact's.
    if (bodies_.rough) {
      // A second pass's push of round-off (notePush) is the same support again.
      const double support = overlap > tolerance::kTouchFraction * bodies_.radius[i]
                                 ? std::max(-settings_.gravity.dot(n), 0.0) * stepSeconds_
                                 : 0.0;
      applySteppedFriction(velocities_[i], spins_[i], bodies_.radius[i], n,
                           push > kImpactPushFactor * support ? push : support,
                           bodies_.contactFriction(i, bodies_.shapeFriction(kind, other)),
                           bodies_.tangentialRestitution);
    }
    recordEnergy(i);
    fromStepEnd(i);
    if (approach <= 0.0) return;
    stats.collisions.add(kind);
    if (log)
      log->push_back({time, kind, i, other, positions_[i] - bodies_.radius[i] * n, approach});
  }

  void resolvePair(int i, int j, double time, RunStats& stats, std::vector<CollisionRecord>* log) {
    Vec3 d = positions_[j] - positions_[i];
    const double radiusSum = bodies_.radius[i] + bodies_.radius[j];
    const double distance2 = d.squaredNorm();
    if (distance2 >= radiusSum * radiusSum) return;
    const double distance = std::sqrt(distance2);
    const Vec3 n = distance > 0.0 ? Vec3(d / distance) : Vec3::UnitY();
    const double overlap = radiusSum - distance;
    stats.maxPenetration = std::max(stats.maxPenetration, overlap);
    // Push apart in proportion to inverse mass, as an impulse would move them.
    const double wi = inverseMassOf(i) / (inverseMassOf(i) + inverseMassOf(j));
    positions_[i] -= (overlap * wi) * n;
    positions_[j] += (overlap * (1.0 - wi)) * n;
    notePush(i, overlap * wi);
    notePush(j, overlap * (1.0 - wi));
    toStepEnd(i);
    toStepEnd(j);
    restoreEnergy(i);
    restoreEnergy(j);
    const double approach = (velocities_[i] - velocities_[j]).dot(n);
    if (approach > 0.0) {
      resolveBallBall(velocities_[i], velocities_[j], inverseMassOf(i), inverseMassOf(j), n,
                      std::min(bodies_.restitution[i], bodies_.restitution[j]), 0.0);
      if (bodies_.rough) {
        const ImpactFriction law = bodies_.impactFriction(i, j);
        if (law.friction > 0.0)
          applyImpactFriction(velocities_[i], spins_[i], velocities_[j], spins_[j],
                              bodies_.radius[i], bodies_.radius[j], inverseMassOf(i),
                              inverseMassOf(j), n,
                              approach + (velocities_[j] - velocities_[i]).dot(n), law);
      }
    }
    payExcess(i, j);
    payExcess(j, i);
    recordEnergy(i);
    recordEnergy(j);
    fromStepEnd(i);
    fromStepEnd(j);
    if (approach <= 0.0) return;
    ++stats.collisions.ballBall;
    if (log)
      log->push_back(
          {time, ContactKind::BallBall, i, j, positions_[i] + bodies_.radius[i] * n, approach});
  }

  // Counts the pushes further than touching distance that a ball takes in the current pass. A
  // push out of a static shape counts as two: the ball cannot push the shape back, and in a
  // narrow V each push sends it into the other wall.
  void notePush(int i, double distance, int count = 1) {
    if (distance <= tolerance::kTouchFraction * bodies_.radius[i]) return;
    if (pushes_[i] == 0) touched_.push_back(i);
    if (pushes_[i] >= 2) return;
    pushes_[i] = static_cast<std::uint8_t>(std::min(pushes_[i] + count, 2));
    if (pushes_[i] == 2) pushedTwice_.push_back(i);
  }

  // As in `swept` (EnergyBooks::restore): a contact first gives each ball back the energy
  // it had after its last contact, which the integrator's steps and the push out of the overlap
  // do not keep, so that their errors never outlive one flight. Gravity's potential makes them
  // matter; without gravity nothing is restored.
  void recordEnergy(int i) {
    if (energy_.empty() || i == held_) return;
    energy_[i] = 0.5 * velocities_[i].squaredNorm() - settings_.gravity.dot(positions_[i]) -
                 energyExcess_[i];
    energyExcess_[i] = 0.0;
  }
  void restoreEnergy(int i) {
    if (energy_.empty() || i == held_) return;
    energyExcess_[i] =
        restoreSpecificEnergy(velocities_[i], positions_[i], settings_.gravity, energy_[i]);
  }
  // A slow ball pushed up out of an overlap can be higher than its energy allows, and its
  // restore leaves it the excess (restoreSpecificEnergy). It pays that at once from the speed
  // the exchange gave it, or else its partner, which the same push moved, pays it, rather than
  // at its next contact: its reported energy would be above its own for a whole flight.
  void payExcess(int i, int partner) {
    if (energy_.empty() || energyExcess_[i] <= 0.0) return;
    for (const int k : {i, partner}) {
      if (k == held_) continue;
      const double owed = energyExcess_[i];
      energyExcess_[i] = 0.0;
      const double massShare = k == i ? 1.0 : bodies_.mass[i] / bodies_.mass[k];
      const double energy = 0.5 * velocities_[k].squaredNorm() -
                            settings_.gravity.dot(positions_[k]) - massShare * owed;
      energyExcess_[i] =
          restoreSpecificEnergy(velocities_[k], positions_[k], settings_.gravity, energy) /
          massShare;
      if (energyExcess_[i] <= 0.0) return;
    }
  }
  // Contacts act on the velocity at the step's end, with the kick still owed (the one state()
  // reports), so that their energy is counted as it will be reported.
  void toStepEnd(int i) {
    if (i != held_) velocities_[i] += pendingKick_ * settings_.gravity;
  }
  void fromStepEnd(int i) {
    if (i != held_) velocities_[i] -= pendingKick_ * settings_.gravity;
  }

  const Bodies& bodies_;
  StepperSettings settings_;
  std::vector<StaticOverlap> overlaps_;  // of the ball being resolved
  std::vector<double> energy_;           // per unit mass, after each ball's last contact
  std::vector<double> energyExcess_;     // not yet taken back (restoreSpecificEnergy)
  StepClock clock_;
  double pendingKick_ = 0.0;
  double stepSeconds_ = 0.0;  // of the step being taken
  std::vector<Vec3> positions_;
  std::vector<Vec3> velocities_;
  std::vector<Vec3> spins_;  // angular velocities: only impacts with friction change them
  // The overlap passes of a step (see step()).
  std::vector<std::uint8_t> pushes_;  // pushes each ball took in the current pass
  std::vector<int> touched_;          // the balls with pushes_ above zero
  std::vector<int> pushedTwice_;      // the balls to look at again in the next pass
  std::vector<char> lookedAt_;        // the balls the current pass looks at again
  BallBins bins_;
  int held_ = -1;  // the held ball (grab.h), or -1
  std::optional<GrabStop> grabStop_;
};

}  // namespace

std::unique_ptr<Stepper> makeDiscreteStepper(const Bodies& bodies, const StepperSettings& settings,
                                             const std::vector<BallState>& state, double now) {
  return std::make_unique<DiscreteStepper>(bodies, settings, state, now);
}

}  // namespace carom
