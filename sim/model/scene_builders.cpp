#include "sim/model/scene_builders.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

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

Scene makeGaltonBoard(int ballCount, std::uint64_t seed, double radius) {
  Scene scene;
  scene.world.gravity = Vec3(0.0, -9.81, 0.0);
  scene.world.restitution = 0.5;
  scene.world.method = Method::Exact;
  const double r = radius;
  const double pitch = 5.0 * r;  // between neighbouring pegs
  const double pegRadius = 0.75 * r;
  const double depth = 3.0 * r;  // the glass is at z = -depth and +depth
  // Pegs and boards reach a radius into the glass: their edges and rims are out of every ball's
  // reach, so no contact time is solved for them.
  const double solidDepth = depth + r;
  const int rows = std::max(10, static_cast<int>(std::lround(std::sqrt(ballCount) / 3.0)));
  const double rowStep = pitch * std::sqrt(3.0) / 2.0;
  const double halfWidth = 0.5 * (rows + 1) * pitch;
  const auto plane = [&](const std::string& name, const Vec3& point, const Vec3& normal) {
    Plane p;
    p.name = name;
    p.point = point;
    p.normal = normal;
    scene.planes.push_back(p);
  };

  // The bins: a floor, and between neighbouring bins a divider under each peg of the last row.
  // The middle bin takes C(rows, rows/2) / 2^rows of the balls, about four to a layer of two
  // radii.
  const double middleShare = std::exp(std::lgamma(rows + 1.0) - std::lgamma(rows / 2 + 1.0) -
                                      std::lgamma(rows - rows / 2 + 1.0) - rows * std::log(2.0));
  const double binHeight = 2.0 * r * (std::ceil(1.3 * middleShare * ballCount / 4.0) + 2.0);
  plane("floor", Vec3::Zero(), Vec3::UnitY());
  plane("left wall", Vec3(-halfWidth, 0.0, 0.0), Vec3::UnitX());
  plane("right wall", Vec3(halfWidth, 0.0, 0.0), -Vec3::UnitX());
  plane("back glass", Vec3(0.0, 0.0, -depth), Vec3::UnitZ());
  plane("front glass", Vec3(0.0, 0.0, depth), -Vec3::UnitZ());
  for (int j = 0; j < rows; ++j) {
    Box divider;
    divider.name = "divider " + std::to_string(j);
    divider.center = Vec3((j - 0.5 * (rows - 1)) * pitch, 0.5 * binHeight, 0.0);
    divider.halfExtents = Vec3(0.25 * r, 0.5 * binHeight, solidDepth);
    scene.boxes.push_back(divider);
  }

  // The pegs: row k has k + 1 of them, the apex on top.
  const double bottomRow = binHeight + pegRadius + r;
  const double topRow = bottomRow + (rows - 1) * rowStep;
  for (int k = 0; k < rows; ++k) {
    for (int j = 0; j <= k; ++j) {
      Cylinder peg;
      peg.name = "peg " + std::to_string(k) + "." + std::to_string(j);
      peg.point = Vec3((j - 0.5 * k) * pitch, topRow - k * rowStep, 0.0);
      peg.axis = Vec3::UnitZ();
      peg.radius = pegRadius;
      peg.length = 2.0 * solidDepth;
      scene.cylinders.push_back(peg);
    }
  }

  // The funnel: two boards from the walls down to an outlet of eight radii above the apex.
  const double slope = 35.0 * std::numbers::pi / 180.0;
  const double outletHalf = 4.0 * r;
  const double boardHalfThickness = 0.5 * r;
  const double boardLength = (halfWidth - outletHalf) / std::cos(slope);
  const double outletHeight = topRow + pitch;
  for (double side : {-1.0, 1.0}) {
    const Vec3 along(std::cos(slope), side * std::sin(slope), 0.0);  // local x, rising outwards
    const Vec3 up(-side * std::sin(slope), std::cos(slope), 0.0);    // local y, the top face
    const Vec3 innerTop(side * outletHalf, outletHeight, 0.0);
    Box board;
    board.name = side < 0.0 ? "left funnel" : "right funnel";
    board.center = innerTop + side * along * (0.5 * boardLength) - up * boardHalfThickness;
    board.halfExtents = Vec3(0.5 * boardLength, boardHalfThickness, solidDepth);
    board.rotation = Rotation{Vec3::UnitZ(), side * 35.0};
    scene.boxes.push_back(board);
  }

  // The balls: two deep, a lattice of 2.5 radii jittered by the seed, from above the funnel up.
  const double funnelTop = outletHeight + (halfWidth - outletHalf) * std::tan(slope);
  const double spacing = 2.5 * r;
  const int across = static_cast<int>(std::floor((2.0 * halfWidth - 2.0 * r) / spacing));
  std::mt19937_64 engine(seed);
  const double jitter = 0.2 * r;
  const auto offset = [&] {
    return jitter * (2.0 * static_cast<double>(engine() >> 11) * 0x1.0p-53 - 1.0);
  };
  for (int i = 0; i < ballCount; ++i) {
    const int column = (i / 2) % across, layer = (i / 2) / across;
    Ball ball;
    ball.radius = r;
    ball.mass = 0.001;
    ball.position = Vec3(-halfWidth + 1.25 * r + column * spacing + offset(),
                         funnelTop + 2.0 * r + layer * spacing + offset(),
                         (i % 2 == 0 ? -1.25 : 1.25) * r + offset());
    scene.balls.push_back(ball);
  }
  return scene;
}

Scene makePouredPile(int ballCount, double friction, std::uint64_t seed) {
  Scene scene;
  scene.world.gravity = Vec3(0.0, -9.81, 0.0);
  scene.world.restitution = 0.5;
  scene.world.friction = friction;
  scene.world.method = Method::Exact;
  Plane floor;
  floor.point = Vec3::Zero();
  floor.normal = Vec3::UnitY();
  scene.planes.push_back(floor);
  addBoxWalls(scene, 0.4, {0, 2});
  constexpr int kAcross = 7;
  const int layers = std::max(1, (ballCount + kAcross * kAcross - 1) / (kAcross * kAcross));
  std::vector<Vec3> sites;
  for (int y = 0; y < layers; ++y)
    for (int x = 0; x < kAcross; ++x)
      for (int z = 0; z < kAcross; ++z)
        sites.emplace_back(-0.33 + 0.11 * x, 0.06 + 0.12 * y, -0.33 + 0.11 * z);
  std::mt19937_64 engine(seed);
  const auto uniform = [&](double half) {
    return half * (2.0 * static_cast<double>(engine() >> 11) * 0x1.0p-53 - 1.0);
  };
  // A Fisher-Yates shuffle on the engine's raw output: the same on every standard library.
  for (std::size_t k = sites.size() - 1; k > 0; --k)
    std::swap(sites[k], sites[static_cast<std::size_t>(engine() % (k + 1))]);
  for (int i = 0; i < ballCount; ++i) {
    Ball ball;
    ball.radius = 0.05;
    ball.position = sites[static_cast<std::size_t>(i)] + Vec3(uniform(0.004), 0.0, uniform(0.004));
    ball.velocity = Vec3(uniform(0.5), uniform(0.5), uniform(0.5));
    scene.balls.push_back(ball);
  }
  return scene;
}

}  // namespace carom
