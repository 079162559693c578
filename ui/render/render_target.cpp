#include "ui/render/render_target.h"

#include <QtGlobal>

#include <array>

namespace carom::render {

RenderTarget::RenderTarget(QOpenGLFunctions_3_3_Core* gl, GLint samples)
    : gl_(gl), samples_(samples) {}

RenderTarget::~RenderTarget() {
  release();
}

bool RenderTarget::bind(const QSize& size, GLuint fallback) {
  if (failed_) {
    gl_->glBindFramebuffer(GL_FRAMEBUFFER, fallback);
    return false;
  }
  if (framebuffer_ == 0 || size != size_) {
    release();
    gl_->glGenFramebuffers(1, &framebuffer_);
    std::array<GLuint, 2> buffers{};
    gl_->glGenRenderbuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    color_ = buffers[0];
    depth_ = buffers[1];
    gl_->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_->glBindRenderbuffer(GL_RENDERBUFFER, color_);
    gl_->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, size.width(),
                                          size.height());
    gl_->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    gl_->glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    gl_->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24,
                                          size.width(), size.height());
    gl_->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    gl_->glBindRenderbuffer(GL_RENDERBUFFER, 0);
    size_ = size;
    if (gl_->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      qWarning(samples_ > 0 ? "SceneView: no multisampled framebuffer; drawing without antialiasing"
                            : "SceneView: no framebuffer for drawing in pieces; drawing at once");
      release();
      failed_ = true;
      gl_->glBindFramebuffer(GL_FRAMEBUFFER, fallback);
      return false;
    }
  }
  gl_->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  return true;
}

void RenderTarget::blitTo(GLuint target, QSize targetSize) {
  if (targetSize.isEmpty()) targetSize = size_;
  gl_->glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  gl_->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  // A multisampled source must be resolved at its own size; only a plain one is scaled.
  const GLenum filter = targetSize == size_ || samples_ > 0 ? GL_NEAREST : GL_LINEAR;
  if (samples_ > 0) targetSize = size_;
  gl_->glBlitFramebuffer(0, 0, size_.width(), size_.height(), 0, 0, targetSize.width(),
                         targetSize.height(), GL_COLOR_BUFFER_BIT, filter);
  gl_->glBindFramebuffer(GL_FRAMEBUFFER, target);
}

void RenderTarget::release() {
  if (framebuffer_ == 0) return;
  gl_->glDeleteFramebuffers(1, &framebuffer_);
  const std::array<GLuint, 2> buffers = {color_, depth_};
  gl_->glDeleteRenderbuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  framebuffer_ = color_ = depth_ = 0;
  size_ = QSize();
}

}  // namespace carom::render
