#include "sim/accuracy_study.h"

#include "sim/measures.h"
#include "sim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace carom {
namespace {

// Runs `sim` to `duration` in slices, so that a cancel is noticed soon. Every run of the study,
// the reference included, goes through here: the same slices give the exact method the same
// landing times, hence bit for bit the same paths.
void advanceTo(Simulation& sim, double duration, const std::atomic<bool>* cancel) {
  const double slice = std::max(sim.world().timeStep, duration / 50.0);
  while (sim.time() < duration && !(cancel && cancel->load())) {
    sim.advance(std::min(slice, duration - sim.time()));
  }
}

}  // namespace

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

StudyResult runStudyCase(const Scene& scene, const StudyCase& settings, double duration,
                         const std::vector<Vec3>& reference, const std::atomic<bool>* cancel) {
  Scene run = scene;
  run.world.method = settings.method;
  run.world.integrator = settings.integrator;
  run.world.timeStep = settings.timeStep;
  StudyResult result{settings};
  // This thread's CPU time, no longer wall time, since runs share the cores (see StudyResult).
  const double start = threadCpuSeconds();
  Simulation sim(run);
  const double initial = sim.totalEnergy();
  advanceTo(sim, duration, cancel);
  result.computeSeconds = threadCpuSeconds() - start;
  result.energyDrift = std::abs(sim.totalEnergy() - initial) / std::max(std::abs(initial), 1e-300);
  const std::vector<Vec3> positions = sim.positions();
  const OverlapReport overlaps = measureOverlaps(sim.bodies(), positions);
  result.maxPenetration = std::max(overlaps.maxPenetration, sim.stats().maxPenetration);
  result.escaped = overlaps.escaped;
  if (reference.size() == positions.size() && !positions.empty()) {
    double sum = 0.0;
    for (std::size_t i = 0; i < positions.size(); ++i)
      sum += (positions[i] - reference[i]).squaredNorm();
    result.positionError = std::sqrt(sum / positions.size());
  }
  return result;
}

std::vector<Vec3> exactFinalPositions(const Scene& scene, double duration,
                                      const std::atomic<bool>* cancel) {
  Scene run = scene;
  run.world.method = Method::Exact;
  Simulation sim(run);
  advanceTo(sim, duration, cancel);
  return sim.positions();
}

}  // namespace carom
