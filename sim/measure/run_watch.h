#pragma once
// A watch on a run: after each step it looks for numbers that have gone wrong (a non-finite
// position or velocity, total energy rising where it can only fall, a ball whose centre got
// inside a solid, an overlap deeper than a fraction of a radius) and names the first problem.
// It only reads the simulation: its settings never change the physics.

#include "sim/simulation.h"
#include "sim/validation/validation.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carom {

class StaticBins;

enum class WatchKind { NonFinite, EnergyRise, Escape, Penetration };
inline constexpr int kWatchKindCount = 4;

namespace watch_default {
// Energy may rise by this fraction of the run's energy scale (RunWatch::energyScale) above its
// value at the baseline. The stepping methods' integrators err by about m |g| |v| dt a ball
// within a flight, which a contact gives back: `swept` runs of the bundled scenes at their
// time steps rise up to 1.6 % (the magic room), exact ones by round-off. An explicit Euler run
// whose step is a fair part of its flights gains several times this.
inline constexpr double kEnergyRise = 0.05;
// A ball's centre may be this fraction of its radius past a solid's surface: none. A centre
// inside a solid is never right, and round-off keeps the methods' balls a radius away from it.
inline constexpr double kEscapeDepth = 0.0;
// An overlap may be this fraction of the smaller radius deep: half, where a ball is more in
// the other than out of it. The exact and swept methods keep overlaps at round-off (1e-9 of a
// radius). `discrete` leaves what one step's resolution did not clear: in the bundled scenes
// up to 0.15 (gas box) and 0.36 (marble run) over 60 s, which a tighter default would stop as
// if wrong, and over a whole radius in the Galton board, whose 1 cm balls move several radii a
// step: there the numbers have gone wrong.
inline constexpr double kPenetration = 0.5;
}  // namespace watch_default

// Each check on or off, with its tolerance (a non-finite number has none).
struct WatchSettings {
  bool nonFinite = true;
  bool energyRise = true;
  double energyRiseTolerance = watch_default::kEnergyRise;
  bool escape = true;
  double escapeTolerance = watch_default::kEscapeDepth;
  bool penetration = true;
  double penetrationTolerance = watch_default::kPenetration;
  bool enabled(WatchKind kind) const;
  bool& enabled(WatchKind kind);
  bool anyEnabled() const { return nonFinite || energyRise || escape || penetration; }
  friend bool operator==(const WatchSettings&, const WatchSettings&) = default;
};

// The checks, one row each in WatchKind's order: the key on the command line and in settings,
// the switch that turns the check on and its tolerance's field (a non-finite number has none)
// and path. The watch, the CLI and the window all read them from here.
struct WatchCheck {
  WatchKind kind;
  std::string_view name;
  bool WatchSettings::*on;
  double WatchSettings::*tolerance;
  std::string_view tolerancePath;
};
inline constexpr WatchCheck kWatchChecks[kWatchKindCount] = {
    {WatchKind::NonFinite, "non-finite", &WatchSettings::nonFinite, nullptr, {}},
    {WatchKind::EnergyRise, "energy-rise", &WatchSettings::energyRise,
     &WatchSettings::energyRiseTolerance, "watch.energyRise"},
    {WatchKind::Escape, "escape", &WatchSettings::escape, &WatchSettings::escapeTolerance,
     "watch.escape"},
    {WatchKind::Penetration, "penetration", &WatchSettings::penetration,
     &WatchSettings::penetrationTolerance, "watch.penetration"},
};
inline constexpr const WatchCheck& watchCheck(WatchKind kind) {
  return kWatchChecks[static_cast<int>(kind)];
}
// Keys as on the command line and in settings ("non-finite", "energy-rise", ...).
inline constexpr std::string_view watchKindName(WatchKind kind) {
  return watchCheck(kind).name;
}

// The tolerances' limits: each finite, at least 0 and at most this.
inline constexpr double kMaxWatchTolerance = 1e6;

// What is wrong with `settings`, paths such as "watch.penetration"; empty when they are valid.
std::vector<ValidationError> validateWatchSettings(const WatchSettings& settings);

// The object the event is about besides its ball: another ball or a static shape.
enum class WatchOther { None, Ball, Plane, Cylinder, Box };

struct WatchEvent {
  WatchKind kind = WatchKind::NonFinite;
  int ball = -1;  // scene index of the ball the event names
  WatchOther otherKind = WatchOther::None;
  int other = -1;     // index of the other object, by otherKind
  double time = 0.0;  // the simulation's time when the check fired
  // The time of the last step the watch passed: where a timeline should offer to go back to.
  double lastGoodTime = 0.0;
  double value = 0.0;      // what was measured, in the tolerance's units
  double tolerance = 0.0;  // the tolerance it exceeded
  std::string text;        // one line, English, e.g. "ball 3 is inside box 1 ..."
};

class RunWatch {
 public:
  // `settings` must be valid (validateWatchSettings empty).
  explicit RunWatch(const WatchSettings& settings = {});

  const WatchSettings& settings() const { return settings_; }
  // New settings (valid), from the next check on; the energy baseline is kept.
  void setSettings(const WatchSettings& settings);

  // Takes `sim`'s state as the energy baseline and forgets what was reported: after anything
  // that does work on the balls from outside (new world settings, a grab, an edit), or a new
  // simulation. The first check() of a watch rebases by itself.
  void rebase(const Simulation& sim);

  // Looks at `sim` after a step; energy is compared with the baseline's, not with the lowest
  // seen: the stepping methods' integrators lose energy in flight and give it back at contacts
  // (a bounce restores the flight's energy, docs/physics.md), which is no rise; the worst problem
  // found (non-finite before escape before penetration before energy; the largest excess within a
  // kind), if any. A ball already reported for a kind is not reported for it again while the
  // problem lasts, and an energy rise rebases the energy, so a run resumed after an event goes on
  // until something new.
  std::optional<WatchEvent> check(const Simulation& sim);

  // The energy check applies: every restitution in the scene (world, balls, planes, cylinders,
  // boxes) is at most 1. As of the last rebase.
  bool energyChecked() const { return energyApplies_; }
  // The scale energy rises are measured against, as of the last rebase: the kinetic energy
  // plus the balls' weight, sum of m |g|, times the scene's height extent along gravity (from
  // the top of the highest ball or finite shape to the lowest of the balls' bottoms, the finite
  // shapes and the floors, planes facing within 60 degrees of up): about the energy the balls
  // can trade between motion and height. Independent of where the potential's zero is, and
  // zero only with no motion and no gravity.
  double energyScale() const { return energyScale_; }

 private:
  struct Found;
  void takeEnergyBaseline(const Simulation& sim, const std::vector<BallState>& state);

  WatchSettings settings_;
  bool based_ = false;
  const Bodies* bodies_ = nullptr;          // the bodies the bins were built from
  std::shared_ptr<const StaticBins> bins_;  // the shapes near each point
  bool energyApplies_ = true;
  double energyScale_ = 0.0;
  double baselineEnergy_ = 0.0;
  std::vector<double> ballEnergy_;  // each ball's energy at the last check
  double lastGoodTime_ = 0.0;
  // Per ball, a bit per kind already reported and still going on.
  std::vector<unsigned char> reported_;
};

}  // namespace carom
