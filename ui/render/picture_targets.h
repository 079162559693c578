#pragma once
// The framebuffers of a picture drawn in pieces: two in turn, one drawn while the other is
// shown, so that the view shows the last whole picture until the next one is whole.

#include "ui/render/render_target.h"

#include <QOpenGLFunctions_3_3_Core>

#include <array>

namespace carom::render {

class PictureTargets {
 public:
  // `gl`'s context must be current here, on every call, and when this is destroyed.
  explicit PictureTargets(QOpenGLFunctions_3_3_Core* gl) : targets_{{{gl, 0}, {gl, 0}}} {}

  // True once either framebuffer could not be made: the driver will not make one later either.
  bool failed() const { return targets_[0].failed() || targets_[1].failed(); }
  // The last whole picture; null before the first.
  RenderTarget* shown() { return shown_ >= 0 ? &targets_[shown_] : nullptr; }
  // The one the next picture is drawn into.
  RenderTarget& hidden() { return targets_[shown_ == 0 ? 1 : 0]; }
  // The hidden picture is whole: it shows, and the next is drawn into the other.
  void flip() { shown_ = shown_ == 0 ? 1 : 0; }

 private:
  std::array<RenderTarget, 2> targets_;
  int shown_ = -1;  // into targets_, -1 before the first picture
};

}  // namespace carom::render
