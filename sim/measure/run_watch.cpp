#include "sim/measure/run_watch.h"

#include "sim/exact/static_bins.h"
#include "sim/stepped/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace carom {
namespace {

// A plane whose normal is within 60 degrees of up is a floor: the balls' lowest height.
constexpr double kFloorCosine = 0.5;

unsigned char bit(WatchKind kind) {
  return static_cast<unsigned char>(1u << static_cast<int>(kind));
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

std::string timeText(double t) {
  std::ostringstream out;
  out.precision(9);
  out << t;
  return out.str();
}

std::string otherText(WatchOther kind, int index) {
  switch (kind) {
    case WatchOther::None:
      return {};
    case WatchOther::Ball:
      return "ball " + std::to_string(index);
    case WatchOther::Plane:
      return "plane " + std::to_string(index);
    case WatchOther::Cylinder:
      return "cylinder " + std::to_string(index);
    case WatchOther::Box:
      return "box " + std::to_string(index);
  }
  return {};
}

WatchOther otherOf(StaticBins::Kind kind) {
  switch (kind) {
    case StaticBins::Kind::Plane:
      return WatchOther::Plane;
    case StaticBins::Kind::Cylinder:
      return WatchOther::Cylinder;
    case StaticBins::Kind::Box:
      return WatchOther::Box;
  }
  return WatchOther::None;
}

bool allRestitutionsAtMostOne(const Bodies& bodies) {
  for (const std::vector<double>* values : {&bodies.planeRestitution, &bodies.cylinderRestitution,
                                            &bodies.boxRestitution, &bodies.restitution})
    for (double e : *values)
      if (!(e <= 1.0)) return false;
  return true;
}

double ballEnergy(const Bodies& bodies, const Vec3& gravity, int i, const BallState& s) {
  return 0.5 * bodies.mass[i] * s.velocity.squaredNorm() - bodies.mass[i] * gravity.dot(s.position);
}

std::string describe(const WatchEvent& e) {
  const std::string ball = "ball " + std::to_string(e.ball);
  const std::string at = " at t = " + timeText(e.time) + " s";
  switch (e.kind) {
    case WatchKind::NonFinite:
      return "non-finite position or velocity of " + ball + at;
    case WatchKind::EnergyRise:
      return "energy rose by " + number(e.value) + " of its scale (tolerance " +
             number(e.tolerance) + "), most in " + ball + at;
    case WatchKind::Escape:
      return ball + " escaped into " + otherText(e.otherKind, e.other) + ": its centre is " +
             number(e.value) + " of its radius past the surface (tolerance " + number(e.tolerance) +
             ")" + at;
    case WatchKind::Penetration:
      return ball + " overlaps " + otherText(e.otherKind, e.other) + " by " + number(e.value) +
             (e.otherKind == WatchOther::Ball ? " of the smaller radius" : " of its radius") +
             " (tolerance " + number(e.tolerance) + ")" + at;
  }
  return {};
}

}  // namespace

bool WatchSettings::enabled(WatchKind kind) const {
  return this->*watchCheck(kind).on;
}

bool& WatchSettings::enabled(WatchKind kind) {
  return this->*watchCheck(kind).on;
}

std::vector<ValidationError> validateWatchSettings(const WatchSettings& settings) {
  std::vector<ValidationError> errors;
  const auto check = [&](std::string_view path, double value) {
    if (!std::isfinite(value) || value < 0.0 || value > kMaxWatchTolerance)
      errors.push_back({std::string(path), "must be a number from 0 to " +
                                               number(kMaxWatchTolerance) + " (got " +
                                               number(value) + ")"});
  };
  for (const WatchCheck& watched : kWatchChecks)
    if (watched.tolerance) check(watched.tolerancePath, settings.*watched.tolerance);
  return errors;
}

// The worst problem of one kind found so far in a check: the largest excess over the tolerance.
struct RunWatch::Found {
  WatchEvent event;
  double excess = -1.0;  // value / tolerance, or value when the tolerance is 0
  bool found() const { return excess >= 0.0; }
  void offer(int ball, WatchOther otherKind, int other, double value, double tolerance) {
    const double e = tolerance > 0.0 ? value / tolerance : value;
    if (e <= excess) return;
    excess = e;
    event.ball = ball;
    event.otherKind = otherKind;
    event.other = other;
    event.value = value;
    event.tolerance = tolerance;
  }
};

RunWatch::RunWatch(const WatchSettings& settings) : settings_(settings) {}

void RunWatch::setSettings(const WatchSettings& settings) {
  settings_ = settings;
}

void RunWatch::rebase(const Simulation& sim) {
  const Bodies& bodies = sim.bodies();
  if (bodies_ != &bodies || !bins_) {
    bins_ = std::make_shared<const StaticBins>(bodies);
    bodies_ = &bodies;
  }
  energyApplies_ = allRestitutionsAtMostOne(bodies);
  const std::vector<BallState> state = sim.state();
  reported_.assign(state.size(), 0);
  lastGoodTime_ = sim.time();
  takeEnergyBaseline(sim, state);
  based_ = true;
}

void RunWatch::takeEnergyBaseline(const Simulation& sim, const std::vector<BallState>& state) {
  const Bodies& bodies = *bodies_;
  const Vec3& g = sim.world().gravity;
  const double gNorm = g.norm();
  const Vec3 down = gNorm > 0.0 ? Vec3(g / gNorm) : Vec3::Zero();
  double kinetic = 0.0, weight = 0.0, energy = 0.0;
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
  ballEnergy_.resize(state.size());
  for (int i = 0; i < static_cast<int>(state.size()); ++i) {
    const BallState& s = state[i];
    kinetic += 0.5 * bodies.mass[i] * s.velocity.squaredNorm();
    weight += bodies.mass[i] * gNorm;
    const double height = -down.dot(s.position);
    top = std::max(top, height + bodies.radius[i]);
    bottom = std::min(bottom, height - bodies.radius[i]);
    ballEnergy_[i] = ballEnergy(bodies, g, i, s);
    energy += ballEnergy_[i];
  }
  // The scene's floors and finite shapes bound how far the balls can fall.
  const Vec3 up = -down;
  for (const PlaneShape& plane : bodies.planes)
    if (plane.normal.dot(up) >= kFloorCosine)
      bottom = std::min(bottom, plane.offset / plane.normal.dot(up));
  for (const BoxShape& box : bodies.boxes) {
    const double height = up.dot(box.center), half = up.cwiseAbs().dot(box.reach());
    top = std::max(top, height + half);
    bottom = std::min(bottom, height - half);
  }
  for (const CylinderShape& cylinder : bodies.cylinders) {
    if (!cylinder.capped()) continue;
    const double height = up.dot(cylinder.point), half = up.cwiseAbs().dot(cylinder.reach());
    top = std::max(top, height + half);
    bottom = std::min(bottom, height - half);
  }
  energyScale_ = state.empty() || gNorm == 0.0 ? kinetic : kinetic + weight * (top - bottom);
  // Non-finite energy is the non-finite check's business; the scale must not become NaN.
  if (!std::isfinite(energyScale_)) energyScale_ = 0.0;
  baselineEnergy_ = energy;
}

std::optional<WatchEvent> RunWatch::check(const Simulation& sim) {
  if (!settings_.anyEnabled()) return std::nullopt;
  if (!based_ || bodies_ != &sim.bodies() ||
      reported_.size() != static_cast<std::size_t>(sim.ballCount()))
    rebase(sim);
  const Bodies& bodies = sim.bodies();
  const std::vector<BallState> state = sim.state();
  const int n = static_cast<int>(state.size());
  const double now = sim.time();

  Found found[kWatchKindCount];
  for (int k = 0; k < kWatchKindCount; ++k) found[k].event.kind = static_cast<WatchKind>(k);
  // Which balls show each problem this time, to forget a report once its problem has gone.
  std::vector<unsigned char> current(n, 0);

  bool allFinite = true;
  for (int i = 0; i < n; ++i) {
    if (state[i].position.allFinite() && state[i].velocity.allFinite()) continue;
    allFinite = false;
    current[i] |= bit(WatchKind::NonFinite);
    if (settings_.nonFinite && !(reported_[i] & bit(WatchKind::NonFinite)))
      found[int(WatchKind::NonFinite)].offer(i, WatchOther::None, -1, 0.0, 0.0);
  }

  // Shapes and pairs are looked at only when every number is finite: a NaN has no place in a
  // grid, and the non-finite report says all there is to say.
  if (allFinite && (settings_.escape || settings_.penetration)) {
    const auto offer = [&](WatchKind kind, int ball, WatchOther otherKind, int other, double value,
                           double tolerance) {
      current[ball] |= bit(kind);
      if (settings_.enabled(kind) && !(reported_[ball] & bit(kind)))
        found[int(kind)].offer(ball, otherKind, other, value, tolerance);
    };
    for (int i = 0; i < n; ++i) {
      const Vec3& p = state[i].position;
      const double r = bodies.radius[i];
      bins_->forEachNear(p, [&](const StaticBins::Entry& entry) {
        double gap = 0.0;
        switch (entry.kind) {
          case StaticBins::Kind::Plane:
            gap = bodies.planes[entry.index].gap(p, r);
            break;
          case StaticBins::Kind::Cylinder:
            gap = bodies.cylinders[entry.index].contact(p, r).gap;
            break;
          case StaticBins::Kind::Box:
            gap = bodies.boxes[entry.index].contact(p, r).gap;
            break;
        }
        // The centre's depth past the surface, and the overlap, in radii.
        const double centreDepth = -(gap + r) / r;
        const double overlap = -gap / r;
        if (settings_.escape && centreDepth > settings_.escapeTolerance)
          offer(WatchKind::Escape, i, otherOf(entry.kind), entry.index, centreDepth,
                settings_.escapeTolerance);
        else if (overlap > settings_.penetrationTolerance)
          offer(WatchKind::Penetration, i, otherOf(entry.kind), entry.index, overlap,
                settings_.penetrationTolerance);
      });
    }
    if (settings_.penetration) {
      std::vector<Vec3> centres(n);
      for (int i = 0; i < n; ++i) centres[i] = state[i].position;
      forEachCloseBallPair(centres, bodies.radius, 0.0, [&](int i, int j) {
        const double smaller = std::min(bodies.radius[i], bodies.radius[j]);
        const double overlap =
            (bodies.radius[i] + bodies.radius[j] - (centres[i] - centres[j]).norm()) / smaller;
        if (overlap <= settings_.penetrationTolerance) return;
        // Named by the smaller ball, whose radius the depth is measured in.
        const bool iSmaller = bodies.radius[i] <= bodies.radius[j];
        current[iSmaller ? j : i] |= bit(WatchKind::Penetration);
        offer(WatchKind::Penetration, iSmaller ? i : j, WatchOther::Ball, iSmaller ? j : i, overlap,
              settings_.penetrationTolerance);
      });
    }
  }

  if (allFinite) {
    const Vec3& g = sim.world().gravity;
    double energy = 0.0, largestGain = -std::numeric_limits<double>::infinity();
    int gainer = 0;
    for (int i = 0; i < n; ++i) {
      const double e = ballEnergy(bodies, g, i, state[i]);
      energy += e;
      if (e - ballEnergy_[i] > largestGain) {
        largestGain = e - ballEnergy_[i];
        gainer = i;
      }
      ballEnergy_[i] = e;
    }
    if (settings_.energyRise && energyApplies_ && n > 0) {
      const double rise = energy - baselineEnergy_;
      const double allowed = settings_.energyRiseTolerance * energyScale_;
      if (rise > allowed)
        found[int(WatchKind::EnergyRise)].offer(gainer, WatchOther::None, -1,
                                                energyScale_ > 0.0 ? rise / energyScale_ : rise,
                                                settings_.energyRiseTolerance);
    }
  }

  // Reports stand while their problems last.
  for (int i = 0; i < n; ++i) reported_[i] &= current[i];

  for (WatchKind kind :
       {WatchKind::NonFinite, WatchKind::Escape, WatchKind::Penetration, WatchKind::EnergyRise}) {
    Found& f = found[int(kind)];
    if (!f.found()) continue;
    WatchEvent event = f.event;
    event.time = now;
    event.lastGoodTime = lastGoodTime_;
    event.text = describe(event);
    reported_[event.ball] |= bit(kind);
    if (kind == WatchKind::EnergyRise) takeEnergyBaseline(sim, state);
    return event;
  }
  lastGoodTime_ = now;
  return std::nullopt;
}

}  // namespace carom
