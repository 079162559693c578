#pragma once
// Measuring the trade between speed and accuracy: the same scene run under each method,
// integrator and a range of time steps, each run's error set against its computing time. The
// reference is the `exact` method.

#include "sim/scene.h"

#include <atomic>
#include <vector>

namespace carom {

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
  double energyDrift = 0.0;     // |E_end - E_start| / |E_start|
  double positionError = 0.0;   // RMS distance from the exact run's final positions
  double maxPenetration = 0.0;  // deepest overlap seen at contacts or at the end
  int escaped = 0;              // balls behind a plane or inside a cylinder at the end
};

// The time steps the study tries: a quarter of the world's time step to four times it.
inline const std::vector<double> kStudyStepFactors{0.25, 0.5, 1.0, 2.0, 4.0};

// `exact` once, then `swept` and `discrete` with every integrator at the world's time step
// times each of `stepFactors`.
std::vector<StudyCase> studyCases(const World& world, const std::vector<double>& stepFactors);

// Runs `scene` for `duration` under `settings`; `reference` holds the exact run's final positions
// (empty: the position error is left at zero). Returns early, with what it has, once `cancel`
// becomes true.
StudyResult runStudyCase(const Scene& scene, const StudyCase& settings, double duration,
                         const std::vector<Vec3>& reference, const std::atomic<bool>* cancel);

// The final positions of the exact run, for use as `reference`: the same run, advanced the same
// way, as the `exact` case of studyCases, so that case's position error is exactly zero. Returns
// early, with positions short of `duration`, once `cancel` becomes true.
std::vector<Vec3> exactFinalPositions(const Scene& scene, double duration,
                                      const std::atomic<bool>* cancel = nullptr);

// The CPU time the calling thread has used so far, s (what computeSeconds counts).
double threadCpuSeconds();

}  // namespace carom
