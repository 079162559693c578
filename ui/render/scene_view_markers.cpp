// SceneView's markers of selected and followed balls outside the picture: a ball that bounced
// out of view would otherwise seem gone. Each marker is a triangle at the edge of the picture,
// in the selection's colour with the ball's own inside, pointing the way the camera would turn
// to see the ball (also for a ball behind the camera).

#include "ui/render/gl_util.h"
#include "ui/render/line_renderer.h"
#include "ui/render/scene_view.h"
#include "ui/render/view_vertices.h"

#include <QPointF>
#include <QSizeF>
#include <QVector4D>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace carom::render {
namespace {

// Sizes in device-independent pixels.
constexpr double kMarkerLength = 18.0;
constexpr double kMarkerWidth = 16.0;
constexpr double kEdgeMargin = 3.0;
constexpr double kInnerScale = 0.45;  // the ball's colour, around the marker's centre
// Selecting thousands of balls out of view would hide the picture's edges under markers.
constexpr std::size_t kMostMarkers = 64;

struct Marker {
  std::array<QPointF, 3> corners;  // in pixels from the picture's centre, y up
};

// The marker of a point, or none when it shows inside a picture `pixels` large.
std::optional<Marker> markerFor(const QMatrix4x4& viewProjection, const Vec3& point,
                                const QSizeF& pixels, double scale) {
  const QVector4D clip =
      viewProjection * QVector4D(static_cast<float>(point.x()), static_cast<float>(point.y()),
                                 static_cast<float>(point.z()), 1.0f);
  if (clip.w() > 0.0f && std::abs(clip.x()) <= clip.w() && std::abs(clip.y()) <= clip.w())
    return std::nullopt;
  // The clip x and y point the way the camera would turn whichever side of it the ball is on
  // (dividing by a negative w, behind the camera, would turn them round).
  QPointF direction(clip.x() * pixels.width(), clip.y() * pixels.height());
  const double length = std::hypot(direction.x(), direction.y());
  direction = length > 0.0 ? direction / length : QPointF(0.0, -1.0);
  const double halfWidth = 0.5 * pixels.width() - kEdgeMargin * scale;
  const double halfHeight = 0.5 * pixels.height() - kEdgeMargin * scale;
  const double reach =
      std::min(direction.x() != 0.0 ? halfWidth / std::abs(direction.x()) : 1e300,
               direction.y() != 0.0 ? halfHeight / std::abs(direction.y()) : 1e300);
  const QPointF tip = reach * direction;
  const QPointF base = tip - kMarkerLength * scale * direction;
  const QPointF across = 0.5 * kMarkerWidth * scale * QPointF(-direction.y(), direction.x());
  return Marker{{tip, base + across, base - across}};
}

// Three vertices in normalized device coordinates, shrunk by `scale` around their centre.
void appendTriangle(std::vector<Float3>& vertices, const Marker& marker, const QSizeF& pixels,
                    double scale) {
  const QPointF centre = (marker.corners[0] + marker.corners[1] + marker.corners[2]) / 3.0;
  for (const QPointF& corner : marker.corners) {
    const QPointF p = centre + scale * (corner - centre);
    vertices.push_back({static_cast<float>(2.0 * p.x() / pixels.width()),
                        static_cast<float>(2.0 * p.y() / pixels.height()), 0.0f});
  }
}

}  // namespace

void SceneView::drawOffscreenMarkers(const FrameCamera& frame) {
  if (!scene_) return;
  std::vector<int> balls = highlightedBalls_;
  if (followedBall_ >= 0) balls.push_back(followedBall_);
  std::sort(balls.begin(), balls.end());
  balls.erase(std::unique(balls.begin(), balls.end()), balls.end());
  std::array<GLint, 4> viewport{};
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  const QSizeF pixels(std::max(viewport[2], 1), std::max(viewport[3], 1));
  const double scale = devicePixelRatioF();
  std::vector<Float3> outer;
  std::vector<std::pair<Marker, QColor>> markers;
  for (int ball : balls) {
    if (ball < 0 || ball >= static_cast<int>(ballPositions_.size())) continue;
    const std::optional<Marker> marker =
        markerFor(frame.viewProjection, ballPositions_[ball], pixels, scale);
    if (!marker) continue;
    appendTriangle(outer, *marker, pixels, 1.0);
    const QColor color = static_cast<std::size_t>(ball) < scene_->ballColors.size()
                             ? scene_->ballColors[ball]
                             : QColor(Qt::gray);
    markers.emplace_back(*marker, color);
    if (markers.size() == kMostMarkers) break;
  }
  lineRenderer_->drawScreenTriangles(outer, kSelectionColor);
  for (const auto& [marker, color] : markers) {
    std::vector<Float3> inner;
    appendTriangle(inner, marker, pixels, kInnerScale);
    lineRenderer_->drawScreenTriangles(inner, color);
  }
}

}  // namespace carom::render
