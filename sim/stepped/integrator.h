#pragma once
// The integrators of `swept` and `discrete`: each splits a step's gravity kick into a part given
// before the step's straight-line motion and a part given after it.
//   explicit Euler:    x += v h;          v += g h
//   symplectic Euler:  v += g h;          x += v h       (the tutorial's)
//   velocity Verlet:   v += g h/2;  x += v h;  v += g h/2

#include "sim/model/scene.h"

namespace carom {

struct KickSplit {
  double before;  // fraction of g h added before moving
  double after;   // fraction added after
};

constexpr KickSplit kickSplit(Integrator integrator) {
  switch (integrator) {
    case Integrator::ExplicitEuler:
      return {0.0, 1.0};
    case Integrator::SymplecticEuler:
      return {1.0, 0.0};
    case Integrator::VelocityVerlet:
      return {0.5, 0.5};
  }
  return {1.0, 0.0};
}

}  // namespace carom
