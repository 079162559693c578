#pragma once
// Plain lines in one colour each: the world's axes, the editor's handle arrows, the watched
// balls' velocity arrows and trails, which share one program and one streamed buffer; and flat
// triangles on the screen (the markers of balls outside the view) through the same.

#include "sim/model/scene.h"
#include "ui/render/bounds.h"
#include "ui/render/gl_util.h"

#include <QColor>
#include <QMatrix4x4>
#include <QOpenGLFunctions_3_3_Core>
#include <QVector3D>

#include <memory>
#include <vector>

class QOpenGLShaderProgram;

namespace carom::render {

class LineRenderer {
 public:
  // Makes its GL objects in `gl`'s context, which must be current here and when destroyed.
  explicit LineRenderer(QOpenGLFunctions_3_3_Core* gl);
  ~LineRenderer();
  LineRenderer(const LineRenderer&) = delete;
  LineRenderer& operator=(const LineRenderer&) = delete;

  // The x, y and z axes through the origin, red, green and blue, across `bounds`.
  void drawAxes(const QMatrix4x4& viewProjection, const Bounds& bounds);
  // From `from` to `to` with two barbs at the tip, on top of everything.
  void drawArrow(const QMatrix4x4& viewProjection, const QVector3D& eye, const Vec3& from,
                 const Vec3& to, const QColor& color);
  // A line through `points` in order, hidden where the scene is in front of it.
  void drawPath(const QMatrix4x4& viewProjection, const std::vector<Vec3>& points,
                const QColor& color);
  // Filled triangles given in normalized device coordinates (three vertices each), on top of
  // everything: marks on the picture itself rather than in the scene.
  void drawScreenTriangles(const std::vector<Float3>& vertices, const QColor& color);

 private:
  QOpenGLFunctions_3_3_Core* gl_;
  std::unique_ptr<QOpenGLShaderProgram> program_;
  GLuint vao_ = 0;
  GLuint buffer_ = 0;
};

}  // namespace carom::render
