#pragma once
// A static shape as the event engine names it: its kind and its index in Bodies' list of that
// kind.

#include "sim/dynamics/run_stats.h"

#include <cstdint>

namespace carom {

enum class StaticKind : std::uint8_t { Plane, Cylinder, Box };

struct StaticRef {
  StaticKind kind;
  int index;
};

inline ContactKind contactKindOf(StaticKind kind) {
  return kind == StaticKind::Box        ? ContactKind::BallBox
         : kind == StaticKind::Cylinder ? ContactKind::BallCylinder
                                        : ContactKind::BallPlane;
}

}  // namespace carom
