#include "sim/accuracy_study.h"

#include "sim/measures.h"
#include "sim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace carom {

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
  const auto start = std::chrono::steady_clock::now();
  Simulation sim(run);
  const double initial = sim.totalEnergy();
  // In slices, so that a cancel is noticed soon.
  const double slice = std::max(settings.timeStep, duration / 50.0);
  while (sim.time() < duration && !(cancel && cancel->load())) {
    sim.advance(std::min(slice, duration - sim.time()));
  }
  result.computeSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

std::vector<Vec3> exactFinalPositions(const Scene& scene, double duration) {
  Scene run = scene;
  run.world.method = Method::Exact;
  Simulation sim(run);
  sim.advance(duration);
  return sim.positions();
}

}  // namespace carom
