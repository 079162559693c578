#include "ui/render/render_scene.h"

#include "sim/core/prefault.h"
#include "sim/geometry/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace carom::render {
namespace {

// Soft, distinguishable colours for balls that have none in the scene file.
constexpr std::array<const char*, 10> kBallPalette = {
    "#e76f51", "#2a9d8f", "#e9c46a", "#457b9d", "#f4a261",
    "#8ab17d", "#b56576", "#6d597a", "#43aa8b", "#f28482",
};
constexpr std::size_t kMostColorsRemembered = 1024;
constexpr const char* kDefaultPlaneColor = "#b8b2a7";
constexpr const char* kDefaultCylinderColor = "#9a8c98";
constexpr const char* kDefaultBoxColor = "#b08968";

QColor colorOr(const std::string& text, const char* fallback) {
  QColor color(QString::fromStdString(text));
  return color.isValid() ? color : QColor(fallback);
}

// A plane counts as a wall of the box when its normal lies along a coordinate axis.
constexpr double kAxisAlignedTolerance = 1e-9;

// The least a scene shows: 10 m without balls, else 20 radii of its largest ball (10 m for the
// editor's first ball), so that its scale follows the balls'.
constexpr double kEmptySceneSize = 10.0;
constexpr double kRoomPerBallRadius = 20.0;

// 1, 2 or 5 times a power of ten, close to `value`: grid spacings people read at a glance.
double niceStep(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  const double mantissa = value / decade;
  if (mantissa < 1.5) return decade;
  if (mantissa < 3.5) return 2.0 * decade;
  if (mantissa < 7.5) return 5.0 * decade;
  return 10.0 * decade;
}

}  // namespace

Bounds sceneBounds(const Scene& scene) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 contentMin = Vec3::Constant(kInf);
  Vec3 contentMax = Vec3::Constant(-kInf);
  auto include = [&](const Vec3& center, double radius) {
    contentMin = contentMin.cwiseMin(center - Vec3::Constant(radius));
    contentMax = contentMax.cwiseMax(center + Vec3::Constant(radius));
  };
  double maxBallRadius = 0.0;
  for (const Ball& ball : scene.balls) {
    include(ball.position, ball.radius);
    maxBallRadius = std::max(maxBallRadius, ball.radius);
  }
  // Every plane and cylinder is drawn through its own point, wherever that lies: a wall placed
  // away from the balls is seen. A box containing the point always meets the shape.
  Vec3 anchorMin = Vec3::Constant(kInf);
  Vec3 anchorMax = Vec3::Constant(-kInf);
  auto anchor = [&](const Vec3& point) {
    anchorMin = anchorMin.cwiseMin(point);
    anchorMax = anchorMax.cwiseMax(point);
    include(point, 0.0);
  };
  // A capped cylinder and a box are finite: all of them is content.
  const auto anchorAround = [&](const Vec3& centre, const Vec3& reach) {
    anchor(centre - reach);
    anchor(centre + reach);
  };
  for (const Cylinder& cylinder : scene.cylinders) {
    const CylinderShape shape = cylinderShape(cylinder);
    if (shape.capped())
      anchorAround(shape.point, shape.reach());
    else
      anchor(cylinder.point);
  }
  for (const Box& box : scene.boxes) {
    const BoxShape shape = boxShape(box);
    anchorAround(shape.center, shape.reach());
  }
  for (const Plane& plane : scene.planes) anchor(plane.point);
  if (!(contentMin.array() <= contentMax.array()).all()) {
    contentMin = Vec3::Constant(-5.0);
    contentMax = Vec3::Constant(5.0);
  }

  // Axis-aligned planes close the box on their side: the room itself is what frames the balls.
  Vec3 lower = contentMin;
  Vec3 upper = contentMax;
  std::array<bool, 3> lowerIsWall = {false, false, false};
  std::array<bool, 3> upperIsWall = {false, false, false};
  for (const Plane& plane : scene.planes) {
    const double length = plane.normal.norm();
    if (length == 0.0) continue;
    const Vec3 normal = plane.normal / length;
    for (int axis = 0; axis < 3; ++axis) {
      const Vec3 unit = Vec3::Unit(axis);
      const double coordinate = plane.point[axis];
      if ((normal - unit).norm() < kAxisAlignedTolerance) {
        lower[axis] = lowerIsWall[axis] ? std::max(lower[axis], coordinate) : coordinate;
        lowerIsWall[axis] = true;
      } else if ((normal + unit).norm() < kAxisAlignedTolerance) {
        upper[axis] = upperIsWall[axis] ? std::min(upper[axis], coordinate) : coordinate;
        upperIsWall[axis] = true;
      }
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (upper[axis] < lower[axis]) std::swap(lower[axis], upper[axis]);
    // A wall closes its side, but not in front of an object standing beyond it (a second floor
    // below the first, a cylinder placed outside the room).
    if (lowerIsWall[axis]) lower[axis] = std::min(lower[axis], anchorMin[axis]);
    if (upperIsWall[axis]) upper[axis] = std::max(upper[axis], anchorMax[axis]);
  }

  double maxExtent = (upper - lower).maxCoeff();
  if (!(maxExtent > 1e-6)) maxExtent = 1.0;
  // Room to build on: a new scene's floor does not shrink to a strip around its first balls.
  maxExtent = std::max(maxExtent,
                       scene.balls.empty() ? kEmptySceneSize : kRoomPerBallRadius * maxBallRadius);
  const double pad = std::max(0.1 * maxExtent, 2.0 * maxBallRadius);
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = upper[axis] - lower[axis];
    if (!lowerIsWall[axis] && !upperIsWall[axis]) {
      // Open on both sides (a floor's width, say): about as wide as the scene is large, so a
      // single ball does not stand on a narrow strip.
      const double grow = std::max(pad, 0.5 * (maxExtent - extent));
      lower[axis] -= grow;
      upper[axis] += grow;
    } else {
      if (!lowerIsWall[axis]) lower[axis] -= pad;
      if (!upperIsWall[axis]) upper[axis] += pad;
    }
  }
  return Bounds{lower, upper};
}

std::vector<Vec3> clipPlaneToBounds(const Vec3& point, const Vec3& normal, const Bounds& bounds) {
  const double length = normal.norm();
  if (length == 0.0) return {};
  const Vec3 n = normal / length;
  // A tangent basis with u x v = n, so that the starting quad winds counter-clockwise around n.
  int leastAxis = 0;
  n.cwiseAbs().minCoeff(&leastAxis);
  const Vec3 u = n.cross(Vec3::Unit(leastAxis)).normalized();
  const Vec3 v = n.cross(u);
  const Vec3 boxCenter = bounds.center();
  const Vec3 center = boxCenter - n * n.dot(boxCenter - point);
  const double half = 2.0 * bounds.radius() + 1.0;  // wider than the box in every direction
  std::vector<Vec3> polygon = {center - half * u - half * v, center + half * u - half * v,
                               center + half * u + half * v, center - half * u + half * v};

  // Sutherland-Hodgman against the six faces. The tolerance keeps planes lying exactly on a
  // face (a floor at the bottom of the box) instead of losing them to rounding.
  const double tolerance = 1e-9 * (1.0 + bounds.radius());
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      auto insideDistance = [&](const Vec3& p) {
        return side == 0 ? p[axis] - bounds.min[axis] + tolerance
                         : bounds.max[axis] - p[axis] + tolerance;
      };
      std::vector<Vec3> clipped;
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % polygon.size()];
        const double da = insideDistance(a);
        const double db = insideDistance(b);
        if (da >= 0.0) clipped.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) clipped.push_back(a + (b - a) * (da / (da - db)));
      }
      polygon = std::move(clipped);
      if (polygon.empty()) return {};
    }
  }

  // Crossing a box edge or corner leaves repeated points; they would make empty triangles.
  std::vector<Vec3> distinct;
  for (const Vec3& p : polygon) {
    // Snapped into the box: the tolerance above lets points sit just outside it.
    const Vec3 inside = p.cwiseMax(bounds.min).cwiseMin(bounds.max);
    if (distinct.empty() || (inside - distinct.back()).norm() > tolerance) {
      distinct.push_back(inside);
    }
  }
  while (distinct.size() > 1 && (distinct.front() - distinct.back()).norm() <= tolerance) {
    distinct.pop_back();
  }
  if (distinct.size() < 3) return {};
  return distinct;
}

bool clipLineToBounds(const Vec3& point, const Vec3& direction, const Bounds& bounds, Vec3* start,
                      Vec3* end) {
  if (direction.norm() == 0.0) return false;
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (point[axis] < bounds.min[axis] || point[axis] > bounds.max[axis]) return false;
      continue;
    }
    double t0 = (bounds.min[axis] - point[axis]) / direction[axis];
    double t1 = (bounds.max[axis] - point[axis]) / direction[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  if (!(enter < leave)) return false;
  *start = point + enter * direction;
  *end = point + leave * direction;
  return true;
}

RenderScene makeRenderScene(const Scene& scene) {
  RenderScene render;
  render.bounds = sceneBounds(scene);
  render.horizon = render.bounds.grown(kHorizonRadii * render.bounds.radius());
  render.gridSpacing = niceStep(render.bounds.size().maxCoeff() / 12.0);

  for (const Plane& plane : scene.planes) {
    RenderPlane rendered;
    rendered.normal = plane.normal.normalized();
    rendered.color = colorOr(plane.color, kDefaultPlaneColor);
    rendered.polygon = clipPlaneToBounds(plane.point, plane.normal, render.horizon);
    render.planes.push_back(std::move(rendered));
  }
  for (const Cylinder& cylinder : scene.cylinders) {
    RenderCylinder rendered;
    rendered.radius = cylinder.radius;
    rendered.color = colorOr(cylinder.color, kDefaultCylinderColor);
    const CylinderShape shape = cylinderShape(cylinder);
    if (shape.capped()) {
      rendered.start = shape.point - shape.halfLength * shape.axis;
      rendered.end = shape.point + shape.halfLength * shape.axis;
    } else if (!clipLineToBounds(cylinder.point, cylinder.axis, render.horizon, &rendered.start,
                                 &rendered.end)) {
      rendered.start = rendered.end = cylinder.point;
    }
    render.cylinders.push_back(std::move(rendered));
  }
  for (const Box& box : scene.boxes) {
    const BoxShape shape = boxShape(box);
    RenderBox rendered;
    rendered.center = shape.center;
    for (int k = 0; k < 3; ++k) rendered.halfAxes[k] = shape.axes.col(k) * shape.half[k];
    rendered.color = colorOr(box.color, kDefaultBoxColor);
    render.boxes.push_back(std::move(rendered));
  }
  const std::size_t count = scene.balls.size();
  reservePrefaulted(render.ballRadii, count);
  reservePrefaulted(render.ballColors, count);
  reservePrefaulted(render.initialBallPositions, count);
  // Balls mostly share a few colours: each is read once (a million took 0.1-0.2 s to read).
  std::array<QColor, kBallPalette.size()> palette;
  for (std::size_t k = 0; k < palette.size(); ++k) palette[k] = QColor(kBallPalette[k]);
  std::unordered_map<std::string, QColor> colors;
  for (std::size_t i = 0; i < count; ++i) {
    const Ball& ball = scene.balls[i];
    render.ballRadii.push_back(ball.radius);
    QColor color;
    if (const auto known = colors.find(ball.color); known != colors.end()) {
      color = known->second;
    } else {
      color = QColor(QString::fromStdString(ball.color));
      if (color.isValid() && colors.size() < kMostColorsRemembered)
        colors.emplace(ball.color, color);
    }
    render.ballColors.push_back(color.isValid() ? color : palette[i % palette.size()]);
    render.initialBallPositions.push_back(ball.position);
  }
  return render;
}

}  // namespace carom::render
