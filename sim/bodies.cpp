#include "sim/bodies.h"

#include <algorithm>

namespace carom {

Bodies makeBodies(const Scene& scene) {
  Bodies bodies;
  const double worldRestitution = scene.world.restitution;
  for (const Plane& plane : scene.planes) {
    bodies.planes.push_back(planeShape(plane));
    bodies.planeRestitution.push_back(plane.restitution.value_or(worldRestitution));
  }
  for (const Cylinder& cylinder : scene.cylinders) {
    bodies.cylinders.push_back(cylinderShape(cylinder));
    bodies.cylinderRestitution.push_back(cylinder.restitution.value_or(worldRestitution));
  }
  for (const Ball& ball : scene.balls) {
    bodies.radius.push_back(ball.radius);
    bodies.mass.push_back(ball.mass);
    bodies.inverseMass.push_back(1.0 / ball.mass);
    bodies.restitution.push_back(ball.restitution.value_or(worldRestitution));
    bodies.maxRadius = std::max(bodies.maxRadius, ball.radius);
  }
  return bodies;
}

}  // namespace carom
