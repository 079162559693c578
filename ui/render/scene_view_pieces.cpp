// SceneView's pictures of huge scenes, drawn in pieces. A software renderer takes 0.6 s to draw a
// million balls; drawn at once in paintGL, that stalls the whole window, outline and properties
// included, at every frame. Instead each picture is drawn into a framebuffer of its own, a piece
// at a time from a zero-time timer, so that the events waiting are handled between pieces, and
// paintGL only copies the last whole picture onto the screen. Each picture keeps the positions,
// camera and overlays its first piece found, so that its pieces fit together.

#include "ui/render/ball_renderer.h"
#include "ui/render/picture_targets.h"
#include "ui/render/render_target.h"
#include "ui/render/scene_view.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>

namespace carom::render {

bool SceneView::drawsInPieces() const {
  return scene_ && static_cast<int>(scene_->ballRadii.size()) >= kPiecewiseBalls && glReady_ &&
         !pictureTargets_->failed();
}

SceneView::PictureKey SceneView::currentPictureKey() const {
  return {contentVersion_, camera_.viewProjection(), devicePixelSize(), antialiasing()};
}

void SceneView::showLastPicture() {
  advanceExplosions();
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  // Live explosions change with time alone: they keep the pictures coming.
  if (!piecewise_.drawing && (drawnKey_ != currentPictureKey() || !explosions_.empty())) {
    piecewise_.drawing = true;
    piecewise_.nextBall = -1;
    piecewise_.workMilliseconds = 0.0;
    pieceTimer_.start();
  }
  if (RenderTarget* shown = pictureTargets_->shown()) {
    shown->blitTo(defaultFramebufferObject(), devicePixelSize());
  } else {
    clearFrame();
    glDisable(GL_DEPTH_TEST);
  }
}

void SceneView::cancelPicture() {
  piecewise_.drawing = false;
  pieceTimer_.stop();
  drawnKey_.reset();
  update();
}

int SceneView::pieceBalls() const {
  const double balls = ballsPerMillisecond_ * kPieceMilliseconds;
  if (!(balls >= kMinPieceBalls)) return kMinPieceBalls;  // also before the first measurement
  return static_cast<int>(std::min<double>(balls, kMaxPieceBalls));
}

void SceneView::drawNextPiece() {
  if (!piecewise_.drawing) return;
  if (!drawsInPieces()) {
    cancelPicture();  // the next paint draws at once
    return;
  }
  QElapsedTimer timer;
  timer.start();
  makeCurrent();
  const int firstBall = piecewise_.nextBall;
  const bool whole = drawPiece();
  endFrame();  // waits for the renderer: the piece's time is the GUI thread's
  doneCurrent();
  const double milliseconds = static_cast<double>(timer.nsecsElapsed()) / 1e6;
  piecewise_.workMilliseconds += milliseconds;
  if (firstBall >= 0 && piecewise_.nextBall > firstBall && milliseconds > 0.0)
    ballsPerMillisecond_ = (piecewise_.nextBall - firstBall) / milliseconds;
  if (!piecewise_.drawing) return;  // the framebuffer could not be made
  if (!whole) {
    pieceTimer_.start();
    return;
  }
  piecewise_.drawing = false;
  pictureTargets_->flip();
  update();
  emit frameRendered(piecewise_.workMilliseconds);
}

bool SceneView::bindPieceTarget() {
  RenderTarget& target = pictureTargets_->hidden();
  if (!target.bind(piecewise_.key.size, defaultFramebufferObject())) {
    cancelPicture();  // and drawsInPieces() is false from now on
    return false;
  }
  if (piecewise_.multisampled) multisample_->bind(piecewise_.key.size, target.framebuffer());
  glViewport(0, 0, piecewise_.key.size.width(), piecewise_.key.size.height());
  return true;
}

bool SceneView::drawPiece() {
  PiecewisePicture& picture = piecewise_;
  if (picture.nextBall < 0) {
    // The first piece: everything the picture shows is taken now, and the balls sorted.
    camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
    picture.key = currentPictureKey();
    drawnKey_ = picture.key;
    picture.frame = frameCamera(camera_);
    picture.pixelHeight = picture.key.size.height();
    picture.multisampled = antialiasing() && multisample_->samples() > 1;
    picture.explosions = explosions_.live();
    picture.trails = trails_;
    picture.velocityArrows = velocityArrows_;
    picture.handleArrows = handleArrows_;
    // A new scene's radii and colours take pieces of their own.
    if (ballRenderer_->attributesDirty() &&
        !ballRenderer_->uploadAttributes(scene_.get(), highlightedBalls_, kAttributePieceBalls))
      return false;
    if (staticDataDirty_) uploadStaticData();
    if (positionsDirty_) uploadBallPositions();
    if (!bindPieceTarget()) return false;
    picture.multisampled = picture.multisampled && multisample_->samples() > 1;
    clearFrame();
    prepareBalls(picture.frame, picture.pixelHeight);
    picture.nextBall = 0;
    return false;
  }
  if (!bindPieceTarget()) return false;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const int balls = ballRenderer_->preparedBalls();
  if (picture.nextBall < balls) {
    const int count = std::min(pieceBalls(), balls - picture.nextBall);
    drawBallRange(picture.frame, picture.pixelHeight, picture.nextBall, count);
    picture.nextBall += count;
    return false;
  }
  drawAfterBalls(picture.frame, picture.explosions, picture.trails, picture.velocityArrows,
                 picture.handleArrows);
  if (picture.multisampled) multisample_->blitTo(pictureTargets_->hidden().framebuffer());
  return true;
}

}  // namespace carom::render
