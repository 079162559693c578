#pragma once
// Measuring the trade between speed and accuracy: the same scene run under each method,
// integrator and a range of time steps, each run's error set against its computing time. The
// reference is the `exact` method.
//
// Paths part from exact ones at a rate set by the scene's chaos, whatever the method: past the
// time the finest setting still agrees with `exact` (the agreement horizon), position error
// measures only that chaos. So position error is taken at the horizon, and whole runs are judged
// by what survives chaos: energy, penetration, escapes, and the distributions of speeds and
// positions.

#include "sim/model/scene.h"

#include <atomic>
#include <cstddef>
#include <optional>
#include <vector>

namespace carom {

class Simulation;

// Energy error as `auto` and the study's tolerance judge it: relative to the run watch's energy
// scale (the energy the balls can trade between motion and height, whatever the potential's
// zero), per simulated second; any change where every restitution is 1, any gain otherwise (how
// much collisions should lose is not known short of running exact).
struct EnergyYardstick {
  double initial = 0.0;
  double scale = 0.0;
  bool conserved = true;
  static EnergyYardstick of(const Simulation& sim);  // at its start
  double error(double energy) const;  // on the scale; infinite when energy is not finite
  double errorPerSecond(double energy, double time) const;
};

struct StudyCase {
  Method method = Method::Exact;
  Integrator integrator = Integrator::SymplecticEuler;
  double timeStep = 0.0;
};

struct StudyResult {
  StudyCase settings;
  // CPU time the run's thread spent on it (threadCpuSeconds()), not wall time: with runs in
  // parallel, or other programs busy, the wall time would count the waits for a core too.
  double computeSeconds = 0.0;
  double energyDrift = 0.0;           // |E_end - E_start| / |E_start|
  double energyErrorPerSecond = 0.0;  // over the whole run, by EnergyYardstick
  // RMS distance from the exact run's positions at each of the reference's sample times.
  std::vector<double> deviation;
  // The deviation at the agreement horizon; NaN when the scene has none (even the finest
  // setting parts from `exact` before the first sample).
  double positionError = 0.0;
  double maxPenetration = 0.0;       // deepest overlap seen at contacts or at the end
  double penetrationFraction = 0.0;  // maxPenetration over the smallest radius
  int escaped = 0;                   // balls behind a plane or inside a cylinder at the end
  // Kolmogorov-Smirnov distances (0 to 1) of the final speeds, and of the final coordinates
  // (the largest of the three axes), from the exact run's.
  double speedDistribution = 0.0;
  double positionDistribution = 0.0;
};

// The exact run's states that every case is set against.
struct StudyReference {
  std::vector<double> sampleTimes;           // increasing, the last one the duration
  std::vector<std::vector<Vec3>> positions;  // at each sample time
  std::vector<Vec3> finalVelocities;
  // The last sample up to which the finest case stays within kAgreementRadiusFraction of the
  // mean radius of `exact`; none when it parts before the first.
  std::optional<std::size_t> horizonSample;
  std::optional<double> horizon() const {
    if (!horizonSample) return std::nullopt;
    return sampleTimes[*horizonSample];
  }
};

// The time steps the study tries: a quarter of the world's time step to four times it.
inline const std::vector<double> kStudyStepFactors{0.25, 0.5, 1.0, 2.0, 4.0};
// Sample times per run, spread evenly on a log scale from kFirstSampleFraction of the duration
// to the duration, fewer when the reference's positions would take more than the budget.
constexpr std::size_t kStudySamples = 40;
constexpr double kFirstSampleFraction = 1e-4;
constexpr std::size_t kStudySampleBudgetBytes = std::size_t(256) << 20;
// Two runs agree while they are this fraction of the mean radius apart (RMS).
constexpr double kAgreementRadiusFraction = 0.1;

// `exact` once, then `swept` and `discrete` with every integrator at the world's time step
// times each of `stepFactors`.
std::vector<StudyCase> studyCases(const World& world, const std::vector<double>& stepFactors);
// The case whose paths are closest to exact ones: `swept` with velocity Verlet at the smallest
// step among `cases`; none when there is no swept case.
std::optional<std::size_t> finestCase(const std::vector<StudyCase>& cases);

std::vector<double> studySampleTimes(double duration, std::size_t ballCount);

// Runs the exact method for `duration`, keeping its positions at studySampleTimes (no horizon
// yet). Returns early, short of `duration`, once `cancel` becomes true.
StudyReference exactReference(const Scene& scene, double duration,
                              const std::atomic<bool>* cancel = nullptr);

// Runs `scene` for `duration` under `settings`, measured against `reference`. Runs that reach
// the same times the same way as the reference's (the `exact` case) follow it bit for bit, so
// that case's errors are exactly zero. Returns early, with what it has, once `cancel` becomes
// true.
StudyResult runStudyCase(const Scene& scene, const StudyCase& settings, double duration,
                         const StudyReference& reference, const std::atomic<bool>* cancel);

// Sets reference.horizonSample from the finest case's deviations.
void setAgreementHorizon(StudyReference& reference, const StudyResult& finest, double meanRadius);
// `result`'s deviation at the reference's horizon, NaN when there is none.
double positionErrorAtHorizon(const StudyResult& result, const StudyReference& reference);

// The RMS distance within which a run agrees with `exact`, as setAgreementHorizon takes it:
// kAgreementRadiusFraction of the scene's mean ball radius (0 without balls).
double agreementRadius(const Scene& scene);

// What the study plots of each run.
enum class StudyMeasure {
  PositionError,  // at the horizon, m
  EnergyDrift,    // relative
  Penetration,    // deepest, m
  Escaped,        // balls
  SpeedDistribution,
  PositionDistribution,
  EnergyErrorPerSecond,  // auto's measure
};
inline constexpr int kStudyMeasures = 7;
// NaN when the run has none (position error without a horizon).
double measureOf(const StudyResult& result, StudyMeasure measure);

// The Kolmogorov-Smirnov distance below which two samples of `count` values each cannot be told
// apart at 5 % significance (above 1 for fewer than 4: then any can).
double indistinguishableDistance(std::size_t count);

// The accuracy asked of the runs, as auto asks it (AccuracyTolerance, method_choice.h).
struct StudyTolerance {
  double energyPerSecond = 1e-3;
  double penetrationFraction = 0.05;
};
// The largest value of `measure` within the tolerance for a run of `scene` over `duration`:
// auto's own bounds for its measures (energy error per second, penetration as a depth, no
// escape), the agreement radius for position error, auto's energy bound over the duration for
// the drift, and indistinguishableDistance for the distributions.
double toleranceOf(StudyMeasure measure, const StudyTolerance& tolerance, const Scene& scene,
                   double duration);
// The run with the least computing time whose `measure` is at most `bound`.
std::optional<std::size_t> cheapestWithin(const std::vector<StudyResult>& results,
                                          StudyMeasure measure, double bound);

// The CPU time the calling thread has used so far, s (what computeSeconds counts).
double threadCpuSeconds();

}  // namespace carom
