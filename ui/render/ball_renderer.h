#pragma once
// The GL side of the balls: their radii, colours and positions in GL buffers, sorted nearest
// first each picture, and drawn as ray-cast impostors (squares or point sprites), whole or a
// range at a time.

#include "sim/model/scene.h"
#include "ui/render/frame_camera.h"
#include "ui/render/render_scene.h"

#include <QOpenGLFunctions_3_3_Core>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

class QOpenGLShaderProgram;

namespace carom::render {

class BallRenderer {
 public:
  // Makes its GL objects in `gl`'s context, which must be current here, on every call, and when
  // this is destroyed. From `pointSpriteBalls` balls on, the small ones are point sprites.
  BallRenderer(QOpenGLFunctions_3_3_Core* gl, int pointSpriteBalls);
  ~BallRenderer();
  BallRenderer(const BallRenderer&) = delete;
  BallRenderer& operator=(const BallRenderer&) = delete;

  // The radii and colours are all uploaded again (a new scene), not only the highlights.
  void markAttributesDirty();
  bool attributesDirty() const { return attributesDirty_; }
  // Uploads at most `mostBalls` balls' attributes when all must be uploaded, and returns
  // whether they all are; else uploads the highlights that changed.
  bool uploadAttributes(const RenderScene* scene, const std::vector<int>& highlightedBalls,
                        std::size_t mostBalls);
  // One position per ball of `scene`, in its order.
  void uploadPositions(const RenderScene* scene, const std::vector<Vec3>& positions);
  // Sorts the uploaded balls for drawing, nearest `frame.eye` first, at `pixelAngle` radians per
  // device pixel; returns how many there are to draw.
  int prepare(const RenderScene* scene, const std::vector<Vec3>& positions,
              const FrameCamera& frame, double pixelAngle);
  // The balls the last prepare sorted.
  int preparedBalls() const { return squareBallCount_ + spriteBallCount_; }
  // Balls [first, first + count) in drawing order: the squares, then the sprites.
  void drawRange(const FrameCamera& frame, double pixelAngle, int first, int count);

 private:
  void createBuffers();
  // Fills the element buffer with the balls nearest first: the squares' triangles, then the
  // point sprites' vertices (in scenes of pointSpriteBalls_ or more, the balls whose sprite fits
  // the renderer's largest point).
  void sortFrontToBack(const RenderScene& scene, const std::vector<Vec3>& positions,
                       const QVector3D& eye, double pixelAngle);
  // Replaces the bound buffer's contents, keeping its storage when the size is unchanged: the
  // frame before has finished (endFrame), so nothing draws from it, and new storage would be
  // fresh memory to fault in.
  template <typename T>
  void uploadReusingStorage(GLenum target, const std::vector<T>& data, GLsizeiptr& storageBytes) {
    const auto bytes = static_cast<GLsizeiptr>(data.size() * sizeof(T));
    if (bytes != storageBytes) {
      gl_->glBufferData(target, bytes, data.empty() ? nullptr : data.data(), GL_STREAM_DRAW);
      storageBytes = bytes;
    } else if (bytes > 0) {
      gl_->glBufferSubData(target, 0, bytes, data.data());
    }
  }

  QOpenGLFunctions_3_3_Core* gl_;
  int pointSpriteBalls_;
  std::unique_ptr<QOpenGLShaderProgram> program_;
  float largestPointSize_ = 1.0f;
  GLuint vao_ = 0;
  GLuint indexBuffer_ = 0;
  GLuint positionBuffer_ = 0;
  GLuint attributeBuffer_ = 0;
  bool attributesDirty_ = true;         // else only highlights that changed are uploaded
  std::size_t attributesUploaded_ = 0;  // balls, while all are being uploaded
  std::vector<bool> uploadedHighlights_;
  int uploadedBallCount_ = 0;
  int squareBallCount_ = 0;  // in the element buffer, before the sprites
  int spriteBallCount_ = 0;
  // What each frame builds for the balls, kept from frame to frame: a million balls make some
  // 80 MB of them, and fresh memory costs a page fault every 4 KiB (a third of a second here).
  std::vector<float> centerScratch_;  // x, y, z of each vertex
  std::vector<std::pair<float, GLuint>> orderScratch_;
  std::vector<std::pair<float, GLuint>> sortScratch_;
  std::vector<GLuint> indexScratch_;
  GLsizeiptr centerBytes_ = 0;  // the sizes of the GL buffers' storage
  GLsizeiptr indexBytes_ = 0;
};

}  // namespace carom::render
