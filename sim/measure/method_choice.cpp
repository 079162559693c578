#include "sim/measure/method_choice.h"

#include "sim/measure/measures.h"
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <memory>

namespace carom {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// How far past the tolerance a candidate is, as the larger ratio of measure (with what it cannot
// resolve) to tolerance; infinite when it lost balls or its state.
double worstExcess(const PilotMeasure& m, const AccuracyTolerance& tolerance) {
  if (m.measuredAt == 0.0 || !m.finite || m.escaped > 0)
    return std::numeric_limits<double>::infinity();
  return std::max(
      (m.energyErrorPerSecond + m.energyResolutionPerSecond) / tolerance.energyPerSecond,
      (m.penetrationFraction + m.penetrationResolution) / tolerance.penetrationFraction);
}

struct Pilot {
  Simulation sim;
  PilotMeasure measure;
  double lastTime = 0.0;
  // The largest energy error at any slice's end, on the yardstick's scale. The error at one
  // moment can be nought by chance (an integrator whose energy oscillates crossing its start, or
  // round-off cancelling); the worst over the pilot is what the run may show.
  double worstEnergyError = 0.0;
};

}  // namespace

double MethodChoice::expectedRunSeconds() const {
  return candidates.empty() ? 0.0 : pick().setupSeconds + pick().costPerSecond * duration;
}

std::vector<StudyCase> autoCandidates(const World& world) {
  std::vector<StudyCase> cases{{Method::Exact, world.integrator, world.timeStep}};
  for (Method method : {Method::Swept, Method::Discrete})
    for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::VelocityVerlet})
      for (double factor : kAutoStepFactors) {
        // Steps outside the limits of scene validation are no candidates.
        World candidate = world;
        candidate.method = method;
        candidate.integrator = integrator;
        candidate.timeStep = world.timeStep * factor;
        if (validateWorld(candidate, 1).empty())
          cases.push_back({method, integrator, candidate.timeStep});
      }
  return cases;
}

MethodChoice chooseMethod(const Scene& scene, double duration, const AccuracyTolerance& tolerance,
                          const std::atomic<bool>* cancel) {
  MethodChoice choice;
  choice.duration = duration;
  const std::vector<StudyCase> cases = autoCandidates(scene.world);
  double smallestRadius = std::numeric_limits<double>::infinity();
  for (const Ball& ball : scene.balls) smallestRadius = std::min(smallestRadius, ball.radius);

  std::vector<std::unique_ptr<Pilot>> pilots;
  for (const StudyCase& settings : cases) {
    Scene run = scene;
    run.world.method = settings.method;
    run.world.integrator = settings.integrator;
    run.world.timeStep = settings.timeStep;
    const double start = threadCpuSeconds();
    auto pilot = std::make_unique<Pilot>(Pilot{Simulation(run), PilotMeasure()});
    pilot->measure.settings = settings;
    pilot->measure.setupSeconds = pilot->measure.computeSeconds = threadCpuSeconds() - start;
    pilots.push_back(std::move(pilot));
  }
  const EnergyYardstick yardstick = EnergyYardstick::of(pilots.front()->sim);

  // Round ends fall on whole steps of every candidate (multiples of the coarsest step), so that
  // each takes whole steps only, as in its run.
  const double coarsest =
      *std::max_element(std::begin(kAutoStepFactors), std::end(kAutoStepFactors)) *
      scene.world.timeStep;
  const auto wholeSteps = [&](double time) {
    return std::min(duration, coarsest * std::max(1.0, std::floor(time / coarsest)));
  };
  double t =
      wholeSteps(std::max(duration * kPilotFirstFraction, kPilotFirstSteps * scene.world.timeStep));
  // No budget for the first round: nothing is known yet of what the run will cost.
  double budget = std::numeric_limits<double>::infinity();
  double spentBefore = 0.0;  // by the rounds before this one, set-up included
  for (const auto& pilot : pilots) spentBefore += pilot->measure.computeSeconds;
  for (int round = 0; duration > 0.0; ++round) {
    double spentNow = spentBefore;
    // The cheapest first: a candidate that met the tolerance and turns out cheaper still
    // lowers the budget before the dear ones spend it.
    std::vector<Pilot*> order;
    for (auto& pilot : pilots) order.push_back(pilot.get());
    // In the first round, with no costs known, `exact` goes last: the stepping methods' cost is
    // bounded by their steps, exact's by nothing (a crowd collapsing into a pile).
    std::stable_sort(order.begin(), order.end(), [round](const Pilot* a, const Pilot* b) {
      if (round == 0)
        return a->measure.settings.method != Method::Exact &&
               b->measure.settings.method == Method::Exact;
      return a->measure.costPerSecond < b->measure.costPerSecond;
    });
    for (Pilot* pilot : order) {
      PilotMeasure& m = pilot->measure;
      if (m.dropped || m.paused) continue;
      // In slices (kPilotSlices), so that a candidate whose cost climbs (a crowd
      // settling into a pile, whose collisions multiply) cannot take the pilot far past its
      // budget. A stepping candidate's slices end on its own steps, which it takes whole.
      const double from = pilot->sim.time();
      double slice = std::min(t - from, scene.world.timeStep) / kPilotSlices;
      const double step = m.settings.method == Method::Exact ? 0.0 : m.settings.timeStep;
      double spent = 0.0;
      for (double sliceEnd = from; pilot->sim.time() < t;) {
        if ((cancel && cancel->load()) || spentNow + spent > budget) break;
        sliceEnd += slice;
        const double target = step > 0.0 ? step * std::ceil(sliceEnd / step) : sliceEnd;
        const double start = threadCpuSeconds();
        pilot->sim.advanceTo(std::min(target, t));
        const double sliceSeconds = threadCpuSeconds() - start;
        pilot->worstEnergyError =
            std::max(pilot->worstEnergyError, yardstick.error(pilot->sim.totalEnergy()));
        spent += sliceSeconds;
        // Cheap slices grow, so that the calls and the clock cost nothing against the run.
        if (sliceSeconds < kPilotSliceSeconds) slice *= 2.0;
      }
      spentNow += spent;
      m.computeSeconds += spent;
      if (cancel && cancel->load()) {
        choice.cancelled = true;
        break;
      }
      const double reached = pilot->sim.time();
      if (reached < t) {
        // Stopped short: its measures stay those of the last round, its cost is at least this.
        if (reached > from) m.costPerSecond = std::max(m.costPerSecond, spent / (reached - from));
        continue;
      }
      m.simulated = reached;
      m.costPerSecond = spent / (m.simulated - pilot->lastTime);  // a catch-up's too
      pilot->lastTime = m.simulated;
      // A candidate that met the tolerance last round, or any in the first (the run may be as
      // cheap as the cheapest), bounds the budget by its run.
      if (m.meets || round == 0)
        budget =
            std::min(budget, std::max(kPilotShare * (m.setupSeconds + m.costPerSecond * duration),
                                      kPilotFloorSeconds));
    }
    if (choice.cancelled) break;
    choice.pilotSimulated = t;
    for (auto& pilot : pilots) {
      PilotMeasure& m = pilot->measure;
      if (m.dropped || m.simulated != t) continue;  // measured in an earlier round
      m.measuredAt = t;
      const std::vector<Vec3> positions = pilot->sim.positions();
      const double energy = pilot->sim.totalEnergy();
      m.finite = std::isfinite(energy);
      for (const Vec3& p : positions) m.finite = m.finite && p.allFinite();
      const OverlapReport overlaps = measureOverlaps(pilot->sim.bodies(), positions);
      m.escaped = overlaps.escaped;
      m.penetrationFraction =
          std::max(overlaps.maxPenetration, pilot->sim.stats().maxPenetration) / smallestRadius;
      m.energyErrorPerSecond =
          m.finite ? pilot->worstEnergyError / t : std::numeric_limits<double>::infinity();
      // One rounding of the energies compared, and of the largest coordinate.
      constexpr double roundOff = std::numeric_limits<double>::epsilon();
      m.energyResolutionPerSecond =
          roundOff * (std::abs(yardstick.initial) + std::abs(energy)) / yardstick.scale / t;
      double farthest = 0.0;
      for (const Vec3& p : positions) farthest = std::max(farthest, p.cwiseAbs().maxCoeff());
      m.penetrationResolution = roundOff * farthest / smallestRadius;
      m.meets = m.finite && m.escaped == 0 && worstExcess(m, tolerance) <= 1.0;
    }
    // Penetration and escapes only grow, and a lost state stays lost: such candidates are out.
    // Any clearly dearer (kPilotPauseFactor) than the best that meets the tolerance (as last
    // measured, this round or before) waits; it goes on, catching up, once it is the cheaper
    // again (costs change as a scene settles).
    const PilotMeasure* best = nullptr;
    for (auto& pilot : pilots) {
      PilotMeasure& m = pilot->measure;
      if (m.dropped) continue;
      if (!m.finite || m.escaped > 0 || m.penetrationFraction > tolerance.penetrationFraction)
        m.dropped = true;
      else if (m.meets && (!best || m.costPerSecond < best->costPerSecond))
        best = &m;
    }
    for (auto& pilot : pilots) {
      PilotMeasure& m = pilot->measure;
      m.paused = !m.dropped && best && &m != best &&
                 m.costPerSecond > kPilotPauseFactor * best->costPerSecond;
    }
    // The next round may take the pilot up to its share of the run the best candidate so far
    // would take, and up to that share of the run's simulated time.
    const double lastRound = std::max(t, wholeSteps(kPilotShare * duration));
    const double next = std::min(wholeSteps(2.0 * t), lastRound);
    double cheapest = std::numeric_limits<double>::infinity();
    for (const auto& pilot : pilots) {
      const PilotMeasure& m = pilot->measure;
      if (!m.dropped) cheapest = std::min(cheapest, m.setupSeconds + m.costPerSecond * duration);
    }
    spentBefore = spentNow;
    choice.pilotSeconds = spentNow;
    const double expected = best ? best->setupSeconds + best->costPerSecond * duration : cheapest;
    budget = std::max(kPilotShare * expected, kPilotFloorSeconds);
    if (t >= lastRound || spentNow >= budget) break;
    t = next;
  }

  for (const auto& pilot : pilots) choice.candidates.push_back(pilot->measure);
  double closestExcess = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < choice.candidates.size(); ++i) {
    const PilotMeasure& m = choice.candidates[i];
    if (m.meets &&
        (!choice.chosen || m.costPerSecond < choice.candidates[*choice.chosen].costPerSecond))
      choice.chosen = i;
    const double excess = worstExcess(m, tolerance);
    if (excess < closestExcess) {
      closestExcess = excess;
      choice.closest = i;
    }
  }
  for (PilotMeasure& m : choice.candidates) {
    if (m.measuredAt == 0.0)
      m.verdict = "not measured: the pilot's budget ran out first (computing " +
                  number(m.costPerSecond) + " s per simulated second or more)";
    else if (!m.finite)
      m.verdict = "state became non-finite";
    else if (m.escaped > 0)
      m.verdict = std::to_string(m.escaped) + " balls escaped";
    else if (m.penetrationFraction > tolerance.penetrationFraction)
      m.verdict = "penetration " + number(m.penetrationFraction) + " of the radius > " +
                  number(tolerance.penetrationFraction);
    else if (m.energyErrorPerSecond > tolerance.energyPerSecond)
      m.verdict = "energy error " + number(m.energyErrorPerSecond) + "/s > " +
                  number(tolerance.energyPerSecond);
    else if (!m.meets)
      m.verdict = "the tolerance is finer than round-off lets the pilot show (energy to " +
                  number(m.energyResolutionPerSecond) + "/s, penetration to " +
                  number(m.penetrationResolution) + " of the radius)";
    else
      m.verdict = "meets the tolerance but costs more";
  }
  if (choice.chosen) {
    PilotMeasure& chosen = choice.candidates[*choice.chosen];
    chosen.verdict = "meets the tolerance, cheapest";
    choice.reason = "the cheapest of the settings that meet the tolerance, at " +
                    number(chosen.costPerSecond) + " s of computing per simulated second";
    if (choice.pilotSeconds > kPilotShare * choice.expectedRunSeconds())
      choice.reason += "; the run is too short for a pilot of " + number(100.0 * kPilotShare) +
                       "% of it (a pilot may take " + number(1000.0 * kPilotFloorSeconds) +
                       " ms, and its first round is " + number(kPilotFirstSteps) +
                       " time steps whatever that costs)";
  } else if (!choice.candidates.empty()) {
    choice.reason = "no setting meets the tolerance; the closest is " + number(closestExcess) +
                    " times over it";
  }
  return choice;
}

}  // namespace carom
