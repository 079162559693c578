#include "scene_view.h"

#include <QElapsedTimer>
#include <QImage>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

namespace carom::render {
namespace {

// ---- Shaders ------------------------------------------------------------------------------------

// Shared by every fragment shader: one sun-like light plus a sky/ground ambient term, so faces
// turned away from the light still show their shape.
constexpr const char* kLightingGlsl = R"(
uniform vec3 eyePosition;
uniform vec3 lightDirection;  // towards the light, unit length

vec3 shade(vec3 base, vec3 normal, vec3 position, float shininess, float specularStrength) {
  vec3 n = normalize(normal);
  vec3 toEye = normalize(eyePosition - position);
  vec3 ambient = mix(vec3(0.30, 0.28, 0.27), vec3(0.46, 0.48, 0.52), 0.5 + 0.5 * n.y);
  float diffuse = max(dot(n, lightDirection), 0.0);
  vec3 halfway = normalize(lightDirection + toEye);
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  return base * (ambient + 0.62 * diffuse) + vec3(specularStrength * highlight);
}
)";

// Balls are ray-cast: one camera-facing square per ball, just large enough to hold the
// sphere's outline, and the fragment shader finds the sphere's surface and depth inside it.
// Four vertices a ball instead of a mesh keeps thousands of balls cheap on software renderers.
constexpr const char* kBallVertexGlsl = R"(#version 330 core
layout(location = 0) in vec2 corner;  // of the square, in [-1, 1]
layout(location = 1) in vec3 center;
layout(location = 2) in float radius;
layout(location = 3) in vec4 color;
uniform mat4 viewProjection;
uniform vec3 eyePosition;
uniform float pixelAngle;  // view height over distance, per device pixel
out vec2 outline;          // position in the square; the sphere's outline is the unit circle
out vec3 squarePosition;
flat out vec3 sphereCenter;
flat out float sphereRadius;
flat out vec3 baseColor;
void main() {
  vec3 toCenter = center - eyePosition;
  float distance = length(toCenter);
  sphereCenter = center;
  sphereRadius = radius;
  baseColor = color.rgb;
  if (distance <= radius * 1.0001) {  // the eye is inside: nothing sensible to draw
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec3 forward = toCenter / distance;
  vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(forward, helper));
  vec3 up = cross(right, forward);
  // The cone of rays touching the sphere cuts the plane through its centre in this circle.
  float outlineRadius = radius * distance / sqrt(distance * distance - radius * radius);
  // Plus a pixel and a half, for the soft edge.
  float halfSize = outlineRadius + 1.5 * pixelAngle * distance;
  outline = corner * (halfSize / outlineRadius);
  squarePosition = center + halfSize * (corner.x * right + corner.y * up);
  gl_Position = viewProjection * vec4(squarePosition, 1.0);
}
)";

constexpr const char* kBallFragmentGlsl = R"(
uniform mat4 viewProjection;
in vec2 outline;
in vec3 squarePosition;
flat in vec3 sphereCenter;
flat in float sphereRadius;
flat in vec3 baseColor;
out vec4 fragColor;
void main() {
  // Coverage of this pixel by the outline, which alpha-to-coverage turns into samples.
  float pixelsPerUnit = 1.0 / max(length(vec2(dFdx(outline.x), dFdy(outline.x))), 1e-6);
  float coverage = clamp((1.0 - length(outline)) * pixelsPerUnit + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;

  vec3 ray = normalize(squarePosition - eyePosition);
  vec3 fromCenter = eyePosition - sphereCenter;
  float b = dot(fromCenter, ray);
  float c = dot(fromCenter, fromCenter) - sphereRadius * sphereRadius;
  // Rays that just miss (the soft edge) use the grazing point.
  float t = -b - sqrt(max(b * b - c, 0.0));
  vec3 hit = eyePosition + t * ray;
  vec4 clip = viewProjection * vec4(hit, 1.0);
  gl_FragDepth = 0.5 + 0.5 * clip.z / clip.w;
  vec3 normal = (hit - sphereCenter) / sphereRadius;
  fragColor = vec4(shade(baseColor, normal, hit, 40.0, 0.35), coverage);
}
)";

constexpr const char* kPlaneVertexGlsl = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 gridCoordinate;  // in grid cells
layout(location = 3) in vec4 color;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec2 grid;
out vec3 baseColor;
void main() {
  worldPosition = position;
  worldNormal = normal;
  grid = gridCoordinate;
  baseColor = color.rgb;
  gl_Position = viewProjection * vec4(position, 1.0);
}
)";

// A faint checker with thin lines on the cell borders. Both fade out where a cell shrinks to a
// few pixels, before they would shimmer.
constexpr const char* kPlaneFragmentGlsl = R"(
in vec3 worldPosition;
in vec3 worldNormal;
in vec2 grid;
in vec3 baseColor;
out vec4 fragColor;
void main() {
  vec2 cellsPerPixel = fwidth(grid);
  float fade = 1.0 - smoothstep(0.15, 0.5, max(cellsPerPixel.x, cellsPerPixel.y));
  vec2 fromLine = abs(fract(grid + 0.5) - 0.5);
  vec2 onLine = 1.0 - smoothstep(0.5 * cellsPerPixel, 1.5 * cellsPerPixel, fromLine);
  float line = max(onLine.x, onLine.y);
  float dark = mod(floor(grid.x) + floor(grid.y), 2.0);
  vec3 textured = baseColor * (1.0 - fade * (0.06 * dark + 0.14 * line));
  fragColor = vec4(shade(textured, worldNormal, worldPosition, 16.0, 0.04), 1.0);
}
)";

constexpr const char* kCylinderVertexGlsl = R"(#version 330 core
layout(location = 0) in vec3 local;  // unit circle in x, y; 0 to 1 along the axis in z
layout(location = 1) in vec3 localNormal;
layout(location = 2) in vec3 start;
layout(location = 3) in vec3 end;
layout(location = 4) in float radius;
layout(location = 5) in vec4 color;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec3 baseColor;
void main() {
  vec3 axis = end - start;
  vec3 w = normalize(axis);
  // Any direction across the axis will do; the world axis least like it keeps this stable.
  vec3 helper = abs(w.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(w, helper));
  vec3 v = cross(w, u);
  worldPosition = start + radius * (local.x * u + local.y * v) + local.z * axis;
  worldNormal = localNormal.x * u + localNormal.y * v + localNormal.z * w;
  baseColor = color.rgb;
  gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
)";

constexpr const char* kCylinderFragmentGlsl = R"(
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 baseColor;
out vec4 fragColor;
void main() {
  fragColor = vec4(shade(baseColor, worldNormal, worldPosition, 24.0, 0.18), 1.0);
}
)";

// Explosions: per instance, two perpendicular quads. Both contain the view's up direction and
// meet the line of sight at 45 degrees, so neither is ever seen edge-on.
constexpr const char* kExplosionVertexGlsl = R"(#version 330 core
layout(location = 0) in vec3 corner;  // x, y in [-1, 1] across a quad; z: which quad, 0 or 1
layout(location = 1) in vec3 center;
layout(location = 2) in float halfSize;
layout(location = 3) in float alpha;
uniform mat4 viewProjection;
uniform vec3 eyePosition;
out vec2 sparkCoordinate;
out float fade;
void main() {
  vec3 toCenter = center - eyePosition;
  float distance = length(toCenter);
  vec3 forward = distance > 1e-6 ? toCenter / distance : vec3(0.0, 0.0, -1.0);
  vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(forward, helper));
  vec3 up = cross(right, forward);
  vec3 across = 0.70710678 * (corner.z < 0.5 ? right + forward : right - forward);
  sparkCoordinate = 0.5 + 0.5 * corner.xy;
  fade = alpha;
  gl_Position = viewProjection * vec4(center + halfSize * (corner.x * across + corner.y * up), 1.0);
}
)";

constexpr const char* kExplosionFragmentGlsl = R"(
uniform sampler2D spark;
uniform vec3 sparkColor;
in vec2 sparkCoordinate;
in float fade;
out vec4 fragColor;
void main() {
  // With additive blending this adds sparkColor times the spark's brightness and the fade.
  fragColor = vec4(sparkColor, texture(spark, sparkCoordinate).r * fade);
}
)";

// ---- Vertex layouts -----------------------------------------------------------------------------

struct PackedColor {
  std::uint8_t r, g, b, a;
};

PackedColor pack(const QColor& color) {
  return {static_cast<std::uint8_t>(color.red()), static_cast<std::uint8_t>(color.green()),
          static_cast<std::uint8_t>(color.blue()), 255};
}

struct Float3 {
  float x, y, z;
};

Float3 toFloat3(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

struct BallAttributes {
  float radius;
  PackedColor color;
};

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

struct ExplosionInstance {
  Float3 center;
  float halfSize;
  float alpha;
};

// ---- Meshes -------------------------------------------------------------------------------------

constexpr int kCylinderSegments = 40;

// ---- Explosions --------------------------------------------------------------------------------

constexpr int kSparkTextureSize = 128;
// Half the width of an explosion's quads at birth, in radii of the ball that collided: about
// the tutorial's proportion, so the spark starts a little larger than the ball.
constexpr double kExplosionSizePerRadius = 2.0;
constexpr double kDefaultBallRadius = 0.5;  // when the record names no ball the scene has
constexpr int kExplosionFrameMilliseconds = 16;
constexpr float kSparkColor[3] = {1.0f, 0.9f, 0.2f};

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

// ---- Interaction --------------------------------------------------------------------------------

constexpr int kSamples = 4;  // multisampling of the view's framebuffer
constexpr double kOrbitRadiansPerPixel = 0.008;
constexpr double kWheelStepAngle = 120.0;  // eighths of a degree in one wheel notch

const Vec3 kLightDirection = Vec3(0.35, 1.0, 0.55).normalized();

template <typename T>
void uploadBuffer(QOpenGLFunctions_3_3_Core* gl, GLuint buffer, const std::vector<T>& data,
                  GLenum usage) {
  gl->glBindBuffer(GL_ARRAY_BUFFER, buffer);
  gl->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
                   data.empty() ? nullptr : data.data(), usage);
}

void* byteOffset(std::size_t offset) {
  return reinterpret_cast<void*>(offset);
}

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* vertex, const char* fragment) {
  auto program = std::make_unique<QOpenGLShaderProgram>();
  const QByteArray fragmentSource =
      QByteArray("#version 330 core\n") + kLightingGlsl + QByteArray(fragment);
  if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
      !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentSource) ||
      !program->link()) {
    qWarning("SceneView: shader program failed: %s", qPrintable(program->log()));
  }
  return program;
}

}  // namespace

SceneView::SceneView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat multisampled = QSurfaceFormat::defaultFormat();
  multisampled.setSamples(kSamples);
  setFormat(multisampled);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(160, 120);
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  clock_.start();
  explosionFrameTimer_.setSingleShot(true);
  explosionFrameTimer_.setInterval(kExplosionFrameMilliseconds);
  connect(&explosionFrameTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
}

SceneView::~SceneView() {
  if (glReady_) {
    makeCurrent();
    releaseGl();
    doneCurrent();
  }
}

void SceneView::setDefaultFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  // No samples here: the default format is also the top-level window's, and a multisampled
  // window only slows Qt's compositing (measured: 31 -> 22 frames/s with 5,000 balls on
  // llvmpipe). The view asks for its own multisampled framebuffer instead.
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

void SceneView::setScene(std::shared_ptr<const RenderScene> scene) {
  const bool first = scene_ == nullptr;
  scene_ = std::move(scene);
  ballPositions_ = scene_ ? scene_->initialBallPositions : std::vector<Vec3>();
  if (followedBall_ >= static_cast<int>(ballPositions_.size())) setFollowedBall(-1);
  if (scene_ && first) camera_.home(scene_->bounds);
  staticDataDirty_ = true;
  positionsDirty_ = true;
  explosions_.clear();  // they belong to the old scene's collisions
  followBall();
  update();
}

void SceneView::setBallPositions(std::vector<Vec3> positions) {
  ballPositions_ = std::move(positions);
  positionsDirty_ = true;
  followBall();
  update();
}

Camera& SceneView::camera() {
  autoFrame_ = false;
  return camera_;
}

QPointF SceneView::project(const Vec3& world) const {
  const QPointF ndc = camera_.projectToNdc(world);
  return QPointF(0.5 * (ndc.x() + 1.0) * width(), 0.5 * (1.0 - ndc.y()) * height());
}

void SceneView::setFollowedBall(int index) {
  if (index < -1 || index >= static_cast<int>(ballPositions_.size())) index = -1;
  if (index == followedBall_) return;
  followedBall_ = index;
  if (index >= 0) autoFrame_ = false;
  followBall();
  update();
  emit followedBallChanged(index);
}

double SceneView::clockSeconds() const {
  return static_cast<double>(clock_.nsecsElapsed()) * 1e-9;
}

void SceneView::addExplosions(const std::vector<carom::CollisionRecord>& collisions) {
  if (!explosionsEnabled_ || collisions.empty()) return;
  const double now = clockSeconds();
  const auto radius = [this](int ball) {
    if (scene_ && ball >= 0 && ball < static_cast<int>(scene_->ballRadii.size()))
      return scene_->ballRadii[ball];
    return kDefaultBallRadius;
  };
  for (const carom::CollisionRecord& collision : collisions) {
    double size = radius(collision.ball);
    if (collision.kind == carom::ContactKind::BallBall)
      size = std::max(size, radius(collision.other));
    explosions_.add(collision.point, kExplosionSizePerRadius * size, now);
  }
  update();
}

void SceneView::setExplosionsEnabled(bool enabled) {
  if (enabled == explosionsEnabled_) return;
  explosionsEnabled_ = enabled;
  if (!enabled) explosions_.clear();
  update();
}

void SceneView::setExplosionLimit(int limit) {
  explosions_.setLimit(limit);
  update();
}

void SceneView::frameScene() {
  setFollowedBall(-1);
  if (scene_) camera_.home(scene_->bounds);
  update();
}

void SceneView::followBall() {
  if (followedBall_ >= 0 && followedBall_ < static_cast<int>(ballPositions_.size())) {
    camera_.follow(ballPositions_[followedBall_]);
  }
}

void SceneView::userMovedCamera() {
  autoFrame_ = false;
  update();
}

// ---- Input --------------------------------------------------------------------------------------

void SceneView::resizeEvent(QResizeEvent* event) {
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  if (autoFrame_ && scene_) camera_.home(scene_->bounds);
  QOpenGLWidget::resizeEvent(event);
}

void SceneView::mousePressEvent(QMouseEvent* event) {
  lastMousePosition_ = event->position().toPoint();
  event->accept();
}

void SceneView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint position = event->position().toPoint();
  const QPoint delta = position - lastMousePosition_;
  lastMousePosition_ = position;
  if (event->buttons() & Qt::LeftButton) {
    // Dragging turns the scene with the cursor, so the camera goes the other way.
    camera_.orbit(-delta.x() * kOrbitRadiansPerPixel, delta.y() * kOrbitRadiansPerPixel);
    userMovedCamera();
  } else if (event->buttons() & Qt::MiddleButton) {
    setFollowedBall(-1);  // following would snap the target straight back
    const double viewHeight = std::max(1, height());
    camera_.pan(delta.x() / viewHeight, delta.y() / viewHeight);
    userMovedCamera();
  }
  event->accept();
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
  event->accept();
}

void SceneView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / kWheelStepAngle;
  if (steps != 0.0) {
    camera_.zoom(steps);
    userMovedCamera();
  }
  event->accept();
}

void SceneView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Left:
      camera_.rotateByKeys(1, 0);
      break;
    case Qt::Key_Right:
      camera_.rotateByKeys(-1, 0);
      break;
    case Qt::Key_Up:
      camera_.rotateByKeys(0, 1);
      break;
    case Qt::Key_Down:
      camera_.rotateByKeys(0, -1);
      break;
    case Qt::Key_Home:
      frameScene();
      return;
    default:
      QOpenGLWidget::keyPressEvent(event);
      return;
  }
  userMovedCamera();
}

// ---- GL -----------------------------------------------------------------------------------------

// One vertex attribute from the bound buffer: floats as they are, bytes as 0..1; per-instance
// attributes advance once per instance.
void SceneView::vertexAttribute(GLuint location, GLint components, GLenum type, GLsizei stride,
                                std::size_t offset, bool perInstance) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, type, type == GL_FLOAT ? GL_FALSE : GL_TRUE, stride,
                        byteOffset(offset));
  if (perInstance) glVertexAttribDivisor(location, 1);
}

void SceneView::initializeGL() {
  initializeOpenGLFunctions();
  // A widget moved to another window gets a new context; the old one's resources go with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SceneView::releaseGl,
          Qt::UniqueConnection);

  ballProgram_ = buildProgram(kBallVertexGlsl, kBallFragmentGlsl);
  planeProgram_ = buildProgram(kPlaneVertexGlsl, kPlaneFragmentGlsl);
  cylinderProgram_ = buildProgram(kCylinderVertexGlsl, kCylinderFragmentGlsl);
  explosionProgram_ = buildProgram(kExplosionVertexGlsl, kExplosionFragmentGlsl);

  std::array<GLuint, 6> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  ballCornerBuffer_ = buffers[0];
  ballPositionBuffer_ = buffers[1];
  ballAttributeBuffer_ = buffers[2];
  planeVertexBuffer_ = buffers[3];
  cylinderVertexBuffer_ = buffers[4];
  cylinderInstanceBuffer_ = buffers[5];
  glGenVertexArrays(1, &ballVao_);
  glGenVertexArrays(1, &planeVao_);
  glGenVertexArrays(1, &cylinderVao_);

  const std::vector<float> squareCorners = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
  uploadBuffer(this, ballCornerBuffer_, squareCorners, GL_STATIC_DRAW);
  createCylinderMesh();

  // Balls: the shared square, then per instance a centre (updated every frame) and a radius and
  // colour (set once per scene), from two buffers so that a frame uploads only the centres.
  glBindVertexArray(ballVao_);
  glBindBuffer(GL_ARRAY_BUFFER, ballCornerBuffer_);
  vertexAttribute(0, 2, GL_FLOAT, 2 * sizeof(float), 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, ballPositionBuffer_);
  vertexAttribute(1, 3, GL_FLOAT, sizeof(Float3), 0, true);
  glBindBuffer(GL_ARRAY_BUFFER, ballAttributeBuffer_);
  vertexAttribute(2, 1, GL_FLOAT, sizeof(BallAttributes), offsetof(BallAttributes, radius), true);
  vertexAttribute(3, 4, GL_UNSIGNED_BYTE, sizeof(BallAttributes), offsetof(BallAttributes, color),
                  true);

  glBindVertexArray(planeVao_);
  glBindBuffer(GL_ARRAY_BUFFER, planeVertexBuffer_);
  vertexAttribute(0, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, position), false);
  vertexAttribute(1, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, normal), false);
  vertexAttribute(2, 2, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, grid), false);
  vertexAttribute(3, 4, GL_UNSIGNED_BYTE, sizeof(PlaneVertex), offsetof(PlaneVertex, color), false);

  glBindVertexArray(cylinderVao_);
  glBindBuffer(GL_ARRAY_BUFFER, cylinderVertexBuffer_);
  vertexAttribute(0, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, local), false);
  vertexAttribute(1, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, normal), false);
  glBindBuffer(GL_ARRAY_BUFFER, cylinderInstanceBuffer_);
  const std::array<std::pair<GLint, std::size_t>, 3> floatFields = {
      std::pair<GLint, std::size_t>{3, offsetof(CylinderInstance, start)},
      {3, offsetof(CylinderInstance, end)},
      {1, offsetof(CylinderInstance, radius)}};
  for (GLuint location = 2; const auto& [components, offset] : floatFields) {
    vertexAttribute(location, components, GL_FLOAT, sizeof(CylinderInstance), offset, true);
    ++location;
  }
  vertexAttribute(5, 4, GL_UNSIGNED_BYTE, sizeof(CylinderInstance),
                  offsetof(CylinderInstance, color), true);

  createExplosionData();

  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  glReady_ = true;
  staticDataDirty_ = true;
  positionsDirty_ = true;
}

void SceneView::releaseGl() {
  if (!glReady_) return;
  glReady_ = false;
  ballProgram_.reset();
  planeProgram_.reset();
  cylinderProgram_.reset();
  explosionProgram_.reset();
  const std::array<GLuint, 2> explosionBuffers = {explosionCornerBuffer_, explosionInstanceBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(explosionBuffers.size()), explosionBuffers.data());
  glDeleteVertexArrays(1, &explosionVao_);
  glDeleteTextures(1, &sparkTexture_);
  explosionCornerBuffer_ = explosionInstanceBuffer_ = explosionVao_ = sparkTexture_ = 0;
  const std::array<GLuint, 6> buffers = {ballCornerBuffer_,     ballPositionBuffer_,
                                         ballAttributeBuffer_,  planeVertexBuffer_,
                                         cylinderVertexBuffer_, cylinderInstanceBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  const std::array<GLuint, 3> arrays = {ballVao_, planeVao_, cylinderVao_};
  glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
  ballCornerBuffer_ = ballPositionBuffer_ = ballAttributeBuffer_ = 0;
  planeVertexBuffer_ = cylinderVertexBuffer_ = cylinderInstanceBuffer_ = 0;
  ballVao_ = planeVao_ = cylinderVao_ = 0;
}

void SceneView::createCylinderMesh() {
  // A unit cylinder with both ends closed: clipped at the bounds, its cut faces show.
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
  uploadBuffer(this, cylinderVertexBuffer_, vertices, GL_STATIC_DRAW);
}

void SceneView::createExplosionData() {
  std::array<GLuint, 2> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  explosionCornerBuffer_ = buffers[0];
  explosionInstanceBuffer_ = buffers[1];
  glGenVertexArrays(1, &explosionVao_);

  std::vector<Float3> corners;
  for (float quad : {0.0f, 1.0f}) {
    corners.insert(corners.end(), {{-1.0f, -1.0f, quad},
                                   {1.0f, -1.0f, quad},
                                   {1.0f, 1.0f, quad},
                                   {-1.0f, -1.0f, quad},
                                   {1.0f, 1.0f, quad},
                                   {-1.0f, 1.0f, quad}});
  }
  uploadBuffer(this, explosionCornerBuffer_, corners, GL_STATIC_DRAW);

  glBindVertexArray(explosionVao_);
  glBindBuffer(GL_ARRAY_BUFFER, explosionCornerBuffer_);
  vertexAttribute(0, 3, GL_FLOAT, sizeof(Float3), 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, explosionInstanceBuffer_);
  vertexAttribute(1, 3, GL_FLOAT, sizeof(ExplosionInstance), offsetof(ExplosionInstance, center),
                  true);
  vertexAttribute(2, 1, GL_FLOAT, sizeof(ExplosionInstance), offsetof(ExplosionInstance, halfSize),
                  true);
  vertexAttribute(3, 1, GL_FLOAT, sizeof(ExplosionInstance), offsetof(ExplosionInstance, alpha),
                  true);

  const QImage spark = makeSparkImage();
  glGenTextures(1, &sparkTexture_);
  glBindTexture(GL_TEXTURE_2D, sparkTexture_);
  // QImage may pad its lines; tell GL their real length (one byte a pixel here).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(spark.bytesPerLine()));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, spark.width(), spark.height(), 0, GL_RED, GL_UNSIGNED_BYTE,
               spark.constBits());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Mipmaps, because a distant spark covers only a few pixels.
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void SceneView::drawExplosions(const QMatrix4x4& viewProjection, const QVector3D& eye) {
  const std::vector<ExplosionPool::Live> live = explosions_.live();
  if (live.empty()) return;
  std::vector<ExplosionInstance> instances;
  instances.reserve(live.size());
  for (const ExplosionPool::Live& e : live) {
    instances.push_back(
        {toFloat3(e.centre), static_cast<float>(e.scale), static_cast<float>(e.alpha)});
  }
  uploadBuffer(this, explosionInstanceBuffer_, instances, GL_STREAM_DRAW);

  explosionProgram_->bind();
  explosionProgram_->setUniformValue("viewProjection", viewProjection);
  explosionProgram_->setUniformValue("eyePosition", eye);
  explosionProgram_->setUniformValue("spark", 0);
  explosionProgram_->setUniformValue("sparkColor",
                                     QVector3D(kSparkColor[0], kSparkColor[1], kSparkColor[2]));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, sparkTexture_);
  glBindVertexArray(explosionVao_);
  // Additive light: hidden behind balls and walls by the depth test, but not writing depth, so
  // sparks never hide each other. Both sides of each quad show. Alpha stays 1 in the image.
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glDrawArraysInstanced(GL_TRIANGLES, 0, 12, static_cast<GLsizei>(instances.size()));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void SceneView::uploadStaticData() {
  staticDataDirty_ = false;
  std::vector<BallAttributes> balls;
  std::vector<PlaneVertex> planeVertices;
  std::vector<CylinderInstance> cylinders;
  if (scene_) {
    for (std::size_t i = 0; i < scene_->ballRadii.size(); ++i) {
      const QColor color = i < scene_->ballColors.size() ? scene_->ballColors[i] : QColor(Qt::gray);
      balls.push_back({static_cast<float>(scene_->ballRadii[i]), pack(color)});
    }
    const double spacing = scene_->gridSpacing > 0.0 ? scene_->gridSpacing : 1.0;
    for (const RenderPlane& plane : scene_->planes) {
      if (plane.polygon.size() < 3) continue;
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
            pack(plane.color)};
      };
      for (std::size_t i = 1; i + 1 < plane.polygon.size(); ++i) {
        planeVertices.push_back(vertex(plane.polygon[0]));
        planeVertices.push_back(vertex(plane.polygon[i]));
        planeVertices.push_back(vertex(plane.polygon[i + 1]));
      }
    }
    for (const RenderCylinder& cylinder : scene_->cylinders) {
      if ((cylinder.end - cylinder.start).norm() == 0.0) continue;  // misses the bounds
      cylinders.push_back({toFloat3(cylinder.start), toFloat3(cylinder.end),
                           static_cast<float>(cylinder.radius), pack(cylinder.color)});
    }
  }
  uploadBuffer(this, ballAttributeBuffer_, balls, GL_STATIC_DRAW);
  uploadBuffer(this, planeVertexBuffer_, planeVertices, GL_STATIC_DRAW);
  uploadBuffer(this, cylinderInstanceBuffer_, cylinders, GL_STATIC_DRAW);
  planeVertexCount_ = static_cast<int>(planeVertices.size());
  cylinderInstanceCount_ = static_cast<int>(cylinders.size());
}

void SceneView::uploadBallPositions() {
  positionsDirty_ = false;
  const std::size_t count =
      scene_ ? std::min(ballPositions_.size(), scene_->ballRadii.size()) : std::size_t{0};
  std::vector<Float3> centers(count);
  for (std::size_t i = 0; i < count; ++i) centers[i] = toFloat3(ballPositions_[i]);
  glBindBuffer(GL_ARRAY_BUFFER, ballPositionBuffer_);
  // Orphaning: a fresh allocation lets the driver keep drawing from last frame's copy.
  const auto bytes = static_cast<GLsizeiptr>(centers.size() * sizeof(Float3));
  glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW);
  if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, centers.data());
  uploadedBallCount_ = static_cast<int>(count);
}

void SceneView::paintGL() {
  QElapsedTimer timer;
  timer.start();
  if (staticDataDirty_) uploadStaticData();
  if (positionsDirty_) uploadBallPositions();
  explosions_.update(clockSeconds());
  // Explosions fade with time, so frames must keep coming while any show, even when nothing
  // else changes (a paused simulation).
  if (!explosions_.empty() && !explosionFrameTimer_.isActive()) explosionFrameTimer_.start();

  glClearColor(0.16f, 0.17f, 0.20f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Also hides the walls seen from outside (their front faces point into the room), which is
  // what lets the camera look in from beyond them.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);

  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  const QMatrix4x4 viewProjection = camera_.viewProjection();
  const QVector3D eye = camera_.eye();
  const QVector3D light(static_cast<float>(kLightDirection.x()),
                        static_cast<float>(kLightDirection.y()),
                        static_cast<float>(kLightDirection.z()));
  const auto use = [&](QOpenGLShaderProgram& program) {
    program.bind();
    program.setUniformValue("viewProjection", viewProjection);
    program.setUniformValue("eyePosition", eye);
    program.setUniformValue("lightDirection", light);
  };

  if (planeVertexCount_ > 0) {
    use(*planeProgram_);
    glBindVertexArray(planeVao_);
    glDrawArrays(GL_TRIANGLES, 0, planeVertexCount_);
  }
  if (cylinderInstanceCount_ > 0) {
    use(*cylinderProgram_);
    glBindVertexArray(cylinderVao_);
    glDrawArraysInstanced(GL_TRIANGLES, 0, cylinderVertexCount_, cylinderInstanceCount_);
  }
  if (uploadedBallCount_ > 0) {
    use(*ballProgram_);
    // Per device pixel, so that the soft edge is a pixel wide on any screen.
    const double deviceHeight = std::max(1.0, height() * devicePixelRatioF());
    const double viewHeightAtUnitDistance =
        2.0 * std::tan(0.5 * camera_.verticalFov() * std::numbers::pi / 180.0);
    ballProgram_->setUniformValue("pixelAngle",
                                  static_cast<float>(viewHeightAtUnitDistance / deviceHeight));
    glBindVertexArray(ballVao_);
    // The squares face the camera by construction; alpha-to-coverage gives the ray-cast outline
    // the same smooth edge multisampling gives triangles. Alpha itself stays 1 in the image.
    glDisable(GL_CULL_FACE);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, uploadedBallCount_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
  drawExplosions(viewProjection, eye);

  // Leave the state as Qt's compositing expects it.
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);

  // Waiting for the GPU makes the time cover the drawing itself, not only its submission.
  glFinish();
  emit frameRendered(static_cast<double>(timer.nsecsElapsed()) / 1e6);
}

}  // namespace carom::render
