#include "ui/render/camera.h"

#include <QVector4D>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carom::render {
namespace {

constexpr double kMinDistance = 1e-3;
constexpr double kMaxDistance = 1e7;

QVector3D toQt(const Vec3& v) {
  return QVector3D(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
}

}  // namespace

QVector3D Camera::eye() const {
  const double horizontal = std::cos(pitch_);
  const QVector3D offset(static_cast<float>(horizontal * std::sin(yaw_)),
                         static_cast<float>(std::sin(pitch_)),
                         static_cast<float>(horizontal * std::cos(yaw_)));
  return target_ + static_cast<float>(distance_) * offset;
}

void Camera::setYaw(double radians) {
  // Kept in (-pi, pi] so that it stays precise however long someone spins the view.
  yaw_ = std::remainder(radians, 2.0 * std::numbers::pi);
}

void Camera::setPitch(double radians) {
  pitch_ = std::clamp(radians, -kMaxPitch, kMaxPitch);
}

void Camera::setDistance(double distance) {
  distance_ = std::clamp(distance, kMinDistance, kMaxDistance);
}

void Camera::setVerticalFov(double degrees) {
  verticalFov_ = std::clamp(degrees, 5.0, 150.0);
}

void Camera::setAspectRatio(double aspectRatio) {
  if (aspectRatio > 0.0 && std::isfinite(aspectRatio)) aspectRatio_ = aspectRatio;
}

QMatrix4x4 Camera::view() const {
  QMatrix4x4 matrix;
  matrix.lookAt(eye(), target_, QVector3D(0.0f, 1.0f, 0.0f));
  return matrix;
}

QMatrix4x4 Camera::projection() const {
  // The near plane follows the distance so that zooming in on a small ball does not cut it,
  // the far plane reaches past the scene's horizon (whose half diagonal is under
  // 1 + 2 kHorizonRadii scene radii) seen from the far side.
  const double nearPlane = std::max(distance_ * 0.01, kMinDistance * 0.1);
  const double farPlane = distance_ + 4.0 * (1.0 + 2.0 * kHorizonRadii) * sceneRadius_ + nearPlane;
  QMatrix4x4 matrix;
  matrix.perspective(static_cast<float>(verticalFov_), static_cast<float>(aspectRatio_),
                     static_cast<float>(nearPlane), static_cast<float>(farPlane));
  return matrix;
}

QPointF Camera::projectToNdc(const Vec3& world) const {
  const QVector4D clip = viewProjection() * QVector4D(toQt(world), 1.0f);
  if (clip.w() == 0.0f) return QPointF();
  return QPointF(clip.x() / clip.w(), clip.y() / clip.w());
}

std::pair<Vec3, Vec3> Camera::rayThroughNdc(const QPointF& ndc) const {
  // Works on the very matrix projectToNdc applies, rounded to float as it is, so that the ray
  // projects back onto `ndc` up to the rounding of projectToNdc itself; the rest is in double.
  const QMatrix4x4 matrix = viewProjection();
  const auto row = [&](int i) {
    return Eigen::Vector4d(matrix(i, 0), matrix(i, 1), matrix(i, 2), matrix(i, 3));
  };
  const Eigen::Vector4d x = row(0);
  const Eigen::Vector4d y = row(1);
  const Eigen::Vector4d w = row(3);
  // A point projects to ndc where x - ndc.x w and y - ndc.y w vanish: two planes through the
  // eye, which meet in the ray's line. In front of the eye the clip w is positive.
  const Eigen::Vector4d acrossX = x - ndc.x() * w;
  const Eigen::Vector4d acrossY = y - ndc.y() * w;
  Vec3 direction = acrossX.head<3>().cross(acrossY.head<3>());
  if (direction.dot(w.head<3>()) < 0.0) direction = -direction;
  // The eye is the point that x, y and w all send to zero, whatever the ndc.
  Eigen::Matrix3d rows;
  rows << x.head<3>().transpose(), y.head<3>().transpose(), w.head<3>().transpose();
  const Vec3 eye = rows.partialPivLu().solve(-Vec3(x(3), y(3), w(3)));
  return {eye, direction.normalized()};
}

void Camera::orbit(double dx, double dy) {
  setYaw(yaw_ + dx);
  setPitch(pitch_ + dy);
}

void Camera::pan(double dx, double dy) {
  const QVector3D forward = (target_ - eye()).normalized();
  const QVector3D right =
      QVector3D::crossProduct(forward, QVector3D(0.0f, 1.0f, 0.0f)).normalized();
  const QVector3D up = QVector3D::crossProduct(right, forward);
  // Height of the view at the target's depth.
  const double viewHeight =
      2.0 * distance_ * std::tan(0.5 * verticalFov_ * std::numbers::pi / 180.0);
  target_ += static_cast<float>(viewHeight) *
             (static_cast<float>(-dx) * right + static_cast<float>(dy) * up);
}

void Camera::zoom(double steps) {
  setDistance(distance_ * std::pow(kZoomFactor, steps));
}

void Camera::rotateByKeys(int horizontalSteps, int verticalSteps) {
  orbit(horizontalSteps * kKeyStep, verticalSteps * kKeyStep);
}

void Camera::frame(const Bounds& bounds) {
  target_ = toQt(bounds.center());
  sceneRadius_ = std::max(bounds.radius(), kMinDistance);
  // The camera's axes do not depend on the distance, so each corner of the box gives the least
  // distance at which it is inside the view; the largest of those fits the whole box, tighter
  // than fitting the enclosing sphere.
  const Vec3 back(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                  std::cos(pitch_) * std::cos(yaw_));
  const Vec3 right = Vec3::UnitY().cross(back).normalized();
  const Vec3 up = back.cross(right);
  const double tanVertical = std::tan(0.5 * verticalFov_ * std::numbers::pi / 180.0);
  const double tanHorizontal = tanVertical * aspectRatio_;
  double distance = kMinDistance;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 point((corner & 1) ? bounds.max.x() : bounds.min.x(),
                     (corner & 2) ? bounds.max.y() : bounds.min.y(),
                     (corner & 4) ? bounds.max.z() : bounds.min.z());
    const Vec3 offset = point - bounds.center();
    const double towardsEye = offset.dot(back);
    distance = std::max(distance, towardsEye + std::abs(offset.dot(right)) / tanHorizontal);
    distance = std::max(distance, towardsEye + std::abs(offset.dot(up)) / tanVertical);
  }
  constexpr double kMargin = 1.05;  // a little air around the box
  setDistance(kMargin * distance);
}

void Camera::home(const Bounds& bounds) {
  setYaw(kDefaultYaw);
  setPitch(kDefaultPitch);
  frame(bounds);
}

void Camera::follow(const Vec3& point) {
  target_ = toQt(point);
}

}  // namespace carom::render
