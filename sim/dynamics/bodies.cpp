#include "sim/dynamics/bodies.h"
#include "sim/core/prefault.h"

#include <algorithm>

namespace carom {

Bodies makeBodies(const Scene& scene) {
  Bodies bodies;
  for (const Plane& plane : scene.planes) {
    bodies.planes.push_back(planeShape(plane));
    bodies.planeOwnRestitution.push_back(plane.restitution);
  }
  for (const Cylinder& cylinder : scene.cylinders) {
    bodies.cylinders.push_back(cylinderShape(cylinder));
    bodies.cylinderOwnRestitution.push_back(cylinder.restitution);
  }
  for (const Box& box : scene.boxes) {
    bodies.boxes.push_back(boxShape(box));
    bodies.boxOwnRestitution.push_back(box.restitution);
  }
  const std::size_t balls = scene.balls.size();
  for (auto* values : {&bodies.radius, &bodies.mass, &bodies.inverseMass})
    reservePrefaulted(*values, balls);
  reservePrefaulted(bodies.ownRestitution, balls);
  for (const Ball& ball : scene.balls) {
    bodies.radius.push_back(ball.radius);
    bodies.mass.push_back(ball.mass);
    bodies.inverseMass.push_back(1.0 / ball.mass);
    bodies.ownRestitution.push_back(ball.restitution);
    bodies.maxRadius = std::max(bodies.maxRadius, ball.radius);
  }
  bodies.setWorldRestitution(scene.world.restitution);
  return bodies;
}

void Bodies::setWorldRestitution(double worldRestitution) {
  const auto resolve = [worldRestitution](const std::vector<std::optional<double>>& own,
                                          std::vector<double>& resolved) {
    resolved.clear();
    reservePrefaulted(resolved, own.size());
    for (const std::optional<double>& value : own)
      resolved.push_back(value.value_or(worldRestitution));
  };
  resolve(planeOwnRestitution, planeRestitution);
  resolve(cylinderOwnRestitution, cylinderRestitution);
  resolve(boxOwnRestitution, boxRestitution);
  resolve(ownRestitution, restitution);
}

}  // namespace carom
