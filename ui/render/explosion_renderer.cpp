#include "ui/render/explosion_renderer.h"

#include "ui/render/gl_util.h"

#include <QImage>
#include <QOpenGLShaderProgram>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace carom::render {
namespace {

constexpr int kSparkTextureSize = 128;
constexpr float kSparkColor[3] = {1.0f, 0.9f, 0.2f};
constexpr int kVerticesPerExplosion = 12;  // two quads, as two triangles each

struct ExplosionInstance {
  Float3 center;
  float halfSize;
  float alpha;
};

// A spark made here rather than loaded: a bright core with a soft glow, and a few rays of
// uneven length so it does not look like a plain blob. Zero at the border, so the quads'
// edges never show.
QImage makeSparkImage() {
  constexpr int kRays = 7;
  constexpr double kRayAngles[kRays] = {0.2, 1.1, 1.9, 2.6, 3.5, 4.4, 5.3};
  constexpr double kRayLengths[kRays] = {0.95, 0.7, 0.9, 0.6, 0.85, 0.75, 0.9};
  QImage image(kSparkTextureSize, kSparkTextureSize, QImage::Format_Grayscale8);
  for (int y = 0; y < kSparkTextureSize; ++y) {
    uchar* line = image.scanLine(y);
    for (int x = 0; x < kSparkTextureSize; ++x) {
      const double dx = (x + 0.5) / kSparkTextureSize * 2.0 - 1.0;
      const double dy = (y + 0.5) / kSparkTextureSize * 2.0 - 1.0;
      const double r = std::hypot(dx, dy);
      const double angle = std::atan2(dy, dx);
      double value = std::exp(-r * r * 60.0) + 0.45 * std::exp(-r * r * 8.0);
      for (int i = 0; i < kRays; ++i) {
        const double across = std::remainder(angle - kRayAngles[i], 2.0 * std::numbers::pi);
        const double along = std::max(0.0, 1.0 - r / kRayLengths[i]);
        // Narrow in angle, so the rays taper towards the centre less than a wedge would.
        value += 0.7 * along * along * std::exp(-std::pow(across * r * 40.0, 2.0));
      }
      const double edge = std::clamp((1.0 - r) / 0.1, 0.0, 1.0);
      line[x] = static_cast<uchar>(std::lround(255.0 * std::clamp(value, 0.0, 1.0) * edge));
    }
  }
  return image;
}

}  // namespace

ExplosionRenderer::ExplosionRenderer(QOpenGLFunctions_3_3_Core* gl)
    : gl_(gl), program_(buildProgram("explosion")) {
  std::array<GLuint, 2> buffers{};
  gl_->glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  cornerBuffer_ = buffers[0];
  instanceBuffer_ = buffers[1];
  gl_->glGenVertexArrays(1, &vao_);

  std::vector<Float3> corners;
  for (float quad : {0.0f, 1.0f}) {
    corners.insert(corners.end(), {{-1.0f, -1.0f, quad},
                                   {1.0f, -1.0f, quad},
                                   {1.0f, 1.0f, quad},
                                   {-1.0f, -1.0f, quad},
                                   {1.0f, 1.0f, quad},
                                   {-1.0f, 1.0f, quad}});
  }
  uploadBuffer(gl_, cornerBuffer_, corners, GL_STATIC_DRAW);

  gl_->glBindVertexArray(vao_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, cornerBuffer_);
  vertexAttribute(gl_, 0, 3, GL_FLOAT, sizeof(Float3), 0, false);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
  vertexAttribute(gl_, 1, 3, GL_FLOAT, sizeof(ExplosionInstance),
                  offsetof(ExplosionInstance, center), true);
  vertexAttribute(gl_, 2, 1, GL_FLOAT, sizeof(ExplosionInstance),
                  offsetof(ExplosionInstance, halfSize), true);
  vertexAttribute(gl_, 3, 1, GL_FLOAT, sizeof(ExplosionInstance),
                  offsetof(ExplosionInstance, alpha), true);
  gl_->glBindVertexArray(0);

  createSparkTexture();
}

ExplosionRenderer::~ExplosionRenderer() {
  program_.reset();
  const std::array<GLuint, 2> buffers = {cornerBuffer_, instanceBuffer_};
  gl_->glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  gl_->glDeleteVertexArrays(1, &vao_);
  gl_->glDeleteTextures(1, &sparkTexture_);
}

void ExplosionRenderer::createSparkTexture() {
  const QImage spark = makeSparkImage();
  gl_->glGenTextures(1, &sparkTexture_);
  gl_->glBindTexture(GL_TEXTURE_2D, sparkTexture_);
  // QImage may pad its lines; tell GL their real length (one byte a pixel here).
  gl_->glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_->glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(spark.bytesPerLine()));
  gl_->glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, spark.width(), spark.height(), 0, GL_RED,
                    GL_UNSIGNED_BYTE, spark.constBits());
  gl_->glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl_->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Mipmaps, because a distant spark covers only a few pixels.
  gl_->glGenerateMipmap(GL_TEXTURE_2D);
  // One mipmap level at a time: half the texture reads of blending two, and sparks are soft.
  gl_->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  gl_->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl_->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl_->glBindTexture(GL_TEXTURE_2D, 0);
}

void ExplosionRenderer::draw(const QMatrix4x4& viewProjection, const QVector3D& eye,
                             const std::vector<ExplosionPool::Live>& live) {
  if (live.empty()) return;
  std::vector<ExplosionInstance> instances;
  instances.reserve(live.size());
  for (const ExplosionPool::Live& e : live) {
    instances.push_back(
        {toFloat3(e.centre), static_cast<float>(e.scale), static_cast<float>(e.alpha)});
  }
  uploadBuffer(gl_, instanceBuffer_, instances, GL_STREAM_DRAW);

  program_->bind();
  program_->setUniformValue("viewProjection", viewProjection);
  program_->setUniformValue("eyePosition", eye);
  program_->setUniformValue("spark", 0);
  program_->setUniformValue("sparkColor",
                            QVector3D(kSparkColor[0], kSparkColor[1], kSparkColor[2]));
  gl_->glActiveTexture(GL_TEXTURE0);
  gl_->glBindTexture(GL_TEXTURE_2D, sparkTexture_);
  gl_->glBindVertexArray(vao_);
  // Additive light: hidden behind balls and walls by the depth test, but not writing depth, so
  // sparks never hide each other. Both sides of each quad show. Alpha stays 1 in the image.
  gl_->glDisable(GL_CULL_FACE);
  gl_->glEnable(GL_BLEND);
  gl_->glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  gl_->glDepthMask(GL_FALSE);
  gl_->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  gl_->glDrawArraysInstanced(GL_TRIANGLES, 0, kVerticesPerExplosion,
                             static_cast<GLsizei>(instances.size()));
  gl_->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_->glDepthMask(GL_TRUE);
  gl_->glDisable(GL_BLEND);
  gl_->glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace carom::render
