#include "ui/render/statics_renderer.h"

#include "ui/render/gl_util.h"
#include "ui/render/view_vertices.h"

#include <QOpenGLShaderProgram>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>

namespace carom::render {
namespace {

// ---- Vertex layouts -----------------------------------------------------------------------------

// Selected planes, cylinders and boxes take on the selection's colour.
QColor shown(const QColor& color, bool selected) {
  if (!selected) return color;
  return QColor((color.red() + kSelectionColor.red()) / 2,
                (color.green() + kSelectionColor.green()) / 2,
                (color.blue() + kSelectionColor.blue()) / 2);
}

struct PlaneVertex {
  Float3 position;
  Float3 normal;
  float grid[2];
  PackedColor color;
};

struct CylinderVertex {
  Float3 local;
  Float3 normal;
};

struct CylinderInstance {
  Float3 start;
  Float3 end;
  float radius;
  PackedColor color;
};

struct BoxVertex {
  Float3 local;
  Float3 normal;
};

struct BoxInstance {
  Float3 center;
  Float3 halfAxes[3];
  PackedColor color;
};

// ---- Meshes -------------------------------------------------------------------------------------

constexpr int kCylinderSegments = 40;

QVector3D toQVector(const Vec3& v) {
  return QVector3D(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
}

}  // namespace

StaticsRenderer::StaticsRenderer(QOpenGLFunctions_3_3_Core* gl)
    : gl_(gl),
      planeProgram_(buildProgram("plane")),
      cylinderProgram_(buildProgram("cylinder")),
      boxProgram_(buildProgram("box", "plane")) {
  createPlaneBuffers();
  createCylinderBuffers();
  createBoxBuffers();
}

StaticsRenderer::~StaticsRenderer() {
  planeProgram_.reset();
  cylinderProgram_.reset();
  boxProgram_.reset();
  const std::array<GLuint, 5> buffers = {planeVertexBuffer_, cylinderVertexBuffer_,
                                         cylinderInstanceBuffer_, boxVertexBuffer_,
                                         boxInstanceBuffer_};
  gl_->glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  const std::array<GLuint, 3> arrays = {planeVao_, cylinderVao_, boxVao_};
  gl_->glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
}

void StaticsRenderer::createPlaneBuffers() {
  gl_->glGenBuffers(1, &planeVertexBuffer_);
  gl_->glGenVertexArrays(1, &planeVao_);
  gl_->glBindVertexArray(planeVao_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, planeVertexBuffer_);
  vertexAttribute(gl_, 0, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, position), false);
  vertexAttribute(gl_, 1, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, normal), false);
  vertexAttribute(gl_, 2, 2, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, grid), false);
  vertexAttribute(gl_, 3, 4, GL_UNSIGNED_BYTE, sizeof(PlaneVertex), offsetof(PlaneVertex, color),
                  false);
  gl_->glBindVertexArray(0);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// One mesh, drawn once per cylinder with the cylinder's ends, radius and colour per instance.
void StaticsRenderer::createCylinderBuffers() {
  std::array<GLuint, 2> buffers{};
  gl_->glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  cylinderVertexBuffer_ = buffers[0];
  cylinderInstanceBuffer_ = buffers[1];
  gl_->glGenVertexArrays(1, &cylinderVao_);
  createCylinderMesh();
  gl_->glBindVertexArray(cylinderVao_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, cylinderVertexBuffer_);
  vertexAttribute(gl_, 0, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, local),
                  false);
  vertexAttribute(gl_, 1, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, normal),
                  false);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, cylinderInstanceBuffer_);
  const std::array<std::pair<GLint, std::size_t>, 3> floatFields = {
      std::pair<GLint, std::size_t>{3, offsetof(CylinderInstance, start)},
      {3, offsetof(CylinderInstance, end)},
      {1, offsetof(CylinderInstance, radius)}};
  for (GLuint location = 2; const auto& [components, offset] : floatFields) {
    vertexAttribute(gl_, location, components, GL_FLOAT, sizeof(CylinderInstance), offset, true);
    ++location;
  }
  vertexAttribute(gl_, 5, 4, GL_UNSIGNED_BYTE, sizeof(CylinderInstance),
                  offsetof(CylinderInstance, color), true);
  gl_->glBindVertexArray(0);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void StaticsRenderer::createCylinderMesh() {
  // A unit cylinder with both ends closed: clipped at the horizon, its cut faces show (faded).
  std::vector<CylinderVertex> vertices;
  const auto ring = [](int segment) {
    const double angle = 2.0 * std::numbers::pi * segment / kCylinderSegments;
    return std::pair<float, float>(static_cast<float>(std::cos(angle)),
                                   static_cast<float>(std::sin(angle)));
  };
  for (int segment = 0; segment < kCylinderSegments; ++segment) {
    const auto [x0, y0] = ring(segment);
    const auto [x1, y1] = ring(segment + 1);
    const CylinderVertex bottom0{{x0, y0, 0.0f}, {x0, y0, 0.0f}};
    const CylinderVertex bottom1{{x1, y1, 0.0f}, {x1, y1, 0.0f}};
    const CylinderVertex top0{{x0, y0, 1.0f}, {x0, y0, 0.0f}};
    const CylinderVertex top1{{x1, y1, 1.0f}, {x1, y1, 0.0f}};
    vertices.insert(vertices.end(), {bottom0, bottom1, top1, bottom0, top1, top0});
    const Float3 up{0.0f, 0.0f, 1.0f};
    const Float3 down{0.0f, 0.0f, -1.0f};
    vertices.insert(vertices.end(),
                    {CylinderVertex{{0.0f, 0.0f, 1.0f}, up}, CylinderVertex{{x0, y0, 1.0f}, up},
                     CylinderVertex{{x1, y1, 1.0f}, up}});
    vertices.insert(vertices.end(),
                    {CylinderVertex{{0.0f, 0.0f, 0.0f}, down}, CylinderVertex{{x1, y1, 0.0f}, down},
                     CylinderVertex{{x0, y0, 0.0f}, down}});
  }
  cylinderVertexCount_ = static_cast<int>(vertices.size());
  uploadBuffer(gl_, cylinderVertexBuffer_, vertices, GL_STATIC_DRAW);
}

// One cube, drawn once per box with its centre, half axes and colour per instance.
void StaticsRenderer::createBoxBuffers() {
  std::array<GLuint, 2> buffers{};
  gl_->glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  boxVertexBuffer_ = buffers[0];
  boxInstanceBuffer_ = buffers[1];
  gl_->glGenVertexArrays(1, &boxVao_);
  // Each face from its outward normal n and two directions u, v with u x v = n, so that its
  // corners run counter-clockwise seen from outside.
  std::vector<BoxVertex> vertices;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {-1.0f, 1.0f}) {
      Vec3 n = Vec3::Zero(), u = Vec3::Zero();
      n[axis] = side;
      u[(axis + 1) % 3] = 1.0;
      const Vec3 v = n.cross(u);
      const auto corner = [&](double a, double b) {
        return BoxVertex{toFloat3(n + a * u + b * v), toFloat3(n)};
      };
      vertices.insert(vertices.end(), {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, -1),
                                       corner(1, 1), corner(-1, 1)});
    }
  }
  boxVertexCount_ = static_cast<int>(vertices.size());
  uploadBuffer(gl_, boxVertexBuffer_, vertices, GL_STATIC_DRAW);
  gl_->glBindVertexArray(boxVao_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, boxVertexBuffer_);
  vertexAttribute(gl_, 0, 3, GL_FLOAT, sizeof(BoxVertex), offsetof(BoxVertex, local), false);
  vertexAttribute(gl_, 1, 3, GL_FLOAT, sizeof(BoxVertex), offsetof(BoxVertex, normal), false);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, boxInstanceBuffer_);
  vertexAttribute(gl_, 2, 3, GL_FLOAT, sizeof(BoxInstance), offsetof(BoxInstance, center), true);
  for (GLuint k = 0; k < 3; ++k)
    vertexAttribute(gl_, 3 + k, 3, GL_FLOAT, sizeof(BoxInstance),
                    offsetof(BoxInstance, halfAxes) + k * sizeof(Float3), true);
  vertexAttribute(gl_, 6, 4, GL_UNSIGNED_BYTE, sizeof(BoxInstance), offsetof(BoxInstance, color),
                  true);
  gl_->glBindVertexArray(0);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void StaticsRenderer::upload(const RenderScene* scene, const std::vector<int>& highlightedPlanes,
                             const std::vector<int>& highlightedCylinders,
                             const std::vector<int>& highlightedBoxes) {
  std::vector<PlaneVertex> planeVertices;
  std::vector<CylinderInstance> cylinders;
  std::vector<BoxInstance> boxes;
  if (scene) {
    const std::vector<bool> selectedPlanes = membership(highlightedPlanes, scene->planes.size());
    const std::vector<bool> selectedCylinders =
        membership(highlightedCylinders, scene->cylinders.size());
    const double spacing = scene->gridSpacing > 0.0 ? scene->gridSpacing : 1.0;
    for (std::size_t index = 0; index < scene->planes.size(); ++index) {
      const RenderPlane& plane = scene->planes[index];
      if (plane.polygon.size() < 3) continue;
      const PackedColor color = pack(shown(plane.color, selectedPlanes[index]));
      // Grid axes in the plane, the same construction for every point so cells line up.
      int leastAxis = 0;
      plane.normal.cwiseAbs().minCoeff(&leastAxis);
      const Vec3 u = plane.normal.cross(Vec3::Unit(leastAxis)).normalized();
      const Vec3 v = plane.normal.cross(u);
      const auto vertex = [&](const Vec3& p) {
        return PlaneVertex{
            toFloat3(p),
            toFloat3(plane.normal),
            {static_cast<float>(p.dot(u) / spacing), static_cast<float>(p.dot(v) / spacing)},
            color};
      };
      for (std::size_t i = 1; i + 1 < plane.polygon.size(); ++i) {
        planeVertices.push_back(vertex(plane.polygon[0]));
        planeVertices.push_back(vertex(plane.polygon[i]));
        planeVertices.push_back(vertex(plane.polygon[i + 1]));
      }
    }
    for (std::size_t index = 0; index < scene->cylinders.size(); ++index) {
      const RenderCylinder& cylinder = scene->cylinders[index];
      if ((cylinder.end - cylinder.start).norm() == 0.0) continue;  // misses the horizon
      cylinders.push_back({toFloat3(cylinder.start), toFloat3(cylinder.end),
                           static_cast<float>(cylinder.radius),
                           pack(shown(cylinder.color, selectedCylinders[index]))});
    }
    const std::vector<bool> selectedBoxes = membership(highlightedBoxes, scene->boxes.size());
    for (std::size_t index = 0; index < scene->boxes.size(); ++index) {
      const RenderBox& box = scene->boxes[index];
      boxes.push_back(
          {toFloat3(box.center),
           {toFloat3(box.halfAxes[0]), toFloat3(box.halfAxes[1]), toFloat3(box.halfAxes[2])},
           pack(shown(box.color, selectedBoxes[index]))});
    }
    boxGridSpacing_ = static_cast<float>(scene->gridSpacing > 0.0 ? scene->gridSpacing : 1.0);
  }
  uploadBuffer(gl_, planeVertexBuffer_, planeVertices, GL_STATIC_DRAW);
  uploadBuffer(gl_, cylinderInstanceBuffer_, cylinders, GL_STATIC_DRAW);
  planeVertexCount_ = static_cast<int>(planeVertices.size());
  cylinderInstanceCount_ = static_cast<int>(cylinders.size());
  uploadBuffer(gl_, boxInstanceBuffer_, boxes, GL_STATIC_DRAW);
  boxInstanceCount_ = static_cast<int>(boxes.size());
}

void StaticsRenderer::setFadeBeyondBounds(QOpenGLShaderProgram& program, const RenderScene* scene) {
  if (!scene) return;
  const Bounds& bounds = scene->bounds;
  program.setUniformValue("boundsMin", toQVector(bounds.min));
  program.setUniformValue("boundsMax", toQVector(bounds.max));
  program.setUniformValue("fadeLength", static_cast<float>(kFadeRadii * bounds.radius()));
  program.setUniformValue("backgroundColor", kBackground);
}

void StaticsRenderer::draw(const FrameCamera& frame, const RenderScene* scene) {
  // Also hides the walls seen from outside (their front faces point into the room), which is
  // what lets the camera look in from beyond them.
  gl_->glEnable(GL_CULL_FACE);
  if (cylinderInstanceCount_ > 0) {
    useProgram(*cylinderProgram_, frame);
    setFadeBeyondBounds(*cylinderProgram_, scene);
    gl_->glBindVertexArray(cylinderVao_);
    gl_->glDrawArraysInstanced(GL_TRIANGLES, 0, cylinderVertexCount_, cylinderInstanceCount_);
  }
  if (boxInstanceCount_ > 0) {
    useProgram(*boxProgram_, frame);
    boxProgram_->setUniformValue("gridSpacing", boxGridSpacing_);
    gl_->glBindVertexArray(boxVao_);
    gl_->glDrawArraysInstanced(GL_TRIANGLES, 0, boxVertexCount_, boxInstanceCount_);
  }
  if (planeVertexCount_ > 0) {
    useProgram(*planeProgram_, frame);
    setFadeBeyondBounds(*planeProgram_, scene);
    gl_->glBindVertexArray(planeVao_);
    // Pushed back by a step of depth, so that lines lying in a plane (the axes) show on it.
    gl_->glEnable(GL_POLYGON_OFFSET_FILL);
    gl_->glPolygonOffset(1.0f, 1.0f);
    gl_->glDrawArrays(GL_TRIANGLES, 0, planeVertexCount_);
    gl_->glDisable(GL_POLYGON_OFFSET_FILL);
  }
}

}  // namespace carom::render
