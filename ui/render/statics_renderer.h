#pragma once
// The GL side of the scene's fixed shapes: planes as triangles with a grid, cylinders and boxes
// as one mesh each drawn once per instance, all uploaded when the scene or the selection
// changes. Infinite planes and cylinders fade out beyond the scene's bounds.

#include "ui/render/frame_camera.h"
#include "ui/render/render_scene.h"

#include <QOpenGLFunctions_3_3_Core>

#include <memory>
#include <vector>

class QOpenGLShaderProgram;

namespace carom::render {

class StaticsRenderer {
 public:
  // Makes its GL objects in `gl`'s context, which must be current here, on every call, and when
  // this is destroyed.
  explicit StaticsRenderer(QOpenGLFunctions_3_3_Core* gl);
  ~StaticsRenderer();
  StaticsRenderer(const StaticsRenderer&) = delete;
  StaticsRenderer& operator=(const StaticsRenderer&) = delete;

  // The shapes of `scene` (none when null), the ones listed in the selection's colour (indices
  // into its planes, cylinders and boxes).
  void upload(const RenderScene* scene, const std::vector<int>& highlightedPlanes,
              const std::vector<int>& highlightedCylinders,
              const std::vector<int>& highlightedBoxes);
  // Cylinders, boxes and planes, fading beyond the bounds of `scene`; leaves face culling on.
  void draw(const FrameCamera& frame, const RenderScene* scene);

 private:
  void createPlaneBuffers();
  void createCylinderBuffers();
  void createCylinderMesh();
  void createBoxBuffers();
  // The fading of infinite shapes beyond the scene's bounds (lighting.glsl), for a bound program.
  void setFadeBeyondBounds(QOpenGLShaderProgram& program, const RenderScene* scene);

  QOpenGLFunctions_3_3_Core* gl_;
  std::unique_ptr<QOpenGLShaderProgram> planeProgram_;
  std::unique_ptr<QOpenGLShaderProgram> cylinderProgram_;
  std::unique_ptr<QOpenGLShaderProgram> boxProgram_;
  GLuint planeVao_ = 0;
  GLuint cylinderVao_ = 0;
  GLuint boxVao_ = 0;
  GLuint planeVertexBuffer_ = 0;
  GLuint cylinderVertexBuffer_ = 0;
  GLuint cylinderInstanceBuffer_ = 0;
  GLuint boxVertexBuffer_ = 0;
  GLuint boxInstanceBuffer_ = 0;
  int planeVertexCount_ = 0;
  int cylinderVertexCount_ = 0;
  int cylinderInstanceCount_ = 0;
  int boxVertexCount_ = 0;
  int boxInstanceCount_ = 0;
  float boxGridSpacing_ = 1.0f;
};

}  // namespace carom::render
