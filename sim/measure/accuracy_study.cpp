#include "sim/measure/accuracy_study.h"

#include "sim/measure/measures.h"
#include "sim/measure/run_watch.h"
#include "sim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

namespace carom {
namespace {

// Runs `sim` through the sample times in slices, so that a cancel is noticed soon, calling
// `atSample(k)` at each. Every run of the study, the reference included, goes through here: the
// same slice ends give the exact method the same landing times, hence bit for bit the same paths.
template <typename F>
void advanceThrough(Simulation& sim, const std::vector<double>& sampleTimes,
                    const std::atomic<bool>* cancel, F&& atSample) {
  if (sampleTimes.empty()) return;
  const double slice = std::max(sim.world().timeStep, sampleTimes.back() / 50.0);
  for (std::size_t k = 0; k < sampleTimes.size(); ++k) {
    // Slice ends are multiples of `slice` from 0, never sums, so they fall the same in every run.
    double sliceEnd = slice * std::floor(sim.time() / slice);
    while (sim.time() < sampleTimes[k]) {
      if (cancel && cancel->load()) return;
      sliceEnd += slice;
      sim.advanceTo(std::min(sliceEnd, sampleTimes[k]));
    }
    atSample(k);
  }
}

double rmsDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size() || a.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

std::vector<double> speeds(const std::vector<Vec3>& velocities) {
  std::vector<double> result(velocities.size());
  for (std::size_t i = 0; i < velocities.size(); ++i) result[i] = velocities[i].norm();
  return result;
}

double coordinateDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> x(a.size()), y(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) x[i] = a[i][axis];
    for (std::size_t i = 0; i < b.size(); ++i) y[i] = b[i][axis];
    largest = std::max(largest, distributionDistance(std::move(x), std::move(y)));
  }
  return largest;
}

Scene withSettings(const Scene& scene, const StudyCase& settings) {
  Scene run = scene;
  run.world.method = settings.method;
  run.world.integrator = settings.integrator;
  run.world.timeStep = settings.timeStep;
  return run;
}

}  // namespace

EnergyYardstick EnergyYardstick::of(const Simulation& sim) {
  EnergyYardstick yardstick;
  yardstick.initial = sim.totalEnergy();
  RunWatch watch;
  watch.rebase(sim);
  yardstick.scale = std::max(watch.energyScale(), std::numeric_limits<double>::min());
  const Bodies& bodies = sim.bodies();
  for (const std::vector<double>* values : {&bodies.planeRestitution, &bodies.cylinderRestitution,
                                            &bodies.boxRestitution, &bodies.restitution})
    for (double e : *values) yardstick.conserved = yardstick.conserved && e == 1.0;
  return yardstick;
}

double EnergyYardstick::error(double energy) const {
  if (!std::isfinite(energy)) return std::numeric_limits<double>::infinity();
  return (conserved ? std::abs(energy - initial) : std::max(0.0, energy - initial)) / scale;
}

double EnergyYardstick::errorPerSecond(double energy, double time) const {
  return time > 0.0 || !std::isfinite(energy) ? error(energy) / time : 0.0;
}

double threadCpuSeconds() {
  // POSIX, here only; elsewhere wall time is the best there is.
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec now{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) == 0)
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
#endif
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<StudyCase> studyCases(const World& world, const std::vector<double>& stepFactors) {
  std::vector<StudyCase> cases{{Method::Exact, world.integrator, world.timeStep}};
  for (Method method : {Method::Swept, Method::Discrete})
    for (Integrator integrator :
         {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::VelocityVerlet})
      for (double factor : stepFactors)
        cases.push_back({method, integrator, world.timeStep * factor});
  return cases;
}

std::optional<std::size_t> finestCase(const std::vector<StudyCase>& cases) {
  std::optional<std::size_t> finest;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const StudyCase& c = cases[i];
    if (c.method != Method::Swept || c.integrator != Integrator::VelocityVerlet) continue;
    if (!finest || c.timeStep < cases[*finest].timeStep) finest = i;
  }
  return finest;
}

std::vector<double> studySampleTimes(double duration, std::size_t ballCount) {
  const std::size_t bytesPerSample = std::max<std::size_t>(1, ballCount) * sizeof(Vec3);
  const std::size_t count =
      std::clamp<std::size_t>(kStudySampleBudgetBytes / bytesPerSample, 1, kStudySamples);
  if (count == 1 || !(duration > 0.0)) return {duration};
  std::vector<double> times(count);
  const double first = duration * kFirstSampleFraction;
  for (std::size_t k = 0; k < count; ++k)
    times[k] = first * std::pow(duration / first, static_cast<double>(k) / double(count - 1));
  times.back() = duration;  // exactly, not by rounding of the power
  return times;
}

StudyReference exactReference(const Scene& scene, double duration,
                              const std::atomic<bool>* cancel) {
  StudyReference reference;
  reference.sampleTimes = studySampleTimes(duration, scene.balls.size());
  Simulation sim(
      withSettings(scene, {Method::Exact, scene.world.integrator, scene.world.timeStep}));
  advanceThrough(sim, reference.sampleTimes, cancel,
                 [&](std::size_t) { reference.positions.push_back(sim.positions()); });
  reference.finalVelocities = sim.velocities();
  return reference;
}

StudyResult runStudyCase(const Scene& scene, const StudyCase& settings, double duration,
                         const StudyReference& reference, const std::atomic<bool>* cancel) {
  StudyResult result;
  result.settings = settings;
  // This thread's CPU time, no longer wall time, since runs share the cores (see StudyResult).
  const double start = threadCpuSeconds();
  Simulation sim(withSettings(scene, settings));
  const double initial = sim.totalEnergy();
  const EnergyYardstick yardstick = EnergyYardstick::of(sim);
  const bool sampled = !reference.sampleTimes.empty() && reference.sampleTimes.back() == duration;
  const std::vector<double> times = sampled ? reference.sampleTimes : std::vector<double>{duration};
  advanceThrough(sim, times, cancel, [&](std::size_t k) {
    if (sampled && k < reference.positions.size())
      result.deviation.push_back(rmsDistance(sim.positions(), reference.positions[k]));
  });
  result.computeSeconds = threadCpuSeconds() - start;
  result.energyDrift = std::abs(sim.totalEnergy() - initial) / std::max(std::abs(initial), 1e-300);
  const std::vector<Vec3> positions = sim.positions();
  const OverlapReport overlaps = measureOverlaps(sim.bodies(), positions);
  result.maxPenetration = std::max(overlaps.maxPenetration, sim.stats().maxPenetration);
  result.escaped = overlaps.escaped;
  result.energyErrorPerSecond = yardstick.errorPerSecond(sim.totalEnergy(), sim.time());
  double smallestRadius = std::numeric_limits<double>::infinity();
  for (const Ball& ball : scene.balls) smallestRadius = std::min(smallestRadius, ball.radius);
  result.penetrationFraction = result.maxPenetration / smallestRadius;
  result.positionError = positionErrorAtHorizon(result, reference);
  if (!reference.positions.empty() && reference.positions.size() == reference.sampleTimes.size()) {
    result.speedDistribution =
        distributionDistance(speeds(sim.velocities()), speeds(reference.finalVelocities));
    result.positionDistribution = coordinateDistance(positions, reference.positions.back());
  }
  return result;
}

void setAgreementHorizon(StudyReference& reference, const StudyResult& finest, double meanRadius) {
  reference.horizonSample.reset();
  const double radius = kAgreementRadiusFraction * meanRadius;
  for (std::size_t k = 0; k < finest.deviation.size(); ++k) {
    if (!(finest.deviation[k] <= radius)) break;
    reference.horizonSample = k;
  }
}

double positionErrorAtHorizon(const StudyResult& result, const StudyReference& reference) {
  if (!reference.horizonSample || *reference.horizonSample >= result.deviation.size())
    return std::numeric_limits<double>::quiet_NaN();
  return result.deviation[*reference.horizonSample];
}

double agreementRadius(const Scene& scene) {
  if (scene.balls.empty()) return 0.0;
  double radii = 0.0;
  for (const Ball& ball : scene.balls) radii += ball.radius;
  return kAgreementRadiusFraction * radii / static_cast<double>(scene.balls.size());
}

double measureOf(const StudyResult& result, StudyMeasure measure) {
  switch (measure) {
    case StudyMeasure::PositionError:
      return result.positionError;
    case StudyMeasure::EnergyDrift:
      return result.energyDrift;
    case StudyMeasure::Penetration:
      return result.maxPenetration;
    case StudyMeasure::Escaped:
      return result.escaped;
    case StudyMeasure::SpeedDistribution:
      return result.speedDistribution;
    case StudyMeasure::PositionDistribution:
      return result.positionDistribution;
    case StudyMeasure::EnergyErrorPerSecond:
      return result.energyErrorPerSecond;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double indistinguishableDistance(std::size_t count) {
  // The two-sample test's critical distance c(alpha) sqrt(2 / n), c = 1.358 at alpha = 0.05.
  constexpr double kCritical = 1.358;
  if (count == 0) return std::numeric_limits<double>::infinity();
  return kCritical * std::sqrt(2.0 / static_cast<double>(count));
}

double toleranceOf(StudyMeasure measure, const StudyTolerance& tolerance, const Scene& scene,
                   double duration) {
  switch (measure) {
    case StudyMeasure::PositionError:
      return agreementRadius(scene);
    case StudyMeasure::EnergyDrift:
      return tolerance.energyPerSecond * duration;
    case StudyMeasure::Penetration: {
      double smallest = std::numeric_limits<double>::infinity();
      for (const Ball& ball : scene.balls) smallest = std::min(smallest, ball.radius);
      return scene.balls.empty() ? 0.0 : tolerance.penetrationFraction * smallest;
    }
    case StudyMeasure::Escaped:
      return 0.0;
    case StudyMeasure::SpeedDistribution:
    case StudyMeasure::PositionDistribution:
      return indistinguishableDistance(scene.balls.size());
    case StudyMeasure::EnergyErrorPerSecond:
      return tolerance.energyPerSecond;
  }
  return 0.0;
}

std::optional<std::size_t> cheapestWithin(const std::vector<StudyResult>& results,
                                          StudyMeasure measure, double bound) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (!(measureOf(results[i], measure) <= bound)) continue;  // NaN is not within
    if (!best || results[i].computeSeconds < results[*best].computeSeconds) best = i;
  }
  return best;
}

}  // namespace carom
