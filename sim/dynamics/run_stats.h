#pragma once
// What a run did: counts, and what it got wrong.

#include "sim/model/scene.h"

#include <cstdint>

namespace carom {

enum class ContactKind { BallBall, BallPlane, BallCylinder, BallBox };

struct CollisionCounts {
  std::uint64_t ballBall = 0;
  std::uint64_t ballPlane = 0;
  std::uint64_t ballCylinder = 0;
  std::uint64_t ballBox = 0;
  std::uint64_t total() const { return ballBall + ballPlane + ballCylinder + ballBox; }
  void add(ContactKind kind, std::uint64_t times = 1) {
    switch (kind) {
      case ContactKind::BallBall:
        ballBall += times;
        return;
      case ContactKind::BallPlane:
        ballPlane += times;
        return;
      case ContactKind::BallCylinder:
        ballCylinder += times;
        return;
      case ContactKind::BallBox:
        ballBox += times;
        return;
    }
  }
};

struct CollisionRecord {
  double time = 0.0;
  ContactKind kind = ContactKind::BallBall;
  int ball = 0;   // index into the scene's balls
  int other = 0;  // ball, plane, cylinder or box index, by kind
  Vec3 point = Vec3::Zero();
  double normalSpeed = 0.0;  // approach speed along the contact normal
};

struct RunStats {
  CollisionCounts collisions;
  std::uint64_t events = 0;          // events processed (exact and swept), collisions included
  std::uint64_t cellCrossings = 0;   // exact and swept: balls moving between grid cells
  std::uint64_t staleEvents = 0;     // predictions found out of date when their time came
  std::uint64_t pairTests = 0;       // ball-ball contact times computed (exact and swept)
  std::uint64_t steps = 0;           // time steps taken (swept and discrete)
  std::uint64_t ballSteps = 0;       // balls times steps (swept and discrete)
  std::uint64_t restings = 0;        // times a ball was put to rest
  std::uint64_t wakes = 0;           // times a resting ball was set moving again
  std::uint64_t minimumBounces = 0;  // bounces raised to the minimum separation speed
  std::uint64_t facePhases = 0;  // exact: phases with friction on faces that ended, each segment
                                 // of a turning one counted (TurningFacePath)
  double maxPenetration = 0.0;   // largest overlap of a ball with anything seen
};

}  // namespace carom
