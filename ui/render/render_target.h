#pragma once
// A framebuffer of colour and depth renderbuffers, multisampled or not: the view draws into one
// when antialiasing is on, and into two in turn when it draws a picture in pieces. Made on first
// use and again on resize.

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

namespace carom::render {

class RenderTarget {
 public:
  // `samples` 0 is a plain framebuffer. `gl`'s context must be current here, on every call, and
  // when this is destroyed.
  RenderTarget(QOpenGLFunctions_3_3_Core* gl, GLint samples);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // 0 once the framebuffer could not be made.
  GLint samples() const { return failed_ ? 0 : samples_; }
  // True once a framebuffer could not be made: the driver will not make one later either.
  bool failed() const { return failed_; }
  QSize size() const { return size_; }
  GLuint framebuffer() const { return framebuffer_; }  // 0 until bound
  // Binds the framebuffer, made or resized to `size` device pixels; when it cannot be made,
  // binds `fallback` instead and returns false.
  bool bind(const QSize& size, GLuint fallback);
  // Copies (resolves) what was drawn into `target`, which is left bound, scaled to
  // `targetSize` (its own size when empty).
  void blitTo(GLuint target, QSize targetSize = QSize());

 private:
  void release();

  QOpenGLFunctions_3_3_Core* gl_;
  GLint samples_;
  bool failed_ = false;
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  GLuint depth_ = 0;
  QSize size_;
};

}  // namespace carom::render
