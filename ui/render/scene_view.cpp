#include "ui/render/scene_view.h"

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
const vec3 groundAmbient = vec3(0.30, 0.28, 0.27);
const vec3 skyAmbient = vec3(0.46, 0.48, 0.52);
const float diffuseStrength = 0.62;
const vec3 selectionColor = vec3(1.0, 0.55, 0.05);

vec3 shade(vec3 base, vec3 normal, vec3 position, float shininess, float specularStrength) {
  vec3 n = normalize(normal);
  vec3 toEye = normalize(eyePosition - position);
  vec3 ambient = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y);
  float diffuse = max(dot(n, lightDirection), 0.0);
  vec3 halfway = normalize(lightDirection + toEye);
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  return base * (ambient + diffuseStrength * diffuse) + vec3(specularStrength * highlight);
}
)";

// Balls are impostors: one camera-facing square per ball, just large enough to hold the
// sphere's outline, and the fragment shader finds the sphere's surface and depth inside it.
// Software renderers set the budget:
// - Four vertices a ball instead of a mesh, drawn as plain indexed triangles: llvmpipe pays a
//   fixed cost for each instance of an instanced draw.
// - Everything that is the same across a ball (the light and the view in the ball's own frame)
//   is worked out per vertex, and the surface is the sphere seen head-on. That is exact at the
//   centre of the view and off by the perspective across one ball elsewhere, which the eye
//   does not see; it halved the time for 1,000 balls against ray casting each pixel.
// - The depth is the square's own, a disc through the centre, not the sphere's surface: then
//   the depth test runs before the shading, and with the balls drawn nearest first, hidden
//   pixels are never shaded (5,000 balls: 15.6 -> 11.9 ms a frame). The disc lies inside the
//   ball, so a plane, cylinder or ball that does not cut into the ball is drawn in front of it
//   exactly where it is in front of the sphere, except that two balls overlapping on the
//   screen are ordered by their centres.
constexpr const char* kBallVertexGlsl = R"(#version 330 core
layout(location = 1) in vec3 center;
layout(location = 2) in float radius;
layout(location = 3) in vec4 color;
uniform mat4 viewProjection;
uniform vec3 eyePosition;
uniform vec3 lightDirection;
uniform float pixelAngle;  // view height over distance, per device pixel
out vec2 outline;          // position in the square; the sphere's outline is the unit circle
// In the ball's frame: x right, y up, z towards the eye.
flat out vec3 light;
flat out vec3 halfway;
flat out vec3 worldUp;
flat out vec3 baseColor;
flat out float edgePixels;  // outline radius in pixels
flat out float selected;    // the colour's alpha is 0 for a selected ball
void main() {
  // The square's corner in [-1, 1]^2 from the vertex's place among its ball's four.
  vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vec3 toCenter = center - eyePosition;
  float distance = length(toCenter);
  baseColor = color.rgb;
  selected = color.a < 0.5 ? 1.0 : 0.0;
  if (distance <= radius * 1.0001) {  // the eye is inside: nothing sensible to draw
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec3 forward = toCenter / distance;
  vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(forward, helper));
  vec3 up = cross(right, forward);
  mat3 toBall = transpose(mat3(right, up, -forward));
  light = toBall * lightDirection;
  halfway = normalize(light + vec3(0.0, 0.0, 1.0));
  worldUp = toBall * vec3(0.0, 1.0, 0.0);

  // The cone of rays touching the sphere cuts the plane through its centre in this circle.
  float outlineRadius = radius * distance / sqrt(distance * distance - radius * radius);
  edgePixels = outlineRadius / (pixelAngle * distance);
  // Plus a pixel and a half, for the soft edge.
  float halfSize = outlineRadius + 1.5 * pixelAngle * distance;
  outline = corner * (halfSize / outlineRadius);
  gl_Position = viewProjection * vec4(center + halfSize * (corner.x * right + corner.y * up), 1.0);
}
)";

constexpr const char* kBallFragmentGlsl = R"(
in vec2 outline;
flat in vec3 light;
flat in vec3 halfway;
flat in vec3 worldUp;
flat in vec3 baseColor;
flat in float edgePixels;
flat in float selected;
out vec4 fragColor;
void main() {
  float fromCenter2 = dot(outline, outline);
  // Coverage of this pixel by the outline, which alpha-to-coverage turns into samples.
  float coverage = clamp((1.0 - sqrt(fromCenter2)) * edgePixels + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  // Pixels of the soft edge just outside take the outline's normal.
  vec3 n = vec3(outline, sqrt(max(1.0 - fromCenter2, 0.0)));
  vec3 ambient = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * dot(n, worldUp));
  float diffuse = max(dot(n, light), 0.0);
  // The shininess of 40 by squaring, far cheaper than pow() in a software renderer.
  float h = max(dot(n, halfway), 0.0);
  float h2 = h * h, h4 = h2 * h2, h8 = h4 * h4, h16 = h8 * h8, h32 = h16 * h16;
  float highlight = diffuse > 0.0 ? h32 * h8 : 0.0;
  // A selected ball wears a bright ring around its outline.
  vec3 base = selected > 0.5 && fromCenter2 > 0.6 ? selectionColor : baseColor;
  fragColor = vec4(base * (ambient + diffuseStrength * diffuse) + vec3(0.35 * highlight),
                   coverage);
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

// The velocity arrow of the selected ball: plain lines on top of everything.
constexpr const char* kLineVertexGlsl = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
}
)";

constexpr const char* kLineFragmentGlsl = R"(
uniform vec3 lineColor;
out vec4 fragColor;
void main() {
  fragColor = vec4(lineColor, 1.0);
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

const QColor kSelectionColor(255, 140, 13);
// The world's axes through the origin: x red, y green, z blue, as in most 3D tools.
const QColor kAxisColors[3] = {QColor(214, 69, 65), QColor(90, 180, 90), QColor(70, 120, 220)};

// Selected planes and cylinders take on the selection's colour.
QColor shown(const QColor& color, bool selected) {
  if (!selected) return color;
  return QColor((color.red() + kSelectionColor.red()) / 2,
                (color.green() + kSelectionColor.green()) / 2,
                (color.blue() + kSelectionColor.blue()) / 2);
}

// Whether each of `count` items is among `indices`: one pass, however many are selected.
std::vector<bool> membership(const std::vector<int>& indices, std::size_t count) {
  std::vector<bool> member(count, false);
  for (int index : indices)
    if (index >= 0 && static_cast<std::size_t>(index) < count) member[index] = true;
  return member;
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
constexpr std::size_t kVerticesPerBall = 4;  // a square, as two triangles
constexpr int kIndicesPerBall = 6;

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

constexpr GLint kSamples = 4;  // multisampling, when antialiasing is on
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
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(160, 120);
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  clock_.start();
  explosionFrameTimer_.setSingleShot(true);
  explosionFrameTimer_.setInterval(kExplosionFrameMilliseconds);
  connect(&explosionFrameTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
}

SceneView::~SceneView() {
  // QOpenGLWidget's destructor destroys the context, whose notice must not reach this view's
  // slot once this part of the object is gone.
  if (QOpenGLContext* gl = context()) disconnect(gl, nullptr, this, nullptr);
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
  // llvmpipe). The view multisamples in a framebuffer of its own, when antialiasing is on.
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

std::pair<Vec3, Vec3> SceneView::rayAt(const QPointF& widgetPosition) const {
  // Before it is laid out the view may have no size: no dividing by zero.
  const double w = std::max(width(), 1);
  const double h = std::max(height(), 1);
  return camera_.rayThroughNdc(
      QPointF(2.0 * widgetPosition.x() / w - 1.0, 1.0 - 2.0 * widgetPosition.y() / h));
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
  autoFrame_ = true;  // and again when the view is resized, until the user moves the camera
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
  const bool antialiasingBefore = antialiasing();
  const QByteArray renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  softwareRenderer_ =
      renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast");
  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  samples_ = std::min(kSamples, maxSamples);
  if (antialiasing() != antialiasingBefore) emit antialiasingChanged(antialiasing());
  // A widget moved to another window gets a new context; the old one's resources go with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SceneView::releaseGl,
          Qt::UniqueConnection);

  ballProgram_ = buildProgram(kBallVertexGlsl, kBallFragmentGlsl);
  planeProgram_ = buildProgram(kPlaneVertexGlsl, kPlaneFragmentGlsl);
  cylinderProgram_ = buildProgram(kCylinderVertexGlsl, kCylinderFragmentGlsl);
  explosionProgram_ = buildProgram(kExplosionVertexGlsl, kExplosionFragmentGlsl);
  lineProgram_ = buildProgram(kLineVertexGlsl, kLineFragmentGlsl);
  glGenVertexArrays(1, &lineVao_);
  glGenBuffers(1, &lineBuffer_);
  glBindVertexArray(lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_);
  vertexAttribute(0, 3, GL_FLOAT, sizeof(Float3), 0, false);
  glBindVertexArray(0);

  std::array<GLuint, 6> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  ballIndexBuffer_ = buffers[0];
  ballPositionBuffer_ = buffers[1];
  ballAttributeBuffer_ = buffers[2];
  planeVertexBuffer_ = buffers[3];
  cylinderVertexBuffer_ = buffers[4];
  cylinderInstanceBuffer_ = buffers[5];
  glGenVertexArrays(1, &ballVao_);
  glGenVertexArrays(1, &planeVao_);
  glGenVertexArrays(1, &cylinderVao_);

  createCylinderMesh();

  // Balls: four vertices each, with a centre (updated every frame) and a radius and colour (set
  // once per scene) from two buffers, so that a frame uploads only the centres.
  glBindVertexArray(ballVao_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ballIndexBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, ballPositionBuffer_);
  vertexAttribute(1, 3, GL_FLOAT, sizeof(Float3), 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, ballAttributeBuffer_);
  vertexAttribute(2, 1, GL_FLOAT, sizeof(BallAttributes), offsetof(BallAttributes, radius), false);
  vertexAttribute(3, 4, GL_UNSIGNED_BYTE, sizeof(BallAttributes), offsetof(BallAttributes, color),
                  false);

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
  releaseMultisampleBuffer();
  ballProgram_.reset();
  planeProgram_.reset();
  cylinderProgram_.reset();
  explosionProgram_.reset();
  lineProgram_.reset();
  glDeleteBuffers(1, &lineBuffer_);
  glDeleteVertexArrays(1, &lineVao_);
  lineBuffer_ = lineVao_ = 0;
  const std::array<GLuint, 2> explosionBuffers = {explosionCornerBuffer_, explosionInstanceBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(explosionBuffers.size()), explosionBuffers.data());
  glDeleteVertexArrays(1, &explosionVao_);
  glDeleteTextures(1, &sparkTexture_);
  explosionCornerBuffer_ = explosionInstanceBuffer_ = explosionVao_ = sparkTexture_ = 0;
  const std::array<GLuint, 6> buffers = {ballIndexBuffer_,      ballPositionBuffer_,
                                         ballAttributeBuffer_,  planeVertexBuffer_,
                                         cylinderVertexBuffer_, cylinderInstanceBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  const std::array<GLuint, 3> arrays = {ballVao_, planeVao_, cylinderVao_};
  glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
  ballIndexBuffer_ = ballPositionBuffer_ = ballAttributeBuffer_ = 0;
  planeVertexBuffer_ = cylinderVertexBuffer_ = cylinderInstanceBuffer_ = 0;
  ballVao_ = planeVao_ = cylinderVao_ = 0;
}

// The element buffer, which belongs to the balls' vertex array object (bound), lists the balls'
// squares nearest first.
void SceneView::sortBallsFrontToBack(const QVector3D& eye) {
  const std::size_t count = static_cast<std::size_t>(uploadedBallCount_);
  const Vec3 eyePoint(eye.x(), eye.y(), eye.z());
  std::vector<std::pair<float, GLuint>> order(count);
  for (std::size_t i = 0; i < count; ++i)
    order[i] = {static_cast<float>((ballPositions_[i] - eyePoint).squaredNorm()),
                static_cast<GLuint>(i)};
  std::sort(order.begin(), order.end());
  std::vector<GLuint> indices;
  indices.reserve(kIndicesPerBall * count);
  for (const auto& [distance, ball] : order) {
    const auto first = static_cast<GLuint>(kVerticesPerBall * ball);
    indices.insert(indices.end(), {first, first + 1, first + 2, first + 2, first + 1, first + 3});
  }
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
               indices.data(), GL_STREAM_DRAW);
}

void SceneView::setHighlighted(std::vector<int> balls, std::vector<int> planes,
                               std::vector<int> cylinders) {
  highlightedBalls_ = std::move(balls);
  highlightedPlanes_ = std::move(planes);
  highlightedCylinders_ = std::move(cylinders);
  staticDataDirty_ = true;
  update();
}

void SceneView::setHandleArrow(std::optional<std::pair<Vec3, Vec3>> fromTo) {
  handleArrow_ = std::move(fromTo);
  update();
}

Eigen::AlignedBox3d SceneView::clipBox() const {
  if (!scene_) return Eigen::AlignedBox3d(Vec3::Constant(-1e300), Vec3::Constant(1e300));
  return Eigen::AlignedBox3d(scene_->bounds.min, scene_->bounds.max);
}

void SceneView::drawAxes(const QMatrix4x4& viewProjection) {
  if (!scene_) return;
  std::vector<Float3> lines;
  std::vector<QColor> colors;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 start;
    Vec3 end;
    if (!clipLineToBounds(Vec3::Zero(), Vec3::Unit(axis), scene_->bounds, &start, &end)) continue;
    lines.insert(lines.end(), {toFloat3(start), toFloat3(end)});
    colors.push_back(kAxisColors[axis]);
  }
  if (lines.empty()) return;
  uploadBuffer(this, lineBuffer_, lines, GL_STREAM_DRAW);
  lineProgram_->bind();
  lineProgram_->setUniformValue("viewProjection", viewProjection);
  glBindVertexArray(lineVao_);
  // The x and z axes lie in a floor at y = 0, which is drawn pushed back a little for them.
  glDepthFunc(GL_LEQUAL);
  for (std::size_t i = 0; i < colors.size(); ++i) {
    lineProgram_->setUniformValue(
        "lineColor", QVector3D(colors[i].redF(), colors[i].greenF(), colors[i].blueF()));
    glDrawArrays(GL_LINES, static_cast<GLint>(2 * i), 2);
  }
  glDepthFunc(GL_LESS);
}

void SceneView::drawHandleArrow(const QMatrix4x4& viewProjection, const QVector3D& eye) {
  if (!handleArrow_) return;
  const auto& [from, to] = *handleArrow_;
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
  uploadBuffer(this, lineBuffer_, lines, GL_STREAM_DRAW);
  lineProgram_->bind();
  lineProgram_->setUniformValue("viewProjection", viewProjection);
  lineProgram_->setUniformValue(
      "lineColor",
      QVector3D(kSelectionColor.redF(), kSelectionColor.greenF(), kSelectionColor.blueF()));
  glBindVertexArray(lineVao_);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  glEnable(GL_DEPTH_TEST);
}

bool SceneView::antialiasing() const {
  return antialiasingChoice_.value_or(!softwareRenderer_);
}

void SceneView::setAntialiasing(bool on) {
  const bool before = antialiasing();
  antialiasingChoice_ = on;
  if (antialiasing() != before) emit antialiasingChanged(antialiasing());
  update();
}

bool SceneView::bindMultisampleBuffer() {
  const QSize size(std::max(1, static_cast<int>(std::lround(width() * devicePixelRatioF()))),
                   std::max(1, static_cast<int>(std::lround(height() * devicePixelRatioF()))));
  if (multisampleFramebuffer_ == 0 || size != multisampleSize_) {
    releaseMultisampleBuffer();
    glGenFramebuffers(1, &multisampleFramebuffer_);
    std::array<GLuint, 2> buffers{};
    glGenRenderbuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    multisampleColor_ = buffers[0];
    multisampleDepth_ = buffers[1];
    glBindFramebuffer(GL_FRAMEBUFFER, multisampleFramebuffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampleColor_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, size.width(),
                                     size.height());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              multisampleColor_);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampleDepth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, size.width(),
                                     size.height());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              multisampleDepth_);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    multisampleSize_ = size;
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      qWarning("SceneView: no multisampled framebuffer; drawing without antialiasing");
      releaseMultisampleBuffer();
      samples_ = 0;
      glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
      return false;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, multisampleFramebuffer_);
  return true;
}

void SceneView::releaseMultisampleBuffer() {
  if (multisampleFramebuffer_ == 0) return;
  glDeleteFramebuffers(1, &multisampleFramebuffer_);
  const std::array<GLuint, 2> buffers = {multisampleColor_, multisampleDepth_};
  glDeleteRenderbuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  multisampleFramebuffer_ = multisampleColor_ = multisampleDepth_ = 0;
  multisampleSize_ = QSize();
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
  // One mipmap level at a time: half the texture reads of blending two, and sparks are soft.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
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
    const std::vector<bool> selectedBalls = membership(highlightedBalls_, scene_->ballRadii.size());
    const std::vector<bool> selectedPlanes = membership(highlightedPlanes_, scene_->planes.size());
    const std::vector<bool> selectedCylinders =
        membership(highlightedCylinders_, scene_->cylinders.size());
    for (std::size_t i = 0; i < scene_->ballRadii.size(); ++i) {
      const QColor color = i < scene_->ballColors.size() ? scene_->ballColors[i] : QColor(Qt::gray);
      PackedColor packed = pack(color);
      if (selectedBalls[i]) packed.a = 0;
      balls.insert(balls.end(), kVerticesPerBall,
                   {static_cast<float>(scene_->ballRadii[i]), packed});
    }
    const double spacing = scene_->gridSpacing > 0.0 ? scene_->gridSpacing : 1.0;
    for (std::size_t index = 0; index < scene_->planes.size(); ++index) {
      const RenderPlane& plane = scene_->planes[index];
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
    for (std::size_t index = 0; index < scene_->cylinders.size(); ++index) {
      const RenderCylinder& cylinder = scene_->cylinders[index];
      if ((cylinder.end - cylinder.start).norm() == 0.0) continue;  // misses the bounds
      cylinders.push_back({toFloat3(cylinder.start), toFloat3(cylinder.end),
                           static_cast<float>(cylinder.radius),
                           pack(shown(cylinder.color, selectedCylinders[index]))});
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
  std::vector<Float3> centers(kVerticesPerBall * count);
  for (std::size_t i = 0; i < count; ++i)
    std::fill_n(centers.begin() + kVerticesPerBall * i, kVerticesPerBall,
                toFloat3(ballPositions_[i]));
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

  const bool multisampled = antialiasing() && samples_ > 1 && bindMultisampleBuffer();
  glClearColor(0.16f, 0.17f, 0.20f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
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

  // Balls first: most of the walls and floor behind them then fail the depth test before their
  // shading runs, which is most of the frame on a software renderer.
  glDisable(GL_CULL_FACE);
  if (uploadedBallCount_ > 0) {
    use(*ballProgram_);
    // Per device pixel, so that the soft edge is a pixel wide on any screen.
    const double deviceHeight = std::max(1.0, height() * devicePixelRatioF());
    const double viewHeightAtUnitDistance =
        2.0 * std::tan(0.5 * camera_.verticalFov() * std::numbers::pi / 180.0);
    ballProgram_->setUniformValue("pixelAngle",
                                  static_cast<float>(viewHeightAtUnitDistance / deviceHeight));
    glBindVertexArray(ballVao_);
    sortBallsFrontToBack(eye);
    // The squares face the camera by construction; alpha-to-coverage gives the impostor outline
    // the same smooth edge multisampling gives triangles. Alpha itself stays 1 in the image.
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glDrawElements(GL_TRIANGLES, kIndicesPerBall * uploadedBallCount_, GL_UNSIGNED_INT, nullptr);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
  // Also hides the walls seen from outside (their front faces point into the room), which is
  // what lets the camera look in from beyond them.
  glEnable(GL_CULL_FACE);
  if (cylinderInstanceCount_ > 0) {
    use(*cylinderProgram_);
    glBindVertexArray(cylinderVao_);
    glDrawArraysInstanced(GL_TRIANGLES, 0, cylinderVertexCount_, cylinderInstanceCount_);
  }
  if (planeVertexCount_ > 0) {
    use(*planeProgram_);
    glBindVertexArray(planeVao_);
    // Pushed back by a step of depth, so that lines lying in a plane (the axes) show on it.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, planeVertexCount_);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  drawAxes(viewProjection);
  drawExplosions(viewProjection, eye);
  drawHandleArrow(viewProjection, eye);

  if (multisampled) {
    const QSize size = multisampleSize_;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampleFramebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    glBlitFramebuffer(0, 0, size.width(), size.height(), 0, 0, size.width(), size.height(),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  }

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
