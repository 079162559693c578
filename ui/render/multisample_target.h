#pragma once
// The multisampled framebuffer the view draws into when antialiasing is on, resolved into the
// widget's own framebuffer at the end of each frame. Made on first use and again on resize.

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

namespace carom::render {

class MultisampleTarget {
 public:
  // `gl`'s context must be current here, on every call, and when this is destroyed.
  MultisampleTarget(QOpenGLFunctions_3_3_Core* gl, GLint samples);
  ~MultisampleTarget();
  MultisampleTarget(const MultisampleTarget&) = delete;
  MultisampleTarget& operator=(const MultisampleTarget&) = delete;

  // 0 once a framebuffer could not be made: the driver will not make one later either.
  GLint samples() const { return samples_; }
  // Binds the framebuffer, made or resized to `size` device pixels; when it cannot be made,
  // binds `fallback` instead and returns false.
  bool bind(const QSize& size, GLuint fallback);
  // Resolves what was drawn into `target`, which is left bound.
  void blitTo(GLuint target);

 private:
  void release();

  QOpenGLFunctions_3_3_Core* gl_;
  GLint samples_;
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  GLuint depth_ = 0;
  QSize size_;
};

}  // namespace carom::render
