// SceneView's pictures: what the view shows, drawn offscreen at any size (File > Export Image,
// Export Video) through the same code that draws the view.

#include "ui/render/render_target.h"
#include "ui/render/scene_view.h"

#include <QOpenGLFramebufferObject>

#include <algorithm>
#include <utility>

namespace carom::render {

SceneView::Picture SceneView::picture() const {
  Camera camera = camera_;
  camera.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  return {
      scene_, ballPositions_, explosions_.live(), trails_, velocityArrows_, handleArrows_, camera,
      true};
}

QImage SceneView::renderPicture(const Picture& picture, const QSize& size) {
  const auto inRange = [](int side) { return side >= kMinPictureSide && side <= kMaxPictureSide; };
  if (!inRange(size.width()) || !inRange(size.height()) || !glReady_) return {};
  // It uploads into the buffers a picture drawn in pieces is drawn from.
  if (piecewise_.drawing) cancelPicture();
  makeCurrent();
  // The picture's content stands in for the view's while it is drawn, through the same code
  // that draws the view; the view's own is put back after.
  const bool otherScene = picture.scene != scene_;
  std::shared_ptr<const RenderScene> ownScene = std::exchange(scene_, picture.scene);
  std::vector<Vec3> ownPositions = std::exchange(ballPositions_, picture.ballPositions);
  std::vector<Trail> ownTrails = std::exchange(trails_, picture.trails);
  std::vector<Arrow> ownVelocities = std::exchange(velocityArrows_, picture.velocityArrows);
  std::vector<Arrow> ownHandles = std::exchange(handleArrows_, picture.handleArrows);
  // The highlight is in the static data: without it, that is uploaded again before and after.
  const bool plain =
      !picture.highlights && (!highlightedBalls_.empty() || !highlightedPlanes_.empty() ||
                              !highlightedCylinders_.empty() || !highlightedBoxes_.empty());
  std::vector<int> ownHighlights[4];
  if (plain) {
    ownHighlights[0] = std::exchange(highlightedBalls_, {});
    ownHighlights[1] = std::exchange(highlightedPlanes_, {});
    ownHighlights[2] = std::exchange(highlightedCylinders_, {});
    ownHighlights[3] = std::exchange(highlightedBoxes_, {});
  }
  // Without the selection, the followed ball gets no marker either.
  const int ownFollowed = picture.highlights ? followedBall_ : std::exchange(followedBall_, -1);
  if (otherScene) markBallAttributesDirty();
  if (otherScene || staticDataDirty_ || plain) uploadStaticData();
  uploadBallPositions();

  QOpenGLFramebufferObjectFormat format;
  format.setAttachment(QOpenGLFramebufferObject::Depth);
  format.setInternalTextureFormat(GL_RGBA8);
  if (antialiasing() && multisample_->samples() > 1) format.setSamples(multisample_->samples());
  QImage image;
  {
    QOpenGLFramebufferObject target(size, format);
    if (target.isValid() && target.bind()) {
      glViewport(0, 0, size.width(), size.height());
      clearFrame();
      Camera camera = picture.camera;
      camera.setAspectRatio(static_cast<double>(size.width()) / size.height());
      drawPicture(frameCamera(camera), size.height(), picture.explosions);
      glBindVertexArray(0);
      glUseProgram(0);
      glDisable(GL_CULL_FACE);
      glDisable(GL_DEPTH_TEST);
      // A multisampled target is resolved into a plain one by toImage.
      image = target.toImage().convertToFormat(QImage::Format_RGB32);
      target.release();
    }
  }
  scene_ = std::move(ownScene);
  ballPositions_ = std::move(ownPositions);
  trails_ = std::move(ownTrails);
  velocityArrows_ = std::move(ownVelocities);
  handleArrows_ = std::move(ownHandles);
  if (plain) {
    highlightedBalls_ = std::move(ownHighlights[0]);
    highlightedPlanes_ = std::move(ownHighlights[1]);
    highlightedCylinders_ = std::move(ownHighlights[2]);
    highlightedBoxes_ = std::move(ownHighlights[3]);
  }
  followedBall_ = ownFollowed;
  if (otherScene || plain) staticDataDirty_ = true;
  if (otherScene) markBallAttributesDirty();
  positionsDirty_ = true;
  doneCurrent();
  return image;
}

}  // namespace carom::render
