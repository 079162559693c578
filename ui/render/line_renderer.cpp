#include "ui/render/line_renderer.h"

#include "ui/render/gl_util.h"
#include "ui/render/render_scene.h"

#include <QOpenGLShaderProgram>

#include <cstddef>
#include <vector>

namespace carom::render {
namespace {

// As in most 3D tools.
const QColor kAxisColors[3] = {QColor(214, 69, 65), QColor(90, 180, 90), QColor(70, 120, 220)};

QVector3D rgb(const QColor& color) {
  return QVector3D(color.redF(), color.greenF(), color.blueF());
}

}  // namespace

LineRenderer::LineRenderer(QOpenGLFunctions_3_3_Core* gl)
    : gl_(gl), program_(buildProgram("line")) {
  gl_->glGenVertexArrays(1, &vao_);
  gl_->glGenBuffers(1, &buffer_);
  gl_->glBindVertexArray(vao_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  vertexAttribute(gl_, 0, 3, GL_FLOAT, sizeof(Float3), 0, false);
  gl_->glBindVertexArray(0);
}

LineRenderer::~LineRenderer() {
  program_.reset();
  gl_->glDeleteBuffers(1, &buffer_);
  gl_->glDeleteVertexArrays(1, &vao_);
}

void LineRenderer::drawAxes(const QMatrix4x4& viewProjection, const Bounds& bounds) {
  std::vector<Float3> lines;
  std::vector<QColor> colors;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 start;
    Vec3 end;
    if (!clipLineToBounds(Vec3::Zero(), Vec3::Unit(axis), bounds, &start, &end)) continue;
    lines.insert(lines.end(), {toFloat3(start), toFloat3(end)});
    colors.push_back(kAxisColors[axis]);
  }
  if (lines.empty()) return;
  uploadBuffer(gl_, buffer_, lines, GL_STREAM_DRAW);
  program_->bind();
  program_->setUniformValue("viewProjection", viewProjection);
  gl_->glBindVertexArray(vao_);
  // The x and z axes lie in a floor at y = 0, which is drawn pushed back a little for them.
  gl_->glDepthFunc(GL_LEQUAL);
  for (std::size_t i = 0; i < colors.size(); ++i) {
    program_->setUniformValue("lineColor", rgb(colors[i]));
    gl_->glDrawArrays(GL_LINES, static_cast<GLint>(2 * i), 2);
  }
  gl_->glDepthFunc(GL_LESS);
}

void LineRenderer::drawArrow(const QMatrix4x4& viewProjection, const QVector3D& eye,
                             const Vec3& from, const Vec3& to, const QColor& color) {
  const Vec3 shaft = to - from;
  const double length = shaft.norm();
  if (length <= 0.0) return;
  // Two barbs at the tip, in the plane of the shaft and the line of sight.
  const Vec3 direction = shaft / length;
  Vec3 side = direction.cross(Vec3(eye.x(), eye.y(), eye.z()) - to);
  side = side.norm() > 0.0 ? side.normalized() : direction.unitOrthogonal();
  const double barb = 0.2 * length;
  const std::vector<Float3> lines = {
      toFloat3(from), toFloat3(to),
      toFloat3(to),   toFloat3(to - barb * direction + 0.5 * barb * side),
      toFloat3(to),   toFloat3(to - barb * direction - 0.5 * barb * side)};
  uploadBuffer(gl_, buffer_, lines, GL_STREAM_DRAW);
  program_->bind();
  program_->setUniformValue("viewProjection", viewProjection);
  program_->setUniformValue("lineColor", rgb(color));
  gl_->glBindVertexArray(vao_);
  gl_->glDisable(GL_DEPTH_TEST);
  gl_->glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  gl_->glEnable(GL_DEPTH_TEST);
}

void LineRenderer::drawPath(const QMatrix4x4& viewProjection, const std::vector<Vec3>& points,
                            const QColor& color) {
  if (points.size() < 2) return;
  std::vector<Float3> vertices;
  vertices.reserve(points.size());
  for (const Vec3& point : points) vertices.push_back(toFloat3(point));
  uploadBuffer(gl_, buffer_, vertices, GL_STREAM_DRAW);
  program_->bind();
  program_->setUniformValue("viewProjection", viewProjection);
  program_->setUniformValue("lineColor", rgb(color));
  gl_->glBindVertexArray(vao_);
  gl_->glDrawArrays(GL_LINE_STRIP, 0, static_cast<GLsizei>(vertices.size()));
}

void LineRenderer::drawScreenTriangles(const std::vector<Float3>& vertices, const QColor& color) {
  if (vertices.size() < 3) return;
  uploadBuffer(gl_, buffer_, vertices, GL_STREAM_DRAW);
  program_->bind();
  program_->setUniformValue("viewProjection", QMatrix4x4());
  program_->setUniformValue("lineColor", rgb(color));
  gl_->glBindVertexArray(vao_);
  gl_->glDisable(GL_DEPTH_TEST);
  gl_->glDisable(GL_CULL_FACE);
  gl_->glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  gl_->glEnable(GL_DEPTH_TEST);
}

}  // namespace carom::render
