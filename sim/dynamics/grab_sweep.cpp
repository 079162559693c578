#include "sim/dynamics/grab_sweep.h"

#include "sim/geometry/contact_time.h"

#include <algorithm>

namespace carom {
namespace {

// A slide along what it met, again: enough for a corner of three surfaces.
constexpr int kMaxSlides = 4;

}  // namespace

FreeTravel freeTravel(const Bodies& bodies, const std::vector<BallState>& state, int ball,
                      const Vec3& move) {
  // The move as a straight path of unit duration: its contact times are the fractions, solved
  // by the same functions as every contact in a run.
  const BallPath path{state[ball].position, move, Vec3::Zero()};
  const double r = bodies.radius[ball];
  double first = 1.0;
  enum class Met { Nothing, Plane, Cylinder, Box, Ball } met = Met::Nothing;
  int which = -1;
  const auto consider = [&](double t, Met kind, int index) {
    if (t < first) {
      first = t;
      met = kind;
      which = index;
    }
  };
  for (int k = 0; k < int(bodies.planes.size()); ++k)
    consider(ballPlaneContactTime(path, r, bodies.planes[k], first), Met::Plane, k);
  for (int k = 0; k < int(bodies.cylinders.size()); ++k)
    consider(ballCylinderContactTime(path, r, bodies.cylinders[k], first), Met::Cylinder, k);
  for (int k = 0; k < int(bodies.boxes.size()); ++k)
    consider(ballBoxContactTime(path, r, bodies.boxes[k], first), Met::Box, k);
  for (int k = 0; k < int(state.size()); ++k)
    if (k != ball)
      consider(ballBallStraightContactTime(state[k].position - path.position, -move,
                                           r + bodies.radius[k], first),
               Met::Ball, k);
  FreeTravel travel{std::max(first, 0.0), Vec3::Zero()};
  const Vec3 at = path.position + travel.fraction * move;
  switch (met) {
    case Met::Nothing:
      break;
    case Met::Plane:
      travel.normal = bodies.planes[which].normal;
      break;
    case Met::Cylinder:
      travel.normal = bodies.cylinders[which].contact(at, r).normal;
      break;
    case Met::Box:
      travel.normal = bodies.boxes[which].contact(at, r).normal;
      break;
    case Met::Ball:
      travel.normal = (at - state[which].position).normalized();
      break;
  }
  return travel;
}

Vec3 slideTo(const Bodies& bodies, std::vector<BallState> state, int ball, Vec3 move) {
  for (int slide = 0; slide <= kMaxSlides && !move.isZero(); ++slide) {
    const FreeTravel travel = freeTravel(bodies, state, ball, move);
    state[ball].position += travel.fraction * move;
    if (travel.normal.isZero()) break;
    move *= 1.0 - travel.fraction;
    const double into = move.dot(travel.normal);
    if (into < 0.0) move -= into * travel.normal;
  }
  return state[ball].position;
}

}  // namespace carom
