#pragma once
// The part of a scene the renderer needs that does not move while it runs: geometry of the
// static objects already clipped to a finite box (the horizon), ball sizes and colours. Built
// once per scene.

#include "sim/model/scene.h"
#include "ui/render/bounds.h"

#include <Eigen/Geometry>  // cross products, for the planes and cylinders
#include <QColor>

#include <array>
#include <vector>

namespace carom::render {

struct RenderPlane {
  Vec3 normal = Vec3::UnitY();  // unit length
  QColor color;
  // The plane clipped to the scene's horizon: a convex polygon, counter-clockwise seen from the
  // side the normal points to. Empty when the plane misses it.
  std::vector<Vec3> polygon;
};

struct RenderCylinder {
  // The ends of a capped cylinder, or the axis clipped to the scene's horizon (`start == end`
  // when it misses it).
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  double radius = 1.0;
  QColor color;
};

struct RenderBox {
  Vec3 center = Vec3::Zero();
  std::array<Vec3, 3> halfAxes;  // its own axes, each as long as its half extent along it
  QColor color;
};

struct RenderScene {
  Bounds bounds;
  // The bounds grown by kHorizonRadii of their radius: where infinite shapes end.
  Bounds horizon;
  std::vector<RenderPlane> planes;
  std::vector<RenderCylinder> cylinders;
  std::vector<RenderBox> boxes;
  std::vector<double> ballRadii;
  std::vector<QColor> ballColors;
  std::vector<Vec3> initialBallPositions;  // shown until the first simulation snapshot
  double gridSpacing = 1.0;                // of the planes' texture, metres
};

RenderScene makeRenderScene(const Scene& scene);

// Building blocks of makeRenderScene, exposed for tests.
Bounds sceneBounds(const Scene& scene);
std::vector<Vec3> clipPlaneToBounds(const Vec3& point, const Vec3& normal, const Bounds& bounds);
// False when the line misses the box; otherwise the segment inside it.
bool clipLineToBounds(const Vec3& point, const Vec3& direction, const Bounds& bounds, Vec3* start,
                      Vec3* end);

}  // namespace carom::render
