#include "sim/grab_sweep.h"

#include "sim/contact_time.h"

#include <algorithm>

namespace carom {

double freeTravel(const Bodies& bodies, const std::vector<BallState>& state, int ball,
                  const Vec3& move) {
  // The move as a straight path of unit duration: its contact times are the fractions, solved
  // by the same functions as every contact in a run.
  const BallPath path{state[ball].position, move, Vec3::Zero()};
  const double r = bodies.radius[ball];
  double first = 1.0;
  for (const PlaneShape& plane : bodies.planes)
    first = std::min(first, ballPlaneContactTime(path, r, plane, first));
  for (const CylinderShape& cylinder : bodies.cylinders)
    first = std::min(first, ballCylinderContactTime(path, r, cylinder, first));
  for (const BoxShape& box : bodies.boxes)
    first = std::min(first, ballBoxContactTime(path, r, box, first));
  for (int k = 0; k < static_cast<int>(state.size()); ++k) {
    if (k == ball) continue;
    first = std::min(first, ballBallStraightContactTime(state[k].position - path.position, -move,
                                                        r + bodies.radius[k], first));
  }
  return std::max(first, 0.0);
}

}  // namespace carom
