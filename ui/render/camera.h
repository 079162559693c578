#pragma once
// An orbit camera: it circles a target point at some distance, looking at it. Pure math, no GL.

#include "sim/model/scene.h"
#include "ui/render/bounds.h"

#include <QMatrix4x4>
#include <QPointF>
#include <QVector3D>

#include <utility>

namespace carom::render {

class Camera {
 public:
  // Above and in front of the target (+z is the front), turned a little to show two walls.
  static constexpr double kDefaultYaw = 0.45;    // radians, about +y
  static constexpr double kDefaultPitch = 0.62;  // radians above the horizon
  static constexpr double kKeyStep = 0.0872665;  // 5 degrees per arrow key press
  static constexpr double kMaxPitch = 1.55;      // just short of straight up or down
  static constexpr double kZoomFactor = 0.85;    // distance scale per zoom step

  QVector3D target() const { return target_; }
  double yaw() const { return yaw_; }
  double pitch() const { return pitch_; }
  double distance() const { return distance_; }
  double verticalFov() const { return verticalFov_; }  // degrees
  double aspectRatio() const { return aspectRatio_; }  // width / height
  QVector3D eye() const;

  void setTarget(const QVector3D& target) { target_ = target; }
  void setYaw(double radians);
  void setPitch(double radians);
  void setDistance(double distance);
  void setVerticalFov(double degrees);
  void setAspectRatio(double aspectRatio);

  QMatrix4x4 view() const;
  QMatrix4x4 projection() const;
  QMatrix4x4 viewProjection() const { return projection() * view(); }
  // Normalized device coordinates (x right, y up, both in [-1, 1] on screen) of a world point.
  QPointF projectToNdc(const Vec3& world) const;
  // Its inverse: the eye and the unit direction of the ray of world points that project to `ndc`.
  std::pair<Vec3, Vec3> rayThroughNdc(const QPointF& ndc) const;

  // Turns around the target: dx about the vertical axis, dy up and down, both in radians.
  void orbit(double dx, double dy);
  // Shifts the target sideways in the view plane; dx, dy are fractions of the view's height,
  // so that a drag across the whole view moves the scene by the whole view.
  void pan(double dx, double dy);
  // Positive steps move closer, each by kZoomFactor.
  void zoom(double steps);
  // Arrow keys: whole steps of kKeyStep.
  void rotateByKeys(int horizontalSteps, int verticalSteps);
  // Looks at the box's centre from just far enough to see all of it; keeps the direction.
  void frame(const Bounds& bounds);
  // The default direction, then frame(bounds).
  void home(const Bounds& bounds);
  void follow(const Vec3& point);

 private:
  QVector3D target_;
  double yaw_ = kDefaultYaw;
  double pitch_ = kDefaultPitch;
  double distance_ = 10.0;
  double verticalFov_ = 45.0;
  double aspectRatio_ = 4.0 / 3.0;
  double sceneRadius_ = 5.0;  // of the last framed bounds: sets the far plane
};

}  // namespace carom::render
