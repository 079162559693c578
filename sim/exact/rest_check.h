#pragma once
// Rule 3 of rest_policy.h (docs/physics.md, "Resting contact"): whether a slow ball of the event
// engine can rest, and where it settles. A question asked of the balls as they are now; the
// engine acts on the answer (engine_resting.cpp): it puts the ball to rest, or wakes the resting
// balls that cannot carry it.

#include "sim/exact/event_engine.h"

#include <optional>
#include <vector>

namespace carom {

class RestCheck {
 public:
  // Whether ball i can rest (its contacts hold it with the balls it touches fixed, and so do its
  // cluster's with the slow ones free, and it can settle) and where: `settle` is the move, at
  // most kSupportGapFraction of the radius, after which what it touches to round-off holds it.
  struct Result {
    bool holds = false;
    Vec3 settle = Vec3::Zero();
    std::vector<int> loosened;  // resting balls that cannot carry it: they must move
  };

  explicit RestCheck(const EventEngine& engine)
      : engine_(engine),
        bodies_(engine.bodies_),
        tracks_(engine.tracks_),
        particles_(engine.particles_),
        cells_(engine.cells_),
        restSpeed_(engine.restSpeed_),
        gravity_(engine.gravity_),
        now_(engine.now_) {}

  Result of(int i) const;

 private:
  // Not resting, and slower than a ball that may settle.
  bool slow(int k) const;
  struct Support {
    StaticRef shape{};  // when ball is -1
    int ball = -1;      // or -1
  };
  struct SupportGap {
    Vec3 normal;
    double gap;
  };
  SupportGap supportGap(int i, const Support& support, const Vec3& centre) const;
  // The μ of ball i's contact with a support (0 in a scene without friction).
  double frictionWith(int i, const Support& support) const;
  // What ball i touches within kSupportGapFraction of its radius: its possible supports
  // (statics, resting balls, balls slower than its rest speed) with their normals, and the
  // faster balls, which it must not settle into.
  struct NearContacts {
    std::vector<Support> supports;
    std::vector<Vec3> normals;
    std::vector<Support> moving;
  };
  NearContacts nearContacts(int i, const Vec3& centre) const;
  std::optional<Vec3> closingMove(int i, const Vec3& centre,
                                  const std::vector<Support>& carrying) const;
  Vec3 closingStep(int i, const Vec3& at, const std::vector<Support>& supports,
                   double* residual) const;
  std::optional<Vec3> settlingMove(int i, const Vec3& centre, const NearContacts& near, Vec3 move,
                                   std::vector<Support> carrying) const;
  // Ball i at `centre` overlaps nothing, and what it touches to round-off holds it.
  bool heldAt(int i, const Vec3& centre, const NearContacts& near) const;
  std::optional<Vec3> lowestPocket(int i, const Vec3& centre, const NearContacts& near) const;
  bool clearAt(int i, const Vec3& centre) const;
  std::optional<Vec3> holdsWhereItIs(int i, const Vec3& centre, const NearContacts& near,
                                     std::vector<Support>* carrying) const;
  bool clusterHolds(int i, int freed = -1) const;

  // What it reads of the engine.
  const EventEngine& engine_;
  const Bodies& bodies_;
  const std::vector<EventEngine::Track>& tracks_;
  const std::vector<EventEngine::Particle>& particles_;
  const CellLevels& cells_;
  const std::vector<double>& restSpeed_;
  const Vec3& gravity_;
  double now_;
};

}  // namespace carom
