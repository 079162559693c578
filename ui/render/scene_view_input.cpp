// SceneView's camera in the user's hands: dragging orbits, the middle button pans, the wheel
// zooms, the arrow keys turn and Home frames the scene. Any of these ends the automatic framing.

#include "ui/render/scene_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>

namespace carom::render {
namespace {

constexpr double kOrbitRadiansPerPixel = 0.008;
constexpr double kWheelStepAngle = 120.0;  // eighths of a degree in one wheel notch

}  // namespace

void SceneView::userMovedCamera() {
  autoFrame_ = false;
  update();
}

void SceneView::resizeEvent(QResizeEvent* event) {
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  if (autoFrame_ && scene_) camera_.home(scene_->bounds);
  QOpenGLWidget::resizeEvent(event);
}

void SceneView::mousePressEvent(QMouseEvent* event) {
  lastMousePosition_ = event->position().toPoint();
  event->accept();
}

void SceneView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint position = event->position().toPoint();
  const QPoint delta = position - lastMousePosition_;
  lastMousePosition_ = position;
  if (event->buttons() & Qt::LeftButton) {
    // Dragging turns the scene with the cursor, so the camera goes the other way.
    camera_.orbit(-delta.x() * kOrbitRadiansPerPixel, delta.y() * kOrbitRadiansPerPixel);
    userMovedCamera();
  } else if (event->buttons() & Qt::MiddleButton) {
    setFollowedBall(-1);  // following would snap the target straight back
    const double viewHeight = std::max(1, height());
    camera_.pan(delta.x() / viewHeight, delta.y() / viewHeight);
    userMovedCamera();
  }
  event->accept();
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
  event->accept();
}

void SceneView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / kWheelStepAngle;
  if (steps != 0.0) {
    camera_.zoom(steps);
    userMovedCamera();
  }
  event->accept();
}

void SceneView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Left:
      camera_.rotateByKeys(1, 0);
      break;
    case Qt::Key_Right:
      camera_.rotateByKeys(-1, 0);
      break;
    case Qt::Key_Up:
      camera_.rotateByKeys(0, 1);
      break;
    case Qt::Key_Down:
      camera_.rotateByKeys(0, -1);
      break;
    default:
      QOpenGLWidget::keyPressEvent(event);
      return;
  }
  userMovedCamera();
}

}  // namespace carom::render
