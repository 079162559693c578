#include "sim/scene_builders.h"

#include <cmath>
#include <numbers>
#include <random>

namespace carom {
namespace {

// Box-Muller on the engine's raw output: unlike std::normal_distribution, the same on every
// standard library.
double standardNormal(std::mt19937_64& engine) {
  const double scale = 1.0 / 18446744073709551616.0;  // 2^-64
  const double u1 = (static_cast<double>(engine()) + 1.0) * scale;
  const double u2 = static_cast<double>(engine()) * scale;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace

void addBoxWalls(Scene& scene, double halfSide, std::initializer_list<int> axes) {
  for (int a : axes) {
    for (double side : {-1.0, 1.0}) {
      Plane wall;
      wall.point = Vec3::Zero();
      wall.point[a] = side * halfSide;
      wall.normal = -side * Vec3::Unit(a);
      scene.planes.push_back(wall);
    }
  }
}

Scene makeGasInBox(int ballCount, double packingFraction, const Vec3& gravity, std::uint64_t seed,
                   double radius) {
  Scene scene;
  scene.world.gravity = gravity;
  scene.world.restitution = 1.0;
  scene.world.method = Method::Exact;
  const double ballVolume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double side = std::cbrt(ballCount * ballVolume / packingFraction);
  const int perSide = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(ballCount))));
  const double spacing = side / perSide;
  const double half = 0.5 * side;
  addBoxWalls(scene, half);
  std::mt19937_64 engine(seed);
  Vec3 total = Vec3::Zero();
  for (int i = 0; i < ballCount; ++i) {
    Ball ball;
    ball.radius = radius;
    const int x = i % perSide, y = (i / perSide) % perSide, z = i / (perSide * perSide);
    ball.position = Vec3(x + 0.5, y + 0.5, z + 0.5) * spacing - Vec3::Constant(half);
    ball.velocity = Vec3(standardNormal(engine), standardNormal(engine), standardNormal(engine));
    total += ball.velocity;
    scene.balls.push_back(ball);
  }
  if (ballCount > 1)
    for (Ball& ball : scene.balls) ball.velocity -= total / ballCount;
  return scene;
}

}  // namespace carom
