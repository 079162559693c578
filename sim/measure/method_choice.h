#pragma once
// Choosing the method for the accuracy asked for ("auto"): a short pilot of the scene under
// candidate methods, integrators and steps, each measured against the tolerance, then the
// cheapest that meets it. The pilot is kept to kPilotShare of the run's expected computing time.

#include "sim/measure/accuracy_study.h"
#include "sim/model/scene.h"
#include "sim/validation/validation.h"

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace carom {

// The pilot's computing time is at most this share of the run's expected time, or
// kPilotFloorSeconds if that is longer: a run of a few milliseconds leaves its pilot no time to
// see a single collision, and a pilot of 50 ms is not a wait anyone notices.
constexpr double kPilotShare = 0.05;
constexpr double kPilotFloorSeconds = 0.05;
// The first round of the pilot covers this fraction of the run's simulated time, or
// kPilotFirstSteps of the world's time step if that is longer (a measure of less than a
// few steps says nothing), but never more than the run; each round doubles it.
constexpr double kPilotFirstFraction = 1e-4;
constexpr double kPilotFirstSteps = 8.0;
// Each candidate's part of a round runs in slices, the budget checked between them: the first
// this fraction of the world's step (of the round, if shorter), each next one twice as long
// while they take under kPilotSliceSeconds.
constexpr int kPilotSlices = 8;
constexpr double kPilotSliceSeconds = 1e-3;
// A candidate waits out later rounds when it costs this many times the best one that meets the
// tolerance: nearer than that, the early rounds' costs (mostly fixed costs of short slices) do
// not tell them apart.
constexpr double kPilotPauseFactor = 2.0;
// The steps of the stepping candidates, as multiples of the world's.
inline constexpr double kAutoStepFactors[] = {0.25, 1.0, 4.0};

struct PilotMeasure {
  StudyCase settings;
  double simulated = 0.0;       // simulated time the pilot took it to, s
  double measuredAt = 0.0;      // simulated time of the measures below; 0: never measured
  double setupSeconds = 0.0;    // CPU time of building its simulation
  double computeSeconds = 0.0;  // CPU time it took, set-up included
  // CPU seconds per simulated second, set-up excluded: over the last round once there were two.
  double costPerSecond = 0.0;
  double energyErrorPerSecond = 0.0;
  double penetrationFraction = 0.0;
  // The finest error and penetration the measures can show, a rounding of the energies and the
  // positions they compare: a pilot that saw nothing (no collision yet, or round-off cancelling
  // in the energy's sum) has shown the run no better than this.
  double energyResolutionPerSecond = 0.0;
  double penetrationResolution = 0.0;
  int escaped = 0;
  bool finite = true;
  bool meets = false;
  // Left out of later rounds: it fails a tolerance that cannot recover (penetration, escapes,
  // non-finite state).
  bool dropped = false;
  // Left out of later rounds as dearer than a candidate that met the tolerance, or stopped short
  // by the pilot's budget; its measures are those of the last round it finished.
  bool paused = false;
  std::string verdict;  // why it meets or not, in a few words, English
};

struct MethodChoice {
  std::vector<PilotMeasure> candidates;  // exact first
  std::optional<std::size_t> chosen;     // the cheapest that meets the tolerance
  std::size_t closest = 0;               // when none meets: the one whose worst excess is smallest
  double pilotSeconds = 0.0;             // CPU time of the whole pilot
  double pilotSimulated = 0.0;           // simulated time of its last round
  bool cancelled = false;
  double duration = 0.0;  // of the run the pilot was for, simulated s
  // Computing time of the chosen candidate (or the closest) for the duration, set-up included.
  double expectedRunSeconds() const;
  const PilotMeasure& pick() const { return candidates[chosen.value_or(closest)]; }
  std::string reason;  // one line, English
};

// `exact`, then `swept` and `discrete` under symplectic Euler and velocity Verlet at a quarter,
// one and four times the world's step, those within the limits of validation (explicit Euler
// costs the same as symplectic Euler and is never more accurate).
std::vector<StudyCase> autoCandidates(const World& world);

// Pilots `scene` (valid) for a run of `duration` simulated seconds and chooses.
MethodChoice chooseMethod(const Scene& scene, double duration, const AccuracyTolerance& tolerance,
                          const std::atomic<bool>* cancel = nullptr);

}  // namespace carom
