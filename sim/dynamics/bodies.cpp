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
  // The objects' own friction, kept only when one of them has any.
  bool anyOwn = false;
  const auto scan = [&](const auto& objects) {
    for (const ObjectInfo& object : objects)
      for (const std::optional<double>& value :
           {object.friction, object.rollingResistance, object.spinningFriction}) {
        anyOwn = anyOwn || value.has_value();
        bodies.ownRough = bodies.ownRough || value.value_or(0.0) > 0.0;
      }
  };
  const auto keep = [&](const auto& objects, std::vector<Bodies::OwnFriction>& values) {
    for (const ObjectInfo& object : objects)
      values.push_back({object.friction, object.rollingResistance, object.spinningFriction});
  };
  scan(scene.planes);
  scan(scene.cylinders);
  scan(scene.boxes);
  scan(scene.balls);
  if (anyOwn) {
    keep(scene.planes, bodies.planeOwnFriction);
    keep(scene.cylinders, bodies.cylinderOwnFriction);
    keep(scene.boxes, bodies.boxOwnFriction);
    keep(scene.balls, bodies.ownFriction);
  }
  bodies.setWorldFriction(scene.world);
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

void Bodies::setWorldFriction(const World& world) {
  tangentialRestitution = world.tangentialRestitution;
  rough = ownRough || world.friction != 0.0 || world.rollingResistance != 0.0 ||
          world.spinningFriction != 0.0;
  const auto resolve = [&](const std::vector<OwnFriction>& own, std::size_t count,
                           std::vector<ContactFriction>& resolved) {
    resolved.clear();
    if (!rough) return;
    for (std::size_t k = 0; k < count; ++k) {
      const OwnFriction o = own.empty() ? OwnFriction{} : own[k];
      resolved.push_back({o.sliding.value_or(world.friction),
                          o.rolling.value_or(world.rollingResistance),
                          o.spinning.value_or(world.spinningFriction)});
    }
  };
  resolve(planeOwnFriction, planes.size(), planeFriction);
  resolve(cylinderOwnFriction, cylinders.size(), cylinderFriction);
  resolve(boxOwnFriction, boxes.size(), boxFriction);
  resolve(ownFriction, radius.size(), friction);
}

}  // namespace carom
