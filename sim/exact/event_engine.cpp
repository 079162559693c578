#include "sim/exact/event_engine.h"

#include "sim/core/prefault.h"
#include "sim/core/tolerances.h"
#include "sim/dynamics/response.h"
#include "sim/dynamics/rest_policy.h"
#include "sim/geometry/contact_time.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

EventEngine::EventEngine(const Bodies& bodies, const std::vector<BallState>& state, double now,
                         const Vec3& gravity, const Vec3& pathAcceleration, double collapseSpeed,
                         double stepSpeed)
    : bodies_(bodies),
      gravity_(gravity),
      pathAcceleration_(pathAcceleration),
      straightPaths_(pathAcceleration.isZero()),
      collapseSpeed_(collapseSpeed),
      now_(now),
      slides_(bodies, gravity, pathAcceleration) {
  const int n = bodies.ballCount();
  resizePrefaulted(particles_, n);
  resizePrefaulted(tracks_, n);
  resizePrefaulted(predictions_, n);
  resizePrefaulted(restSpeed_, n);
  resizePrefaulted(slideSpeed_, n);
  for (int i = 0; i < n; ++i) {
    Particle& p = particles_[i];
    p.resting = state[i].resting;
    tracks_[i] = {{state[i].position, p.resting ? Vec3::Zero() : state[i].velocity, now},
                  bodies.radius[i]};
    // A stepped method cannot resolve bounces slower than a step's kick: below that, the
    // integrator's own error (explicit Euler gains g²h²/2 a step) would keep a resting ball
    // hopping and pump energy into it.
    restSpeed_[i] = std::max(restSpeed(gravity_, bodies.radius[i]), stepSpeed);
    slideSpeed_[i] = std::max(slideSpeed(gravity_, bodies.radius[i]), stepSpeed);
  }
  creaseLine_.resize(n);
  creaseAcceleration_.resize(n);
  // Straight sweeps under gravity are the only paths that are not the true ones.
  restoresEnergy_ = straightPaths_ && !gravity_.isZero();
  if (restoresEnergy_) {
    energy_.resize(n);
    energyExcess_.assign(n, 0.0);
    for (int i = 0; i < n; ++i) recordEnergy(i);
  }
  cells_.build(bodies_, positions());
  predictAll();
}

std::vector<Vec3> EventEngine::positions() const {
  std::vector<Vec3> at(particles_.size());
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i)
    at[i] = tracks_[i].motion.positionAt(now_, accelerationOf(i));
  return at;
}

void EventEngine::rebuildCellsIfCrowded() {
  if (!cells_.crowded()) return;
  cells_.build(bodies_, positions());
  predictAll();
}

void EventEngine::predictAll() {
  queue_.reset(static_cast<int>(particles_.size()));
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) predict(i);
  // Balls heading for resting ones learn of it from the resting ball's side.
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i)
    if (particles_[i].resting) warnNeighbours(i);
}

BallPath EventEngine::pathAt(int i, double t) const {
  const Motion& m = tracks_[i].motion;
  const Vec3& a = accelerationOf(i);
  return {m.positionAt(t, a), m.velocityAt(t, a), a};
}

void EventEngine::predict(int i) {
  predictions_[i].contact = {};
  predictions_[i].crossing = {};
  if (!particles_[i].resting) {
    const BallPath path = pathAt(i, now_);
    // Neighbours first: in a pile the next ball contact is near, and a static shape's contact
    // time need only be solved for up to it (ballBoxContactTime then skips the quartics of
    // corners out of reach). A static contact at the same instant still comes first.
    findBallContacts(i, path, [&](auto&& visit) { forEachNeighbour(i, visit); });
    const Contact ball = predictions_[i].contact;
    predictions_[i].contact = {};
    findStaticContact(i, path, ball.time);
    if (ball.time < predictions_[i].contact.time) predictions_[i].contact = ball;
    predictions_[i].crossing = cells_.nextCrossing(i, path, now_, horizon_, straightPaths_);
  }
  schedule(i);
}

void EventEngine::findStaticContact(int i, const BallPath& path, double until) {
  Contact& best = predictions_[i].contact;
  // Contacts up to `until` are all found, a touch beyond it too, so that one at `until` itself
  // is not lost to rounding.
  const double bound =
      until < kNever ? until + 1e-9 * (until - now_) + std::numeric_limits<double>::min() : kNever;
  const double r = bodies_.radius[i];
  const Particle& p = particles_[i];
  for (const StaticRef ref : cells_.staticsNear(i)) {
    if (slidesAgainst(p, ref)) continue;  // it slides along, never into it
    const double horizon = std::min({best.time, horizon_, bound}) - now_;
    double t = kNever;
    EventKind kind = EventKind::Plane;
    switch (ref.kind) {
      case StaticKind::Plane:
        t = ballPlaneContactTime(path, r, bodies_.planes[ref.index], horizon);
        break;
      case StaticKind::Cylinder:
        t = ballCylinderContactTime(path, r, bodies_.cylinders[ref.index], horizon);
        kind = EventKind::Cylinder;
        break;
      case StaticKind::Box:
        t = ballBoxContactTime(path, r, bodies_.boxes[ref.index], horizon);
        kind = EventKind::Box;
        break;
    }
    if (t < horizon) best = {now_ + t, kind, ref.index, 0};
  }
  if (p.slidePlane >= 0 && slides_.surface(p.slidePlane).owner.kind != StaticKind::Plane)
    findSlideEnd(i, path);
}

template <typename ForEachBall>
void EventEngine::findBallContacts(int i, const BallPath& path, ForEachBall&& forEachBall) {
  // Gather the candidates first and ask for their tracks ahead: the tests then find them in
  // cache instead of waiting on each in turn.
  constexpr int kBatch = 32;
  int batch[kBatch];
  int count = 0;
  auto flush = [&] {
    for (int b = 0; b < count; ++b) findBallContact(i, path, batch[b]);
    count = 0;
  };
  forEachBall([&](int k) {
    __builtin_prefetch(&tracks_[k]);
    // A curved path reads the ball's flags too (accelerationOf).
    if (!straightPaths_) __builtin_prefetch(&particles_[k].slidePlane);
    batch[count++] = k;
    if (count == kBatch) flush();
  });
  flush();
}

void EventEngine::findBallContact(int i, const BallPath& path, int k) {
  ++pairTests_;
  Contact& best = predictions_[i].contact;
  const double horizon = std::min(best.time, horizon_) - now_;
  const Track& other = tracks_[k];
  const double radiusSum = tracks_[i].radius + other.radius;
  double t;
  if (straightPaths_) {
    // Inlined path of the neighbour: this loop is where the engine spends its time.
    const Motion& m = other.motion;
    const Vec3 relativePosition = m.position + (now_ - m.since) * m.velocity - path.position;
    t = ballBallStraightContactTime(relativePosition, m.velocity - path.velocity, radiusSum,
                                    horizon);
  } else {
    t = ballBallContactTime(path, pathAt(k, now_), radiusSum, horizon);
  }
  // A contact at the horizon itself (a swept step's end) is kept, not left to the next step:
  // there the pair would touch, and balls too small for the rounding of positions so far out
  // could share one centre, which tells no approach from a retreat.
  if (t < best.time - now_ && t <= horizon_ - now_)
    best = {now_ + t, EventKind::Ball, k, particles_[k].counter};
}

void EventEngine::schedule(int i) {
  queue_.set(i, std::min(predictions_[i].contact.time, predictions_[i].crossing.time));
}

void EventEngine::warnNeighbours(int i) {
  const BallPath path = pathAt(i, now_);
  forEachNeighbour(i, [&](int k) {
    if (particles_[k].resting) return;
    const double t =
        ballBallContactTime(pathAt(k, now_), path, bodies_.radius[i] + bodies_.radius[k], kNever);
    if (now_ + t < predictions_[k].contact.time) {
      predictions_[k].contact = {now_ + t, EventKind::Ball, i, particles_[i].counter};
      schedule(k);
    }
  });
}

void EventEngine::cross(int i, RunStats& stats) {
  ++stats.cellCrossings;
  const CellLevels::Crossing crossing = predictions_[i].crossing;
  const BallPath path = pathAt(i, now_);
  // The path is unchanged, so the contact already predicted stays valid: only the statics of the
  // new cell and the balls in the cells that just came into reach can bring it forward.
  if (cells_.cross(i, crossing)) findStaticContact(i, path);
  findBallContacts(i, path,
                   [&](auto&& visit) { cells_.forEachBallComingIntoReach(i, crossing, visit); });
  predictions_[i].crossing = cells_.nextCrossing(i, path, now_, horizon_, straightPaths_);
  schedule(i);
}

void EventEngine::advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) {
  while (!queue_.empty() && queue_.topTime() <= end) {
    const int i = queue_.top();
    now_ = std::max(now_, queue_.topTime());  // time never steps backwards
    process(i, stats, log);
    rebuildCellsIfCrowded();
  }
  now_ = std::max(now_, end);
  stats.pairTests += pairTests_;
  pairTests_ = 0;
}

void EventEngine::process(int i, RunStats& stats, std::vector<CollisionRecord>* log) {
  ++stats.events;
  inelasticEvent_ = false;
  if (predictions_[i].crossing.time <= predictions_[i].contact.time) {
    cross(i, stats);
    return;
  }
  const Contact event = predictions_[i].contact;
  switch (event.kind) {
    case EventKind::None:
      schedule(i);
      return;
    case EventKind::SlideEnd:
      endSlide(i, stats, log);
      return;
    case EventKind::Plane:
    case EventKind::Cylinder:
    case EventKind::Box: {
      const StaticRef ref{staticKindOf(event.kind), event.other};
      if (particles_[i].held) {
        heldMeetsStatic(i, ref, stats, log);
        return;
      }
      moveTo(i, now_);
      collideWithStatic(i, ref, slides_.surfaceAt(tracks_[i].motion.position, ref), stats, log);
      return;
    }
    case EventKind::Ball: {
      const int j = event.other;
      if (particles_[j].counter != event.otherCounter) {
        ++stats.staleEvents;
        predict(i);
        return;
      }
      if (particles_[i].held || particles_[j].held) {
        const bool iHeld = particles_[i].held;
        pushByHeld(iHeld ? i : j, iHeld ? j : i, stats, log);
        return;
      }
      collideBalls(i, j, stats, log);
      return;
    }
  }
}

void EventEngine::collideWithStatic(int i, StaticRef ref, int face, RunStats& stats,
                                    std::vector<CollisionRecord>* log) {
  restoreEnergy(i);
  const Motion& m = tracks_[i].motion;
  const double r = bodies_.radius[i];
  const auto [n, gap, restitution] = staticContact(i, ref);
  notePenetration(-gap, stats);
  const double approach = -m.velocity.dot(n);
  noteRestitution(restitution);
  collideWithSurface(i, n, restitution, stats, face);
  if (!particles_[i].resting) {
    leaveTouchingStatics(i, stats);
    updateSlide(i, stats);
  }
  const ContactKind kind = contactKindOf(ref.kind);
  stats.collisions.add(kind);
  if (log) log->push_back({now_, kind, i, ref.index, m.position - r * n, approach});
  closeBooks(i, 0.0);
  if (!particles_[i].resting) predict(i);
}

void EventEngine::collideBalls(int i, int j, RunStats& stats, std::vector<CollisionRecord>* log) {
  Particle& a = particles_[i];
  Particle& b = particles_[j];
  moveTo(i, now_);
  moveTo(j, now_);
  if (!a.resting) restoreEnergy(i);
  if (!b.resting) restoreEnergy(j);
  Motion& ma = tracks_[i].motion;
  Motion& mb = tracks_[j].motion;
  Vec3 n = mb.position - ma.position;
  const double distance = n.norm();
  const double radiusSum = bodies_.radius[i] + bodies_.radius[j];
  notePenetration(radiusSum - distance, stats);
  n = pairNormal(n, distance, ma.velocity - mb.velocity);  // centres that coincide: head-on
  const double approach = (ma.velocity - mb.velocity).dot(n);
  const double restitution = std::min(bodies_.restitution[i], bodies_.restitution[j]);
  noteRestitution(restitution);
  // The contact was predicted, so it is resolved even when round-off makes the approach look
  // zero or negative here: the minimum separation then parts the pair, and the same contact
  // cannot be predicted again at this instant.
  // Too gentle to move a resting ball: it acts as an immovable surface, unless ball i would rest
  // on it and it cannot carry i (restCheck), when it wakes first.
  bool answered = false;
  double exchangedI = 0.0, exchangedJ = 0.0;
  if (b.resting && approach < tolerance::kSettleSpeedFactor * restSpeed_[i]) {
    answered = restsOnContact(i, -n, restitution, stats);
    if (!answered && b.resting) {
      bounceOffSurface(i, -n, restitution, stats);
      if (!a.resting) updateSlide(i, stats);
      answered = true;
    }
  }
  if (!answered) {
    if (b.resting) wake(j, stats);
    // A pair that gravity presses together (a falling ball on a sliding one) separates at no
    // less than the rest speed, as a ball on a floor would (rule 1 of rest_policy.h). Only an
    // inelastic pair can collapse: an elastic one parts at the slide speed, which it needs only
    // when it meets at no speed (balls placed touching, a frictionless pyramid).
    const auto [minimum, lossless] = pairFloor(i, j, n, restitution);
    // What the exchange alone gives each ball, without the minimum separation: the energy an
    // elastic pair's books keep (closeBooks).
    Vec3 exchangedA = ma.velocity, exchangedB = mb.velocity;
    resolveBallBall(exchangedA, exchangedB, bodies_.inverseMass[i], bodies_.inverseMass[j], n,
                    restitution, 0.0);
    exchangedI = 0.5 * (exchangedA.squaredNorm() - ma.velocity.squaredNorm());
    exchangedJ = 0.5 * (exchangedB.squaredNorm() - mb.velocity.squaredNorm());
    resolveBallBall(ma.velocity, mb.velocity, bodies_.inverseMass[i], bodies_.inverseMass[j], n,
                    restitution, minimum, lossless);
    changed(i);
    changed(j);
    updateSlide(i, stats);
    updateSlide(j, stats);
  }
  ++stats.collisions.ballBall;
  if (log)
    log->push_back(
        {now_, ContactKind::BallBall, i, j, ma.position + bodies_.radius[i] * n, approach});
  closeBooks(i, exchangedI);
  // A resting ball that answered as a surface took no part.
  if (!answered) closeBooks(j, exchangedJ);
  if (!a.resting) predict(i);
  if (!b.resting) predict(j);
}

EventEngine::PairFloor EventEngine::pairFloor(int i, int j, const Vec3& n,
                                              double restitution) const {
  const bool pressed = (gravityOn(j) - gravityOn(i)).dot(n) < 0.0;
  const double separation = restitution >= 1.0 ? std::min(slideSpeed_[i], slideSpeed_[j])
                                               : std::min(restSpeed_[i], restSpeed_[j]);
  // Parting slower than round-off in the balls' own velocities parts nothing (kTangentRateFraction
  // of the speed, and of the pair's relative speed at most half that): the contact came again
  // at the same instant, for ever. The collapse speed is the scene's, and a light pair far
  // faster than its heavy balls (1e11 m/s against 20) took 1e-6 m/s, less than an ulp.
  constexpr double kRoundOffRate = 2.0 * tolerance::kTangentRateFraction;
  const double fastest2 =
      std::max(tracks_[i].motion.velocity.squaredNorm(), tracks_[j].motion.velocity.squaredNorm());
  // Any other inelastic pair under gravity loses nothing below the rest speed (rule 8).
  const double minimum = pressed ? std::max(collapseSpeed_, separation) : collapseSpeed_;
  return {minimum * minimum >= kRoundOffRate * kRoundOffRate * fastest2
              ? minimum
              : kRoundOffRate * std::sqrt(fastest2),
          pressed || restitution >= 1.0 ? 0.0 : separation};
}

void EventEngine::collideWithSurface(int i, const Vec3& n, double restitution, RunStats& stats,
                                     int plane) {
  // Any slow contact may end in rest, also a sideways one: a ball on a floor trapped between a
  // wall and a resting ball would otherwise rattle between them.
  if (!restsOnContact(i, n, restitution, stats)) bounceOffSurface(i, n, restitution, stats, plane);
}

void EventEngine::bounceOffSurface(int i, const Vec3& n, double restitution, RunStats& stats,
                                   int plane) {
  Particle& p = particles_[i];
  Motion& m = tracks_[i].motion;
  const double approach = -m.velocity.dot(n);
  const double speed = m.velocity.norm();
  const bool pressed = gravity_.dot(n) < 0.0;
  const double rest = restSpeed_[i];
  const int capture =
      plane >= 0 && pressed && restitution * std::max(approach, 0.0) <= slideSpeed_[i]
          ? slideCapture(i, plane)
          : kNoCapture;
  if (capture != kNoCapture) {
    startSliding(i, plane);
    if (capture != kAlone) startCrease(i, capture);
    // A ball that lands without bouncing (restitution 0) and little sideways speed rests.
    if (restsOnContact(i, n, restitution, stats)) return;
  } else {
    // A plane needs no minimum: a ball bouncing on it slower than a bounce of touching height
    // slides instead (above), and so bounces in finitely many events.
    // An elastic contact cannot collapse either: it needs a minimum only to part when it meets
    // at no speed, and takes the slide speed's.
    const double pressedMinimum = plane >= 0 ? 0.0 : restitution >= 1.0 ? slideSpeed_[i] : rest;
    const double minimum = pressed ? pressedMinimum : collapseSpeed_;
    if (restitution * std::max(approach, 0.0) < minimum) ++stats.minimumBounces;
    resolveAgainstSurface(m.velocity, n, restitution, minimum);
    changed(i);
  }
  // A cycle of contacts that lets time advance by round-off only must not hang the run. The
  // flight since the last contact is negligible by the ball's own measure, its speed times the
  // time against its size, so a fast ball crossing a box is never taken for a wedged one; or
  // when it is within a few ulps of the ball's position, which it cannot move (a ball 1e12 m
  // out hopping along a cylinder stayed where it was and hopped for ever).
  const double positionRoundOff =
      4.0 * std::numeric_limits<double>::epsilon() * m.position.cwiseAbs().maxCoeff();
  if ((now_ - p.lastSurfaceCollision) * speed <=
      std::max(tolerance::kBurstTravelFraction * bodies_.radius[i], positionRoundOff)) {
    if (++p.collisionsInBurst > tolerance::kMaxCollisionsInBurst) {
      putToRest(i, stats);
      p.wedged = true;
    }
  } else {
    p.collisionsInBurst = 0;
  }
  p.lastSurfaceCollision = now_;
}

EventEngine::StaticContact EventEngine::staticContact(int i, StaticRef ref,
                                                      const Vec3& position) const {
  const double r = bodies_.radius[i];
  if (ref.kind == StaticKind::Box) {
    const BoxShape::Contact contact = bodies_.boxes[ref.index].contact(position, r);
    return {contact.normal, contact.gap, restitutionWith(i, ref)};
  }
  if (ref.kind == StaticKind::Cylinder) {
    const CylinderShape::Contact contact = bodies_.cylinders[ref.index].contact(position, r);
    return {contact.normal, contact.gap, restitutionWith(i, ref)};
  }
  const PlaneShape& plane = bodies_.planes[ref.index];
  return {plane.normal, plane.gap(position, r), restitutionWith(i, ref)};
}

double EventEngine::restitutionWith(int i, StaticRef ref) const {
  const std::vector<double>& shapes = ref.kind == StaticKind::Box ? bodies_.boxRestitution
                                      : ref.kind == StaticKind::Cylinder
                                          ? bodies_.cylinderRestitution
                                          : bodies_.planeRestitution;
  return std::min(bodies_.restitution[i], shapes[ref.index]);
}

// A ball touching several static shapes at once (the bottom of a narrow wedge) leaves them all
// in the one event: it reflects off each shape it still moves into, in turn, as events at the
// same instant would, until it moves into none. In a wedge of angle θ that takes about π/θ
// reflections, each a few dot products, where as events each would count towards the burst
// guard and end in rest with the energy gone. Past kMaxSimultaneousReflections (wedges under
// about 3e-7 rad, or a ball jammed between parallel walls) the burst guard's rest applies.
void EventEngine::leaveTouchingStatics(int i, RunStats& stats) {
  const Particle& p = particles_[i];
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  touchedStatics_.clear();
  for (const StaticRef ref : cells_.staticsNear(i)) {
    if (slidesAgainst(p, ref)) continue;  // see updateSlide
    const auto [n, gap, restitution] = staticContact(i, ref);
    if (gap <= touching) touchedStatics_.push_back({n, restitution, ref.kind});
  }
  // No minimum separation here: in a wedge opening slower than the rest speed it would send
  // the ball from one wall into the other for ever. An inelastic ball slows down in the loop
  // instead, and then rests by the supports rule at its next contact.
  const bool left =
      reflectOffEach(tracks_[i].motion.velocity, touchedStatics_,
                     tolerance::kMaxSimultaneousReflections, [&](std::size_t k, double) {
                       noteRestitution(touchedStatics_[k].restitution);
                       stats.collisions.add(contactKindOf(touchedStatics_[k].kind));
                     });
  if (left)
    changed(i);
  else
    putToRest(i, stats);
}

void EventEngine::recordEnergy(int i) {
  if (!restoresEnergy_) return;
  const Motion& m = tracks_[i].motion;
  energy_[i] = 0.5 * m.velocity.squaredNorm() - gravity_.dot(m.position) - energyExcess_[i];
  energyExcess_[i] = 0.0;
}

void EventEngine::closeBooks(int i, double exchanged) {
  if (!restoresEnergy_) return;
  if (inelasticEvent_) {
    recordEnergy(i);
    return;
  }
  energy_[i] += exchanged;
  energyExcess_[i] = 0.0;
}

void EventEngine::restoreEnergy(int i) {
  if (!restoresEnergy_) return;
  Motion& m = tracks_[i].motion;
  energyExcess_[i] = restoreSpecificEnergy(m.velocity, m.position, gravity_, energy_[i]);
}

void EventEngine::changed(int i) {
  ++particles_[i].counter;
}

void EventEngine::notePenetration(double overlap, RunStats& stats) const {
  stats.maxPenetration = std::max(stats.maxPenetration, overlap);
}

BallState EventEngine::stateOf(int ball) const {
  const Particle& p = particles_[ball];
  const Motion& m = tracks_[ball].motion;
  const Vec3& a = accelerationOf(ball);
  return {m.positionAt(now_, a), m.velocityAt(now_, a), p.resting};
}

std::vector<BallState> EventEngine::state() const {
  std::vector<BallState> all(particles_.size());
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) all[i] = stateOf(i);
  return all;
}

void EventEngine::setVelocities(const std::vector<Vec3>& velocities) {
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    Particle& p = particles_[i];
    if (p.resting || p.held) continue;
    moveTo(i, now_);
    Motion& m = tracks_[i].motion;
    m.velocity = velocities[i];
    if (p.slidePlane >= 0) {
      // A kick of gravity into the plane is held by the plane; a kick away from it lets go.
      dropPlanesLeft(i);
      keepOnPlane(i);
    }
    changed(i);
  }
  predictAll();
}

std::size_t EventEngine::memoryBytes() const {
  return sizeof(*this) + carom::memoryBytes(tracks_) + carom::memoryBytes(particles_) +
         carom::memoryBytes(predictions_) + carom::memoryBytes(touchedStatics_) +
         carom::memoryBytes(energy_) + carom::memoryBytes(energyExcess_) +
         carom::memoryBytes(restSpeed_) + carom::memoryBytes(slideSpeed_) + slides_.memoryBytes() +
         carom::memoryBytes(creaseLine_) + carom::memoryBytes(creaseAcceleration_) +
         cells_.memoryBytes() + queue_.memoryBytes();
}

}  // namespace carom
