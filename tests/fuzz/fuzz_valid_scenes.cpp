// libFuzzer target: any scene that validation accepts runs. The bytes choose a scene over the
// whole accepted range (radii from 1e-12 to 1e12 m, positions, speeds and gravity up to 1e12,
// every method and integrator, planes, cylinders and boxes, friction and spin), kept valid by
// dropping each ball that validation refuses; the scene then runs for a few hundred events or a few
// dozen steps, under other world settings from half way, with the run's measures and watch looking
// on. A crash, an exception, a non-finite position or velocity, or a run that never ends
// (libFuzzer's -timeout) is a finding. Built by scripts/fuzz.sh.

#include "sim/core/tolerances.h"
#include "sim/geometry/shapes.h"
#include "sim/measure/measures.h"
#include "sim/measure/run_watch.h"
#include "sim/simulation.h"
#include "sim/validation/validation.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace {

using namespace carom;
namespace tol = carom::tolerance;

// A run's work: events (exact, swept) and steps (swept, discrete), so that a unit stays well
// under a second however fast the scene's balls move.
constexpr std::uint64_t kMaxEvents = 400;
constexpr std::uint64_t kMaxSteps = 40;
constexpr int kMaxSlices = 256;
constexpr int kMaxBalls = 16;
// Slices are at least this fraction of the time (some 45 ulps): a ball of 1e-9 m at 4e10 m/s
// crosses its radius in less than an ulp of the time a run reaches.
constexpr double kLeastSliceFraction = 1e-14;
// Runs end by this time: gravity of 1e12 m/s^2 takes a ball beyond any double in 1e148 s.
constexpr double kLatestTime = 1e100;
// A touching ball whose speed along the normal is within this fraction of its speed slides or
// rests along it (the engine's own threshold is kTangentRateFraction, 1e-12).
constexpr double kSlidingRate = 1e-9;

class SceneMaker {
 public:
  explicit SceneMaker(FuzzedDataProvider& bytes) : bytes_(bytes) {}

  Scene make() {
    Scene scene;
    scene.world = world();
    // The scene's own length scale and a few places it happens at, anywhere in range: most
    // objects are sized and placed by them, so that they meet; some anywhere at all.
    scale_ = logUniform(tol::kMinRadius, tol::kMaxMagnitude);
    // Masses anywhere in range, but within 100 of one another: a light ball pinched between a
    // heavy one and a wall takes pi sqrt(M / m) collisions to turn it back, some M / m when
    // inelastic (a ratio of 1e4 made 368,000 in a microsecond), so ratios over the whole range
    // (1e60) make valid scenes no run can finish, however correct.
    mass_ = logUniform(tol::kMinMass, tol::kMaxMass);
    const int anchors = bytes_.ConsumeIntegralInRange(1, 3);
    for (int k = 0; k < anchors; ++k) anchors_.push_back(anywhere());
    for (int k = bytes_.ConsumeIntegralInRange(0, 3); k > 0; --k) scene.planes.push_back(plane());
    for (int k = bytes_.ConsumeIntegralInRange(0, 3); k > 0; --k) {
      scene.cylinders.push_back(cylinder());
      targets_.push_back(scene.cylinders.back().point);
    }
    for (int k = bytes_.ConsumeIntegralInRange(0, 3); k > 0; --k) {
      scene.boxes.push_back(box());
      targets_.push_back(scene.boxes.back().center);
    }
    for (int k = bytes_.ConsumeIntegralInRange(0, kMaxBalls); k > 0; --k) {
      scene.balls.push_back(ball());
      // An overlapping ball (or one validation refuses otherwise) is dropped.
      if (!validateObjects(scene, {{}, {}, {}, {scene.balls.size() - 1}}, 1).empty())
        scene.balls.pop_back();
    }
    // Half the time, steps of a ball's time to cross its radius or some more: over the whole
    // range, most runs of a few dozen steps would see nothing happen.
    if (bytes_.ConsumeBool()) scene.world.timeStep = stepForScene(scene);
    return scene;
  }

  double stepForScene(const Scene& scene) {
    double crossing = tol::kMaxTimeStep;
    for (const Ball& ball : scene.balls)
      if (ball.velocity.norm() > 0.0)
        crossing = std::min(crossing, ball.radius / ball.velocity.norm());
    return std::clamp(crossing * logUniform(1.0, 1e3), tol::kMinTimeStep, tol::kMaxTimeStep);
  }

  World world() {
    World w;
    w.method = method();
    w.integrator = integrator();
    w.gravity = bytes_.ConsumeBool() ? Vec3::Zero() : along(direction());
    w.timeStep = logUniform(tol::kMinTimeStep, tol::kMaxTimeStep);
    w.restitution = bytes_.ConsumeBool() ? 1.0 : bytes_.ConsumeProbability<double>();
    return w;
  }

  // Friction and spin are taken from the bytes after all the rest, so that an input found
  // before them makes the same scene: its bytes run out here, and bytes run out give none.
  void addFriction(Scene& scene, World& later) {
    for (World* w : {&scene.world, &later}) {
      w->friction = coefficient().value_or(0.0);
      w->rollingResistance = coefficient().value_or(0.0);
      w->spinningFriction = coefficient().value_or(0.0);
      w->tangentialRestitution = bytes_.ConsumeBool() ? bytes_.ConsumeProbability<double>() : 0.0;
    }
    for (Plane& plane : scene.planes) giveCoefficients(plane);
    for (Cylinder& cylinder : scene.cylinders) giveCoefficients(cylinder);
    for (Box& box : scene.boxes) giveCoefficients(box);
    for (Ball& ball : scene.balls) {
      giveCoefficients(ball);
      if (bytes_.ConsumeBool()) ball.angularVelocity = along(direction());
    }
  }

 private:
  Method method() {
    return bytes_.PickValueInArray({Method::Exact, Method::Swept, Method::Discrete});
  }
  Integrator integrator() {
    return bytes_.PickValueInArray(
        {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::VelocityVerlet});
  }
  double logUniform(double low, double high) {
    const double p = bytes_.ConsumeProbability<double>();
    return std::clamp(std::exp(std::log(low) + p * (std::log(high) - std::log(low))), low, high);
  }
  double uniform(double low, double high) {
    return low + bytes_.ConsumeProbability<double>() * (high - low);
  }
  // A size: the scene's scale give or take a factor of ten, or anything in range.
  double size() {
    if (bytes_.ConsumeBool()) return logUniform(tol::kMinRadius, tol::kMaxMagnitude);
    return std::clamp(scale_ * logUniform(0.1, 10.0), tol::kMinRadius, tol::kMaxMagnitude);
  }
  double magnitude() { return logUniform(tol::kMinRadius, tol::kMaxMagnitude); }
  // Three values in turn: in one call's arguments their order would be the compiler's.
  template <typename F>
  Vec3 vector(F&& value) {
    Vec3 v;
    for (int a = 0; a < 3; ++a) v[a] = value();
    return v;
  }
  Vec3 direction() {
    const Vec3 d = vector([&] { return uniform(-1.0, 1.0); });
    return d.norm() > 1e-3 ? Vec3(d.normalized()) : Vec3::UnitY();
  }
  static Vec3 clamped(const Vec3& v) {
    return v.cwiseMax(-tol::kMaxMagnitude).cwiseMin(tol::kMaxMagnitude);
  }
  Vec3 anywhere() {
    return vector([&] {
      if (bytes_.ConsumeBool()) return 0.0;
      const double sign = bytes_.ConsumeBool() ? -1.0 : 1.0;
      return sign * magnitude();
    });
  }
  // A vector of any magnitude in range along unit vector `unit`.
  Vec3 along(const Vec3& unit) {
    const double length = magnitude();
    return clamped(length * unit);
  }
  // A few sizes.
  double distance() {
    const double sizes = uniform(0.0, 8.0);
    return sizes * size();
  }
  const Vec3& anchor() {
    return anchors_[bytes_.ConsumeIntegralInRange<std::size_t>(0, anchors_.size() - 1)];
  }
  // Near one of the anchors, a few sizes away, or anywhere.
  Vec3 place() {
    if (bytes_.ConsumeIntegralInRange(0, 7) == 0) return anywhere();
    const Vec3& from = anchor();
    const double length = distance();
    return clamped(from + length * direction());
  }
  // Mostly towards an anchor, where the other objects are, or a finite shape.
  Vec3 velocity(const Vec3& from) {
    const int kind = bytes_.ConsumeIntegralInRange(0, 3);
    if (kind == 0) return Vec3::Zero();
    if (kind == 1) return along(direction());
    const Vec3& target =
        kind == 3 && !targets_.empty()
            ? targets_[bytes_.ConsumeIntegralInRange<std::size_t>(0, targets_.size() - 1)]
            : anchor();
    const Vec3 to = target - from;
    const double distance = to.norm();
    return along(distance > 0.0 ? Vec3(to / distance) : direction());
  }
  std::optional<double> restitution() {
    if (bytes_.ConsumeBool()) return std::nullopt;
    return bytes_.ConsumeProbability<double>();
  }
  // Mostly a real material's, at times anything up to the limit.
  std::optional<double> coefficient() {
    if (!bytes_.ConsumeBool()) return std::nullopt;
    if (bytes_.ConsumeBool()) return bytes_.ConsumeProbability<double>();
    return logUniform(1.0, tol::kMaxFriction);
  }
  void giveCoefficients(ObjectInfo& info) {
    info.friction = coefficient();
    info.rollingResistance = coefficient();
    info.spinningFriction = coefficient();
  }
  Plane plane() {
    // Facing an anchor, so that the balls around it are in front of it.
    Plane p;
    p.normal = direction();
    const Vec3& from = anchor();
    p.point = clamped(from - distance() * p.normal);
    p.restitution = restitution();
    return p;
  }
  Cylinder cylinder() {
    Cylinder c;
    c.point = place();
    c.axis = direction();
    c.radius = size();
    if (bytes_.ConsumeBool()) c.length = size();
    c.restitution = restitution();
    return c;
  }
  Box box() {
    Box b;
    b.center = place();
    b.halfExtents = vector([&] { return size(); });
    if (bytes_.ConsumeBool()) b.rotation = Rotation{direction(), uniform(-360.0, 360.0)};
    b.restitution = restitution();
    return b;
  }
  Ball ball() {
    Ball b;
    b.position = place();
    b.velocity = velocity(b.position);
    b.radius = size();
    b.mass = std::clamp(mass_ * logUniform(0.1, 10.0), tol::kMinMass, tol::kMaxMass);
    b.restitution = restitution();
    return b;
  }

  FuzzedDataProvider& bytes_;
  double scale_ = 1.0;
  double mass_ = 1.0;
  std::vector<Vec3> anchors_;
  std::vector<Vec3> targets_;  // the finite shapes' centres
};

bool finiteState(const Simulation& sim) {
  for (const BallState& ball : sim.state())
    if (!ball.position.allFinite() || !ball.velocity.allFinite()) return false;
  return true;
}

constexpr double kNever = std::numeric_limits<double>::infinity();

// The time for the quickest ball to move a tenth of its radius, by its speed or by gravity: a
// few hops of a ball on a floor at the rest speed, the quickest events a scene has.
double fineSlice(const Simulation& sim) {
  double slice = kNever;
  const double g = sim.world().gravity.norm();
  const std::vector<BallState> state = sim.state();
  for (std::size_t i = 0; i < state.size(); ++i) {
    const double reach = 0.1 * sim.bodies().radius[i];
    const double speed = state[i].velocity.norm();
    if (speed > 0.0) slice = std::min(slice, reach / speed);
    if (g > 0.0) slice = std::min(slice, std::sqrt(2.0 * reach / g));
  }
  return slice;
}

// The least time for a gap to close at `closing` (negative: receding), accelerated by
// `acceleration` at most, between two things at `speed` to each other. Touching (a gap of zero
// or less): the way back of a ball that left, now for one that approaches, and never for one
// that slides or rests along (its closing within round-off of its speed): no new contact.
double meetingTime(double gap, double closing, double acceleration, double speed) {
  if (gap > 0.0) {
    // The root of gap = c t + acceleration t^2 / 2, in a form without cancellation.
    const double c = std::max(closing, 0.0);
    return 2.0 * gap / (c + std::sqrt(c * c + 2.0 * acceleration * gap));
  }
  if (std::abs(closing) <= kSlidingRate * speed) return kNever;
  if (closing > 0.0) return 0.0;
  return acceleration > 0.0 ? -2.0 * closing / acceleration : kNever;
}

// The same for a ball at velocity v and a shape within some slabs: the ball meets it no sooner
// than it is in all of them, each a gap along a unit normal that it closes at v along it. In
// all of them, the shape's own gap and normal decide.
template <std::size_t N>
double slabsMeetingTime(const std::array<std::pair<double, Vec3>, N>& slabs, double gap,
                        const Vec3& normal, const Vec3& v, double g) {
  double latest = 0.0;
  bool inside = true;
  for (const auto& [slabGap, n] : slabs) {
    if (slabGap <= 0.0) continue;
    inside = false;
    latest = std::max(latest, meetingTime(slabGap, -v.dot(n), g, v.norm()));
  }
  if (!inside) return latest;
  return meetingTime(gap, gap > 0.0 ? v.norm() : -v.dot(normal), g, v.norm());
}

// The least time before any ball could make a new contact with another ball or a shape, with
// gravity's whole pull (twice for a pair: one of them may rest). Until then the run only moves
// balls along.
double timeToFirstMeeting(const Simulation& sim) {
  const std::vector<BallState> state = sim.state();
  const Bodies& bodies = sim.bodies();
  const double g = sim.world().gravity.norm();
  double earliest = kNever;
  for (std::size_t i = 0; i < state.size(); ++i) {
    const Vec3& at = state[i].position;
    const Vec3& v = state[i].velocity;
    const double r = bodies.radius[i];
    for (std::size_t j = i + 1; j < state.size(); ++j) {
      const Vec3 offset = at - state[j].position;
      const Vec3 relative = v - state[j].velocity;
      const double distance = offset.norm();
      if (distance == 0.0) return 0.0;
      const double gap = distance - r - bodies.radius[j];
      const double speed = relative.norm();
      const double closing = gap > 0.0 ? speed : -relative.dot(offset / distance);
      earliest = std::min(earliest, meetingTime(gap, closing, 2.0 * g, speed));
    }
    for (const PlaneShape& plane : bodies.planes)
      earliest =
          std::min(earliest, meetingTime(plane.gap(at, r), -v.dot(plane.normal), g, v.norm()));
    for (const CylinderShape& cylinder : bodies.cylinders) {
      const CylinderShape::Contact contact = cylinder.contact(at, r);
      const Vec3 offset = at - cylinder.point;
      const double along = cylinder.axis.dot(offset);
      // The side's slab: the distance from the axis, which closes no faster than the speed
      // across it; and the caps' (none for an infinite cylinder).
      const Vec3 across = cylinder.perpendicular(v);
      const Vec3 side = across.norm() > 0.0 ? Vec3(-across.normalized()) : Vec3::Zero();
      const std::array<std::pair<double, Vec3>, 2> slabs{
          {{cylinder.perpendicular(offset).norm() - cylinder.radius - r, side},
           {std::abs(along) - cylinder.halfLength - r,
            along < 0.0 ? Vec3(-cylinder.axis) : cylinder.axis}}};
      earliest = std::min(earliest, slabsMeetingTime(slabs, contact.gap, contact.normal, v, g));
    }
    for (const BoxShape& box : bodies.boxes) {
      const BoxShape::Contact contact = box.contact(at, r);
      const Vec3 local = box.toLocal(at);
      std::array<std::pair<double, Vec3>, 3> slabs;
      for (int a = 0; a < 3; ++a)
        slabs[a] = {std::abs(local[a]) - box.half[a] - r,
                    local[a] < 0.0 ? Vec3(-box.axes.col(a)) : Vec3(box.axes.col(a))};
      earliest = std::min(earliest, slabsMeetingTime(slabs, contact.gap, contact.normal, v, g));
    }
  }
  return earliest;
}

// Runs `sim` for a bounded amount of work in two halves, the second under `later` (the window
// changes world settings live), trapping on a non-finite ball. Work is bounded by events, not
// by time. A slice runs up to where a ball could first make a new contact, which only moves
// balls along; when that is near, no further than a few of the scene's quickest events
// (fineSlice) and a length that grows while slices hold few events and shrinks when they hold
// many; and never less than a few ulps of the time. A slice grown over a long flight could
// otherwise hold a burst of millions of events, all correct: a ball hopping at the rest speed
// under 1e12 m/s^2 makes 1e11 a second. The stepping methods' slices stay within a few steps.
void run(Simulation& sim, const World& later) {
  sim.setCollisionLog(true);
  RunWatch watch;
  double grown = kNever;
  for (int half = 0; half < 2; ++half) {
    if (half == 1) sim.setWorld(later);
    const RunStats start = sim.stats();
    for (int k = 0; k < kMaxSlices / 2; ++k) {
      const double fine = fineSlice(sim);
      if (!(fine < kNever)) break;  // nothing moves
      if (!(grown < kNever)) grown = fine;
      const double meeting = timeToFirstMeeting(sim);
      double slice = meeting < kNever ? std::max(meeting, std::min(grown, 8.0 * fine)) : grown;
      slice = std::max(slice, kLeastSliceFraction * sim.time());
      if (sim.world().method != Method::Exact) slice = std::min(slice, 4.0 * sim.world().timeStep);
      if (sim.time() + slice > kLatestTime) break;
      const std::uint64_t eventsBefore = sim.stats().events;
      sim.advance(slice);
      if (!finiteState(sim)) __builtin_trap();
      sim.takeCollisions();
      measureOverlaps(sim.bodies(), sim.positions());
      watch.check(sim);
      const RunStats& stats = sim.stats();
      if (stats.events - start.events >= kMaxEvents / 2 ||
          stats.steps - start.steps >= kMaxSteps / 2)
        break;
      const std::uint64_t events = stats.events - eventsBefore;
      if (events < kMaxEvents / 16)
        grown = 4.0 * std::min(grown, slice);
      else if (events > kMaxEvents / 8)
        grown /= 4.0;
    }
    watch.rebase(sim);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider bytes(data, size);
  SceneMaker maker(bytes);
  Scene scene = maker.make();
  World later = maker.world();
  if (bytes.ConsumeBool()) later.timeStep = maker.stepForScene(scene);
  maker.addFriction(scene, later);
  if (!validateScene(scene, 1).empty()) return 0;
  Simulation sim(scene);
  run(sim, later);
  return 0;
}
