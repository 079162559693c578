// EventEngine's loop: the balls' predictions, the queue of their events, and the state the
// engine hands out.

#include "sim/exact/event_engine.h"

#include "sim/core/prefault.h"
#include "sim/dynamics/rest_policy.h"
#include "sim/geometry/contact_time.h"

#include <algorithm>
#include <limits>

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
      roughFaces_(bodies.rough && !straightPaths_),
      slides_(bodies, gravity, pathAcceleration),
      // Straight sweeps under gravity are the only paths that are not the true ones.
      books_(straightPaths_, gravity, bodies.ballCount()) {
  const int n = bodies.ballCount();
  resizePrefaulted(particles_, n);
  resizePrefaulted(tracks_, n);
  resizePrefaulted(predictions_, n);
  resizePrefaulted(restSpeed_, n);
  resizePrefaulted(slideSpeed_, n);
  resizePrefaulted(spin_, n);
  for (int i = 0; i < n; ++i) {
    spin_[i] = state[i].angularVelocity;
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
  if (roughFaces_) {
    faces_.resize(n);
    turningFaces_.resize(n);
  }
  for (int i = 0; i < n; ++i) books_.record(i, tracks_[i].motion);
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
  if (roughFaces_) findPhaseEnd(i);
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
  books_.startEvent();
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
    case EventKind::PhaseEnd:
      endPhase(i, stats);
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

void EventEngine::changed(int i) {
  ++particles_[i].counter;
}

BallState EventEngine::stateOf(int ball) const {
  const Particle& p = particles_[ball];
  const Motion& m = tracks_[ball].motion;
  if (roughFaces_ && faces_[ball].motion.turning) {
    const TurningFacePath::State exact = turningFaces_[ball].at(now_);
    return {turningFaces_[ball].from + exact.displacement, exact.velocity, p.resting,
            spinAt(ball, now_)};
  }
  const Vec3& a = accelerationOf(ball);
  return {m.positionAt(now_, a), m.velocityAt(now_, a), p.resting, spinAt(ball, now_)};
}

std::vector<BallState> EventEngine::state() const {
  std::vector<BallState> all(particles_.size());
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) all[i] = stateOf(i);
  return all;
}

void EventEngine::setVelocities(const std::vector<Vec3>& velocities) {
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    Particle& p = particles_[i];
    if (p.held) continue;
    if (p.resting) {
      spinInPlace(i, velocities[i]);
      continue;
    }
    moveTo(i, now_);
    Motion& m = tracks_[i].motion;
    m.velocity = velocities[i];
    if (p.slidePlane >= 0) {
      // A kick of gravity into the plane is held by the plane; a kick away from it lets go.
      dropPlanesLeft(i);
      const int face = p.creasePlane < 0 ? p.slidePlane : -1;
      const Vec3 n = face >= 0 ? slides_.surface(face).plane.normal : Vec3::Zero();
      const double held = -m.velocity.dot(n);
      keepOnPlane(i);
      // What the face held of the kick is its push for the step, and friction's measure.
      if (bodies_.rough && face >= 0)
        applySteppedFriction(m.velocity, spin_[i], bodies_.radius[i], n, held,
                             bodies_.contactFriction(i, shapeFriction(slides_.surface(face).owner)),
                             bodies_.tangentialRestitution);
    }
    changed(i);
  }
  predictAll();
}

void EventEngine::spinInPlace(int i, const Vec3& kick) {
  const Particle& p = particles_[i];
  if (!bodies_.rough || p.slidePlane < 0 || p.creasePlane >= 0) return;
  const SlideSurfaces::Surface& face = slides_.surface(p.slidePlane);
  Vec3 still = Vec3::Zero();
  applySteppedFriction(
      still, spin_[i], bodies_.radius[i], face.plane.normal, -kick.dot(face.plane.normal),
      bodies_.contactFriction(i, shapeFriction(face.owner)), bodies_.tangentialRestitution);
}

std::size_t EventEngine::memoryBytes() const {
  return sizeof(*this) + carom::memoryBytes(tracks_) + carom::memoryBytes(particles_) +
         carom::memoryBytes(predictions_) + carom::memoryBytes(touchedStatics_) +
         carom::memoryBytes(spin_) + carom::memoryBytes(faces_) +
         carom::memoryBytes(turningFaces_) + books_.memoryBytes() + carom::memoryBytes(restSpeed_) +
         carom::memoryBytes(slideSpeed_) + slides_.memoryBytes() + carom::memoryBytes(creaseLine_) +
         carom::memoryBytes(creaseAcceleration_) + cells_.memoryBytes() + queue_.memoryBytes();
}

}  // namespace carom
