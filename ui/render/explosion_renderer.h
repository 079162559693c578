#pragma once
// The GL side of the explosions (ExplosionPool keeps the bookkeeping): every live spark in one
// instanced draw of two crossed, textured quads, added to the light of what lies behind.

#include "ui/render/explosion_pool.h"

#include <QMatrix4x4>
#include <QOpenGLFunctions_3_3_Core>
#include <QVector3D>

#include <memory>
#include <vector>

class QOpenGLShaderProgram;

namespace carom::render {

class ExplosionRenderer {
 public:
  // Makes its GL objects in `gl`'s context, which must be current here and when destroyed.
  explicit ExplosionRenderer(QOpenGLFunctions_3_3_Core* gl);
  ~ExplosionRenderer();
  ExplosionRenderer(const ExplosionRenderer&) = delete;
  ExplosionRenderer& operator=(const ExplosionRenderer&) = delete;

  // Depth-tested against what is drawn already; leaves no blending or texture bound.
  void draw(const QMatrix4x4& viewProjection, const QVector3D& eye,
            const std::vector<ExplosionPool::Live>& live);

 private:
  void createSparkTexture();

  QOpenGLFunctions_3_3_Core* gl_;
  std::unique_ptr<QOpenGLShaderProgram> program_;
  GLuint vao_ = 0;
  GLuint cornerBuffer_ = 0;
  GLuint instanceBuffer_ = 0;
  GLuint sparkTexture_ = 0;
};

}  // namespace carom::render
