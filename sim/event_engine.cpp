#include "event_engine.h"

#include "contact_time.h"
#include "response.h"
#include "rest_policy.h"
#include "tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The grid covers the balls and stretches to axis-aligned planes, which usually bound the room.
void gridBounds(const Bodies& bodies, const std::vector<BallState>& state, Vec3& lower,
                Vec3& upper) {
  lower = Vec3::Constant(kNever);
  upper = Vec3::Constant(-kNever);
  for (const BallState& s : state) {
    lower = lower.cwiseMin(s.position);
    upper = upper.cwiseMax(s.position);
  }
  if (state.empty()) lower = upper = Vec3::Zero();
  for (const PlaneShape& plane : bodies.planes) {
    for (int a = 0; a < 3; ++a) {
      if (std::abs(plane.normal[a]) < 1.0 - 1e-12) continue;
      const double at = plane.offset / plane.normal[a];
      lower[a] = std::min(lower[a], at);
      upper[a] = std::max(upper[a], at);
    }
  }
  const double margin = 2.0 * bodies.maxRadius;
  lower -= Vec3::Constant(margin);
  upper += Vec3::Constant(margin);
}

}  // namespace

EventEngine::EventEngine(const Bodies& bodies, const std::vector<BallState>& state, double now,
                         const Vec3& gravity, const Vec3& pathAcceleration, double collapseSpeed)
    : bodies_(bodies),
      gravity_(gravity),
      pathAcceleration_(pathAcceleration),
      collapseSpeed_(collapseSpeed),
      now_(now) {
  const int n = bodies.ballCount();
  particles_.resize(n);
  predictions_.resize(n);
  restSpeed_.resize(n);
  for (int i = 0; i < n; ++i) {
    Particle& p = particles_[i];
    p.resting = state[i].resting;
    p.motion = {state[i].position, p.resting ? Vec3::Zero() : state[i].velocity,
                p.resting ? Vec3::Zero() : pathAcceleration_, now};
    restSpeed_[i] = restSpeed(gravity_, bodies.radius[i]);
  }
  buildGrid(state);
  buildStaticLists();
  predictAll();
}

void EventEngine::buildGrid(const std::vector<BallState>& state) {
  Vec3 lower, upper;
  gridBounds(bodies_, state, lower, upper);
  // Cells a little wider than the largest diameter, so contacts never skip a cell.
  const double cellSize = std::max(2.0 * bodies_.maxRadius * (1.0 + 1e-9), 1e-300);
  const std::size_t maxCells = 4 * particles_.size() + 64;
  grid_ = CellGrid(lower, upper, cellSize, maxCells);
  members_.reset(grid_.cellCount(), static_cast<int>(particles_.size()));
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    particles_[i].cell = grid_.index(grid_.coordsOf(particles_[i].motion.position));
    members_.insert(i, particles_[i].cell);
  }
}

void EventEngine::buildStaticLists() {
  const int cells = grid_.cellCount();
  staticStart_.assign(cells + 1, 0);
  statics_.clear();
  const double reach = bodies_.maxRadius * (1.0 + 1e-9);
  for (int cell = 0; cell < cells; ++cell) {
    staticStart_[cell] = static_cast<int>(statics_.size());
    const CellGrid::Coords c = grid_.coords(cell);
    const bool border = grid_.isBorder(c);
    Vec3 lo, hi;
    for (int a = 0; a < 3; ++a) {
      lo[a] = grid_.lowerFace(a, c[a]);
      hi[a] = grid_.upperFace(a, c[a]);
    }
    for (int k = 0; k < static_cast<int>(bodies_.planes.size()); ++k) {
      const PlaneShape& plane = bodies_.planes[k];
      // Nearest corner of the cell to the surface (or behind it) decides.
      double nearest = -plane.offset;
      if (!border)
        for (int a = 0; a < 3; ++a) nearest += plane.normal[a] * (plane.normal[a] > 0 ? lo[a] : hi[a]);
      if (border || nearest <= reach) statics_.push_back({false, k});
    }
    for (int k = 0; k < static_cast<int>(bodies_.cylinders.size()); ++k) {
      bool near = border;
      if (!near) {
        const Vec3 centre = 0.5 * (lo + hi);
        const double halfDiagonal = 0.5 * (hi - lo).norm();
        near = bodies_.cylinders[k].gap(centre, 0.0) <= halfDiagonal + reach;
      }
      if (near) statics_.push_back({true, k});
    }
  }
  staticStart_[cells] = static_cast<int>(statics_.size());
}

void EventEngine::predictAll() {
  queue_.reset(static_cast<int>(particles_.size()));
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) predict(i);
  // Balls heading for resting ones learn of it from the resting ball's side.
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i)
    if (particles_[i].resting) warnNeighbours(i);
}

BallPath EventEngine::pathAt(int i, double t) const {
  const Motion& m = particles_[i].motion;
  return {m.positionAt(t), m.velocityAt(t), m.acceleration};
}

template <typename F>
void EventEngine::forEachNeighbour(int i, F&& f) const {
  grid_.forEachNeighbourCell(grid_.coords(particles_[i].cell), [&](int cell) {
    members_.forEachIn(cell, [&](int k) {
      if (k != i) f(k);
    });
  });
}

void EventEngine::predict(int i) {
  Particle& p = particles_[i];
  Prediction next;
  double best = kNever;
  if (!p.resting) {
    const BallPath path = pathAt(i, now_);
    const double r = bodies_.radius[i];
    for (int s = staticStart_[p.cell]; s < staticStart_[p.cell + 1]; ++s) {
      const StaticRef ref = statics_[s];
      const double t =
          ref.cylinder ? ballCylinderContactTime(path, r, bodies_.cylinders[ref.index], best)
                       : ballPlaneContactTime(path, r, bodies_.planes[ref.index], best);
      if (t < best) {
        best = t;
        next = {ref.cylinder ? EventKind::Cylinder : EventKind::Plane, 0, ref.index, 0};
      }
    }
    forEachNeighbour(i, [&](int k) {
      const double t = ballBallContactTime(path, pathAt(k, now_), r + bodies_.radius[k], best);
      if (t < best) {
        best = t;
        next = {EventKind::Ball, 0, k, particles_[k].counter};
      }
    });
    const CellGrid::Coords c = grid_.coords(p.cell);
    for (int a = 0; a < 3; ++a) {
      const double up = boundaryCrossingTime(path.position[a], path.velocity[a],
                                             path.acceleration[a], grid_.upperFace(a, c[a]), true,
                                             best);
      if (up < best) {
        best = up;
        next = {EventKind::CellUp, static_cast<std::int8_t>(a), -1, 0};
      }
      const double down = boundaryCrossingTime(path.position[a], path.velocity[a],
                                               path.acceleration[a], grid_.lowerFace(a, c[a]),
                                               false, best);
      if (down < best) {
        best = down;
        next = {EventKind::CellDown, static_cast<std::int8_t>(a), -1, 0};
      }
    }
  }
  predictions_[i] = next;
  queue_.set(i, now_ + best);
}

void EventEngine::warnNeighbours(int i) {
  const BallPath path = pathAt(i, now_);
  forEachNeighbour(i, [&](int k) {
    if (particles_[k].resting) return;
    const double t =
        ballBallContactTime(pathAt(k, now_), path, bodies_.radius[i] + bodies_.radius[k], kNever);
    if (now_ + t < queue_.timeOf(k)) {
      predictions_[k] = {EventKind::Ball, 0, i, particles_[i].counter};
      queue_.set(k, now_ + t);
    }
  });
}

void EventEngine::advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) {
  while (!queue_.empty() && queue_.topTime() <= end) {
    const int i = queue_.top();
    now_ = std::max(now_, queue_.topTime());  // time never steps backwards
    process(i, stats, log);
  }
  now_ = std::max(now_, end);
}

void EventEngine::process(int i, RunStats& stats, std::vector<CollisionRecord>* log) {
  ++stats.events;
  const Prediction event = predictions_[i];
  Particle& p = particles_[i];
  switch (event.kind) {
    case EventKind::None:
      queue_.set(i, kNever);
      return;
    case EventKind::CellUp:
    case EventKind::CellDown: {
      ++stats.cellCrossings;
      CellGrid::Coords c = grid_.coords(p.cell);
      c[event.axis] += event.kind == EventKind::CellUp ? 1 : -1;
      members_.remove(i);
      p.cell = grid_.index(c);
      members_.insert(i, p.cell);
      predict(i);  // the path is unchanged, so predictions involving i stay valid
      return;
    }
    case EventKind::Plane:
    case EventKind::Cylinder: {
      p.motion.moveTo(now_);
      const double r = bodies_.radius[i];
      Vec3 n;
      double gap, restitution;
      if (event.kind == EventKind::Plane) {
        const PlaneShape& plane = bodies_.planes[event.other];
        n = plane.normal;
        gap = plane.gap(p.motion.position, r);
        restitution = std::min(bodies_.restitution[i], bodies_.planeRestitution[event.other]);
      } else {
        const CylinderShape& cylinder = bodies_.cylinders[event.other];
        n = cylinder.perpendicular(p.motion.position - cylinder.point);
        gap = n.norm() - cylinder.radius - r;
        n.normalize();
        restitution = std::min(bodies_.restitution[i], bodies_.cylinderRestitution[event.other]);
      }
      notePenetration(-gap, stats);
      const double approach = -p.motion.velocity.dot(n);
      if (collideWithSurface(i, n, restitution, stats)) {
        if (event.kind == EventKind::Plane)
          ++stats.collisions.ballPlane;
        else
          ++stats.collisions.ballCylinder;
        if (log)
          log->push_back({now_,
                          event.kind == EventKind::Plane ? ContactKind::BallPlane
                                                         : ContactKind::BallCylinder,
                          i, event.other, p.motion.position - r * n, approach});
      }
      if (!particles_[i].resting) predict(i);
      return;
    }
    case EventKind::Ball: {
      const int j = event.other;
      if (particles_[j].counter != event.otherCounter) {
        ++stats.staleEvents;
        predict(i);
        return;
      }
      collideBalls(i, j, stats, log);
      return;
    }
  }
}

void EventEngine::collideBalls(int i, int j, RunStats& stats, std::vector<CollisionRecord>* log) {
  Particle& a = particles_[i];
  Particle& b = particles_[j];
  a.motion.moveTo(now_);
  b.motion.moveTo(now_);
  Vec3 n = b.motion.position - a.motion.position;
  const double distance = n.norm();
  const double radiusSum = bodies_.radius[i] + bodies_.radius[j];
  notePenetration(radiusSum - distance, stats);
  n /= distance;
  const double approach = (a.motion.velocity - b.motion.velocity).dot(n);
  const double restitution = std::min(bodies_.restitution[i], bodies_.restitution[j]);
  bool collided = false;
  if (b.resting && approach < tolerance::kWakeSpeedFactor * restSpeed_[i]) {
    // Too gentle to move a resting ball: it acts as an immovable surface.
    collided = collideWithSurface(i, -n, restitution, stats);
  } else if (approach > 0.0) {
    if (b.resting) wake(j, stats);
    resolveBallBall(a.motion.velocity, b.motion.velocity, bodies_.inverseMass[i],
                    bodies_.inverseMass[j], n, restitution, collapseSpeed_);
    changed(i);
    changed(j);
    collided = true;
  }
  if (collided) {
    ++stats.collisions.ballBall;
    if (log)
      log->push_back({now_, ContactKind::BallBall, i, j,
                      a.motion.position + bodies_.radius[i] * n, approach});
  }
  if (!a.resting) predict(i);
  if (!b.resting) predict(j);
}

bool EventEngine::collideWithSurface(int i, const Vec3& n, double restitution, RunStats& stats) {
  Particle& p = particles_[i];
  const double approach = -p.motion.velocity.dot(n);
  const bool pressed = gravity_.dot(n) < 0.0;
  if (approach <= 0.0 && !pressed) return false;
  const double rest = restSpeed_[i];
  // Any slow contact may end in rest, also a sideways one: a ball on a floor trapped between a
  // wall and a resting ball would otherwise rattle between them.
  if (approach < rest) {
    const Vec3 tangential = p.motion.velocity + approach * n;
    if (tangential.norm() < rest && supported(i)) {
      putToRest(i, stats);
      return true;
    }
  }
  const double minimum = pressed ? rest : collapseSpeed_;
  if (restitution * std::max(approach, 0.0) < minimum) ++stats.minimumBounces;
  resolveAgainstSurface(p.motion.velocity, n, restitution, minimum);
  changed(i);
  // A zero-time cycle of contacts (a ball wedged between shapes) must not hang the run.
  if (p.instant == now_) {
    if (++p.collisionsThisInstant > tolerance::kMaxCollisionsAtOneInstant) putToRest(i, stats);
  } else {
    p.instant = now_;
    p.collisionsThisInstant = 0;
  }
  return true;
}

void EventEngine::changed(int i) { ++particles_[i].counter; }

void EventEngine::putToRest(int i, RunStats& stats) {
  Particle& p = particles_[i];
  p.motion.moveTo(now_);
  p.motion.velocity.setZero();
  p.motion.acceleration.setZero();
  p.resting = true;
  changed(i);
  ++stats.restings;
  predictions_[i] = {};
  queue_.set(i, kNever);
  warnNeighbours(i);
}

void EventEngine::wake(int i, RunStats& stats) {
  // Resting balls touching a woken ball from above may have rested on it: wake them, and
  // whatever rests on them.
  std::vector<int> pending{i};
  particles_[i].resting = false;
  while (!pending.empty()) {
    const int k = pending.back();
    pending.pop_back();
    Particle& p = particles_[k];
    ++stats.wakes;
    p.motion.since = now_;
    p.motion.acceleration = pathAcceleration_;
    p.collisionsThisInstant = 0;
    changed(k);
    forEachNeighbour(k, [&](int m) {
      Particle& q = particles_[m];
      if (!q.resting) return;
      const Vec3 offset = q.motion.position - p.motion.position;
      if (offset.dot(gravity_) >= 0.0) return;  // beside or below: it does not rest on k
      const double gap = offset.norm() - bodies_.radius[k] - bodies_.radius[m];
      if (gap <= tolerance::kSupportGapFraction * std::min(bodies_.radius[k], bodies_.radius[m])) {
        q.resting = false;
        pending.push_back(m);
      }
    });
    if (k != i) predict(k);
  }
}

// Resting balls and balls slower than the rest speed count as supports: neighbours leaning on
// each other in a pile must be able to come to rest one after the other.
bool EventEngine::supported(int i) const {
  const Particle& p = particles_[i];
  const Vec3 centre = p.motion.positionAt(now_);
  const double r = bodies_.radius[i];
  const double reach = tolerance::kSupportGapFraction * r;
  std::vector<Vec3> normals;
  for (int s = staticStart_[p.cell]; s < staticStart_[p.cell + 1]; ++s) {
    const StaticRef ref = statics_[s];
    if (ref.cylinder) {
      const CylinderShape& cylinder = bodies_.cylinders[ref.index];
      if (cylinder.gap(centre, r) <= reach)
        normals.push_back(cylinder.perpendicular(centre - cylinder.point).normalized());
    } else {
      const PlaneShape& plane = bodies_.planes[ref.index];
      if (plane.gap(centre, r) <= reach) normals.push_back(plane.normal);
    }
  }
  forEachNeighbour(i, [&](int k) {
    const Particle& q = particles_[k];
    if (!q.resting && q.motion.velocityAt(now_).norm() >= restSpeed_[i]) return;
    const Vec3 d = centre - q.motion.positionAt(now_);
    if (d.norm() - r - bodies_.radius[k] <= reach) normals.push_back(d.normalized());
  });
  return holdsAgainstGravity(gravity_, normals);
}

void EventEngine::notePenetration(double overlap, RunStats& stats) const {
  stats.maxPenetration = std::max(stats.maxPenetration, overlap);
}

std::string EventEngine::gridSummary() const {
  const CellGrid::Coords& c = grid_.counts();
  return "cell grid " + std::to_string(c[0]) + "x" + std::to_string(c[1]) + "x" +
         std::to_string(c[2]) + ", " + std::to_string(statics_.size()) +
         " static-shape entries in cells";
}

BallState EventEngine::stateOf(int ball) const {
  const Particle& p = particles_[ball];
  return {p.motion.positionAt(now_), p.motion.velocityAt(now_), p.resting};
}

std::vector<BallState> EventEngine::state() const {
  std::vector<BallState> all(particles_.size());
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) all[i] = stateOf(i);
  return all;
}

void EventEngine::setVelocities(const std::vector<Vec3>& velocities) {
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    Particle& p = particles_[i];
    if (p.resting) continue;
    p.motion.moveTo(now_);
    p.motion.velocity = velocities[i];
    changed(i);
  }
  predictAll();
}

}  // namespace carom
