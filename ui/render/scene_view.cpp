#include "ui/render/scene_view.h"

#include "ui/render/explosion_renderer.h"
#include "ui/render/gl_util.h"
#include "ui/render/line_renderer.h"
#include "ui/render/render_target.h"
#include "ui/render/view_vertices.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QSize>
#include <QSurfaceFormat>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>

namespace carom::render {
namespace {

// ---- Vertex layouts -----------------------------------------------------------------------------

// Velocity arrows of the watched balls: apart from the handles' orange, the sparks' yellow and
// the trails' tints of the balls' colours.
const QColor kVelocityColor(255, 255, 255);

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

// ---- Explosions --------------------------------------------------------------------------------

// Half the width of an explosion's quads at birth, in radii of the ball that collided: about
// the tutorial's proportion, so the spark starts a little larger than the ball.
constexpr double kExplosionSizePerRadius = 2.0;
constexpr double kDefaultBallRadius = 0.5;  // when the record names no ball the scene has
constexpr int kExplosionFrameMilliseconds = 16;

// ---- Drawing ------------------------------------------------------------------------------------

constexpr GLint kSamples = 4;  // multisampling, when antialiasing is on

const Vec3 kLightDirection = Vec3(0.35, 1.0, 0.55).normalized();
const QVector3D kBackground(0.16f, 0.17f, 0.20f);

QVector3D toQVector(const Vec3& v) {
  return QVector3D(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
}

// Multisampling's samples, when antialiasing is on: as many as asked if the driver has them.
GLint multisamples(QOpenGLFunctions_3_3_Core* gl) {
  GLint maxSamples = 0;
  gl->glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  return std::min(kSamples, maxSamples);
}

}  // namespace

SceneView::SceneView(QWidget* parent) : QOpenGLWidget(parent) {
  // The arrow keys are the view's: a wheel turn or a middle or right drag gives it the focus as a
  // click does, without adding or deselecting anything.
  setFocusPolicy(Qt::WheelFocus);
  setMinimumSize(160, 120);
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  clock_.start();
  explosionFrameTimer_.setSingleShot(true);
  explosionFrameTimer_.setInterval(kExplosionFrameMilliseconds);
  connect(&explosionFrameTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
  pieceTimer_.setSingleShot(true);
  pieceTimer_.setInterval(0);  // events waiting are handled first
  connect(&pieceTimer_, &QTimer::timeout, this, &SceneView::drawNextPiece);
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
  // Into the storage it has: a fresh copy of a million positions faulted in for 0.1 s.
  if (scene_)
    ballPositions_.assign(scene_->initialBallPositions.begin(), scene_->initialBallPositions.end());
  else
    ballPositions_.clear();
  if (followedBall_ >= static_cast<int>(ballPositions_.size())) setFollowedBall(-1);
  if (scene_ && first) camera_.home(scene_->bounds);
  staticDataDirty_ = true;
  markBallAttributesDirty();
  positionsDirty_ = true;
  explosions_.clear();  // they belong to the old scene's collisions
  cancelPicture();      // its sizes and order are the old scene's
  followBall();
  contentChanged();
}

void SceneView::setBallPositions(const std::vector<Vec3>& positions) {
  ballPositions_.assign(positions.begin(), positions.end());
  positionsDirty_ = true;
  followBall();
  contentChanged();
}

void SceneView::contentChanged() {
  ++contentVersion_;
  update();
}

QSize SceneView::devicePixelSize() const {
  const auto devicePixels = [this](int length) {
    return std::max(1, static_cast<int>(std::lround(length * devicePixelRatioF())));
  };
  return QSize(devicePixels(width()), devicePixels(height()));
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

double SceneView::explosionSize(const RenderScene* scene, const carom::CollisionRecord& collision) {
  const auto radius = [scene](int ball) {
    if (scene && ball >= 0 && ball < static_cast<int>(scene->ballRadii.size()))
      return scene->ballRadii[ball];
    return kDefaultBallRadius;
  };
  double size = radius(collision.ball);
  if (collision.kind == carom::ContactKind::BallBall)
    size = std::max(size, radius(collision.other));
  return kExplosionSizePerRadius * size;
}

void SceneView::addExplosions(const std::vector<carom::CollisionRecord>& collisions) {
  if (!explosionsEnabled_ || collisions.empty()) return;
  const double now = clockSeconds();
  for (const carom::CollisionRecord& collision : collisions)
    explosions_.add(collision.point, explosionSize(scene_.get(), collision), now);
  contentChanged();
}

void SceneView::setExplosionsEnabled(bool enabled) {
  if (enabled == explosionsEnabled_) return;
  explosionsEnabled_ = enabled;
  if (!enabled) explosions_.clear();
  contentChanged();
}

void SceneView::setExplosionLimit(int limit) {
  explosions_.setLimit(limit);
  contentChanged();
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

// ---- GL -----------------------------------------------------------------------------------------

void SceneView::initializeGL() {
  initializeOpenGLFunctions();
  detectSoftwareRenderer();
  // A widget moved to another window gets a new context; the old one's resources go with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SceneView::releaseGl,
          Qt::UniqueConnection);
  ballProgram_ = buildProgram("ball");
  std::array<GLfloat, 2> pointSizes{1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes.data());
  largestPointSize_ = pointSizes[1];
  planeProgram_ = buildProgram("plane");
  cylinderProgram_ = buildProgram("cylinder");
  boxProgram_ = buildProgram("box", "plane");
  createBallBuffers();
  createPlaneBuffers();
  createCylinderBuffers();
  createBoxBuffers();
  QOpenGLFunctions_3_3_Core* const gl = this;  // a protected base: make_unique cannot see it
  lineRenderer_ = std::make_unique<LineRenderer>(gl);
  explosionRenderer_ = std::make_unique<ExplosionRenderer>(gl);
  multisample_ = std::make_unique<RenderTarget>(gl, multisamples(gl));
  for (auto& target : pictureTargets_) target = std::make_unique<RenderTarget>(gl, 0);
  glReady_ = true;
  staticDataDirty_ = true;
  markBallAttributesDirty();
  positionsDirty_ = true;
}

// Known only now, and it changes whether antialiasing is on by default.
void SceneView::detectSoftwareRenderer() {
  const bool antialiasingBefore = antialiasing();
  const QByteArray renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  softwareRenderer_ =
      renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast");
  if (antialiasing() != antialiasingBefore) emit antialiasingChanged(antialiasing());
}

// Balls: four vertices each, with a centre (updated every frame) and a radius and colour (set
// once per scene) from two buffers, so that a frame uploads only the centres.
void SceneView::createBallBuffers() {
  ballCenterBytes_ = ballIndexBytes_ = 0;
  std::array<GLuint, 3> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  ballIndexBuffer_ = buffers[0];
  ballPositionBuffer_ = buffers[1];
  ballAttributeBuffer_ = buffers[2];
  glGenVertexArrays(1, &ballVao_);
  glBindVertexArray(ballVao_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ballIndexBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, ballPositionBuffer_);
  vertexAttribute(this, 1, 3, GL_FLOAT, sizeof(Float3), 0, false);
  glBindBuffer(GL_ARRAY_BUFFER, ballAttributeBuffer_);
  vertexAttribute(this, 2, 1, GL_FLOAT, sizeof(BallAttributes), offsetof(BallAttributes, radius),
                  false);
  vertexAttribute(this, 3, 4, GL_UNSIGNED_BYTE, sizeof(BallAttributes),
                  offsetof(BallAttributes, color), false);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SceneView::createPlaneBuffers() {
  glGenBuffers(1, &planeVertexBuffer_);
  glGenVertexArrays(1, &planeVao_);
  glBindVertexArray(planeVao_);
  glBindBuffer(GL_ARRAY_BUFFER, planeVertexBuffer_);
  vertexAttribute(this, 0, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, position),
                  false);
  vertexAttribute(this, 1, 3, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, normal), false);
  vertexAttribute(this, 2, 2, GL_FLOAT, sizeof(PlaneVertex), offsetof(PlaneVertex, grid), false);
  vertexAttribute(this, 3, 4, GL_UNSIGNED_BYTE, sizeof(PlaneVertex), offsetof(PlaneVertex, color),
                  false);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// One mesh, drawn once per cylinder with the cylinder's ends, radius and colour per instance.
void SceneView::createCylinderBuffers() {
  std::array<GLuint, 2> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  cylinderVertexBuffer_ = buffers[0];
  cylinderInstanceBuffer_ = buffers[1];
  glGenVertexArrays(1, &cylinderVao_);
  createCylinderMesh();
  glBindVertexArray(cylinderVao_);
  glBindBuffer(GL_ARRAY_BUFFER, cylinderVertexBuffer_);
  vertexAttribute(this, 0, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, local),
                  false);
  vertexAttribute(this, 1, 3, GL_FLOAT, sizeof(CylinderVertex), offsetof(CylinderVertex, normal),
                  false);
  glBindBuffer(GL_ARRAY_BUFFER, cylinderInstanceBuffer_);
  const std::array<std::pair<GLint, std::size_t>, 3> floatFields = {
      std::pair<GLint, std::size_t>{3, offsetof(CylinderInstance, start)},
      {3, offsetof(CylinderInstance, end)},
      {1, offsetof(CylinderInstance, radius)}};
  for (GLuint location = 2; const auto& [components, offset] : floatFields) {
    vertexAttribute(this, location, components, GL_FLOAT, sizeof(CylinderInstance), offset, true);
    ++location;
  }
  vertexAttribute(this, 5, 4, GL_UNSIGNED_BYTE, sizeof(CylinderInstance),
                  offsetof(CylinderInstance, color), true);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SceneView::createCylinderMesh() {
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
  uploadBuffer(this, cylinderVertexBuffer_, vertices, GL_STATIC_DRAW);
}

// One cube, drawn once per box with its centre, half axes and colour per instance.
void SceneView::createBoxBuffers() {
  std::array<GLuint, 2> buffers{};
  glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  boxVertexBuffer_ = buffers[0];
  boxInstanceBuffer_ = buffers[1];
  glGenVertexArrays(1, &boxVao_);
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
  uploadBuffer(this, boxVertexBuffer_, vertices, GL_STATIC_DRAW);
  glBindVertexArray(boxVao_);
  glBindBuffer(GL_ARRAY_BUFFER, boxVertexBuffer_);
  vertexAttribute(this, 0, 3, GL_FLOAT, sizeof(BoxVertex), offsetof(BoxVertex, local), false);
  vertexAttribute(this, 1, 3, GL_FLOAT, sizeof(BoxVertex), offsetof(BoxVertex, normal), false);
  glBindBuffer(GL_ARRAY_BUFFER, boxInstanceBuffer_);
  vertexAttribute(this, 2, 3, GL_FLOAT, sizeof(BoxInstance), offsetof(BoxInstance, center), true);
  for (GLuint k = 0; k < 3; ++k)
    vertexAttribute(this, 3 + k, 3, GL_FLOAT, sizeof(BoxInstance),
                    offsetof(BoxInstance, halfAxes) + k * sizeof(Float3), true);
  vertexAttribute(this, 6, 4, GL_UNSIGNED_BYTE, sizeof(BoxInstance), offsetof(BoxInstance, color),
                  true);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SceneView::releaseGl() {
  if (!glReady_) return;
  glReady_ = false;
  cancelPicture();
  shownTarget_ = -1;
  multisample_.reset();
  for (auto& target : pictureTargets_) target.reset();
  ballProgram_.reset();
  planeProgram_.reset();
  cylinderProgram_.reset();
  boxProgram_.reset();
  lineRenderer_.reset();
  explosionRenderer_.reset();
  const std::array<GLuint, 8> buffers = {
      ballIndexBuffer_,      ballPositionBuffer_,     ballAttributeBuffer_, planeVertexBuffer_,
      cylinderVertexBuffer_, cylinderInstanceBuffer_, boxVertexBuffer_,     boxInstanceBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  const std::array<GLuint, 4> arrays = {ballVao_, planeVao_, cylinderVao_, boxVao_};
  glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
  ballIndexBuffer_ = ballPositionBuffer_ = ballAttributeBuffer_ = 0;
  planeVertexBuffer_ = cylinderVertexBuffer_ = cylinderInstanceBuffer_ = 0;
  boxVertexBuffer_ = boxInstanceBuffer_ = 0;
  ballVao_ = planeVao_ = cylinderVao_ = boxVao_ = 0;
}

void SceneView::setHighlighted(std::vector<int> balls, std::vector<int> planes,
                               std::vector<int> cylinders, std::vector<int> boxes) {
  highlightedBalls_ = std::move(balls);
  highlightedPlanes_ = std::move(planes);
  highlightedCylinders_ = std::move(cylinders);
  highlightedBoxes_ = std::move(boxes);
  staticDataDirty_ = true;
  contentChanged();
}

void SceneView::setHandleArrows(std::vector<std::pair<Vec3, Vec3>> arrows) {
  handleArrows_ = std::move(arrows);
  contentChanged();
}

void SceneView::setTrails(std::vector<Trail> trails) {
  trails_ = std::move(trails);
  contentChanged();
}

void SceneView::setVelocityArrows(std::vector<Arrow> arrows) {
  velocityArrows_ = std::move(arrows);
  contentChanged();
}

Eigen::AlignedBox3d SceneView::clipBox() const {
  if (!scene_) return Eigen::AlignedBox3d(Vec3::Constant(-1e300), Vec3::Constant(1e300));
  return Eigen::AlignedBox3d(scene_->bounds.min, scene_->bounds.max);
}

bool SceneView::antialiasing() const {
  return antialiasingChoice_.value_or(!softwareRenderer_);
}

void SceneView::setAntialiasing(bool on) {
  const bool before = antialiasing();
  antialiasingChoice_ = on;
  if (antialiasing() != before) emit antialiasingChanged(antialiasing());
  contentChanged();
}

void SceneView::uploadStaticData() {
  staticDataDirty_ = false;
  uploadBallAttributes(std::numeric_limits<std::size_t>::max());
  std::vector<PlaneVertex> planeVertices;
  std::vector<CylinderInstance> cylinders;
  std::vector<BoxInstance> boxes;
  if (scene_) {
    const std::vector<bool> selectedPlanes = membership(highlightedPlanes_, scene_->planes.size());
    const std::vector<bool> selectedCylinders =
        membership(highlightedCylinders_, scene_->cylinders.size());
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
      if ((cylinder.end - cylinder.start).norm() == 0.0) continue;  // misses the horizon
      cylinders.push_back({toFloat3(cylinder.start), toFloat3(cylinder.end),
                           static_cast<float>(cylinder.radius),
                           pack(shown(cylinder.color, selectedCylinders[index]))});
    }
    const std::vector<bool> selectedBoxes = membership(highlightedBoxes_, scene_->boxes.size());
    for (std::size_t index = 0; index < scene_->boxes.size(); ++index) {
      const RenderBox& box = scene_->boxes[index];
      boxes.push_back(
          {toFloat3(box.center),
           {toFloat3(box.halfAxes[0]), toFloat3(box.halfAxes[1]), toFloat3(box.halfAxes[2])},
           pack(shown(box.color, selectedBoxes[index]))});
    }
    boxGridSpacing_ = static_cast<float>(scene_->gridSpacing > 0.0 ? scene_->gridSpacing : 1.0);
  }
  uploadBuffer(this, planeVertexBuffer_, planeVertices, GL_STATIC_DRAW);
  uploadBuffer(this, cylinderInstanceBuffer_, cylinders, GL_STATIC_DRAW);
  planeVertexCount_ = static_cast<int>(planeVertices.size());
  cylinderInstanceCount_ = static_cast<int>(cylinders.size());
  uploadBuffer(this, boxInstanceBuffer_, boxes, GL_STATIC_DRAW);
  boxInstanceCount_ = static_cast<int>(boxes.size());
}

void SceneView::paintGL() {
  if (drawsInPieces()) {
    showLastPicture();
    return;
  }
  QElapsedTimer timer;
  timer.start();
  if (staticDataDirty_) uploadStaticData();
  if (positionsDirty_) uploadBallPositions();
  advanceExplosions();
  const bool multisampled = beginFrame();
  camera_.setAspectRatio(static_cast<double>(width()) / std::max(1, height()));
  drawPicture(frameCamera(camera_), height() * devicePixelRatioF(), explosions_.live());
  if (multisampled) multisample_->blitTo(defaultFramebufferObject());
  endFrame();
  emit frameRendered(static_cast<double>(timer.nsecsElapsed()) / 1e6);
}

void SceneView::drawPicture(const FrameCamera& frame, double pixelHeight,
                            const std::vector<ExplosionPool::Live>& explosions) {
  // Balls first: most of the walls and floor behind them then fail the depth test before their
  // shading runs, which is most of the frame on a software renderer.
  drawBalls(frame, pixelHeight);
  drawAfterBalls(frame, explosions, trails_, velocityArrows_, handleArrows_);
}

void SceneView::drawAfterBalls(const FrameCamera& frame,
                               const std::vector<ExplosionPool::Live>& explosions,
                               const std::vector<Trail>& trails,
                               const std::vector<Arrow>& velocityArrows,
                               const std::vector<Arrow>& handleArrows) {
  drawStatics(frame);
  if (scene_) lineRenderer_->drawAxes(frame.viewProjection, scene_->bounds);
  for (const Trail& trail : trails)
    lineRenderer_->drawPath(frame.viewProjection, trail.points, trail.color);
  explosionRenderer_->draw(frame.viewProjection, frame.eye, explosions);
  for (const auto& [base, tip] : velocityArrows)
    lineRenderer_->drawArrow(frame.viewProjection, frame.eye, base, tip, kVelocityColor);
  for (const auto& [base, tip] : handleArrows)
    lineRenderer_->drawArrow(frame.viewProjection, frame.eye, base, tip, kSelectionColor);
  drawOffscreenMarkers(frame);
}

void SceneView::advanceExplosions() {
  explosions_.update(clockSeconds());
  // Explosions fade with time, so frames must keep coming while any show, even when nothing
  // else changes (a paused simulation). Pictures drawn in pieces follow each other anyway.
  if (!explosions_.empty() && !explosionFrameTimer_.isActive() && !drawsInPieces())
    explosionFrameTimer_.start();
}

bool SceneView::beginFrame() {
  const bool multisampled = antialiasing() && multisample_->samples() > 1 &&
                            multisample_->bind(devicePixelSize(), defaultFramebufferObject());
  clearFrame();
  return multisampled;
}

void SceneView::clearFrame() {
  glClearColor(kBackground.x(), kBackground.y(), kBackground.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
}

SceneView::FrameCamera SceneView::frameCamera(const Camera& camera) const {
  return {
      camera.viewProjection(), camera.eye(),
      QVector3D(static_cast<float>(kLightDirection.x()), static_cast<float>(kLightDirection.y()),
                static_cast<float>(kLightDirection.z()))};
}

void SceneView::useProgram(QOpenGLShaderProgram& program, const FrameCamera& frame) {
  program.bind();
  program.setUniformValue("viewProjection", frame.viewProjection);
  program.setUniformValue("eyePosition", frame.eye);
  program.setUniformValue("lightDirection", frame.light);
}

void SceneView::setFadeBeyondBounds(QOpenGLShaderProgram& program) {
  if (!scene_) return;
  const Bounds& bounds = scene_->bounds;
  program.setUniformValue("boundsMin", toQVector(bounds.min));
  program.setUniformValue("boundsMax", toQVector(bounds.max));
  program.setUniformValue("fadeLength", static_cast<float>(kFadeRadii * bounds.radius()));
  program.setUniformValue("backgroundColor", kBackground);
}

void SceneView::drawStatics(const FrameCamera& frame) {
  // Also hides the walls seen from outside (their front faces point into the room), which is
  // what lets the camera look in from beyond them.
  glEnable(GL_CULL_FACE);
  if (cylinderInstanceCount_ > 0) {
    useProgram(*cylinderProgram_, frame);
    setFadeBeyondBounds(*cylinderProgram_);
    glBindVertexArray(cylinderVao_);
    glDrawArraysInstanced(GL_TRIANGLES, 0, cylinderVertexCount_, cylinderInstanceCount_);
  }
  if (boxInstanceCount_ > 0) {
    useProgram(*boxProgram_, frame);
    boxProgram_->setUniformValue("gridSpacing", boxGridSpacing_);
    glBindVertexArray(boxVao_);
    glDrawArraysInstanced(GL_TRIANGLES, 0, boxVertexCount_, boxInstanceCount_);
  }
  if (planeVertexCount_ > 0) {
    useProgram(*planeProgram_, frame);
    setFadeBeyondBounds(*planeProgram_);
    glBindVertexArray(planeVao_);
    // Pushed back by a step of depth, so that lines lying in a plane (the axes) show on it.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, planeVertexCount_);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
}

void SceneView::endFrame() {
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  // Waiting for the GPU makes the frame time cover the drawing itself, not only its submission.
  glFinish();
}

}  // namespace carom::render
