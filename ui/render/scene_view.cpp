#include "ui/render/scene_view.h"

#include "ui/render/ball_renderer.h"
#include "ui/render/explosion_renderer.h"
#include "ui/render/line_renderer.h"
#include "ui/render/picture_targets.h"
#include "ui/render/render_target.h"
#include "ui/render/statics_renderer.h"
#include "ui/render/view_vertices.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QSize>
#include <QSurfaceFormat>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace carom::render {
namespace {

// Velocity arrows of the watched balls: apart from the handles' orange, the sparks' yellow and
// the trails' tints of the balls' colours.
const QColor kVelocityColor(255, 255, 255);

// ---- Explosions --------------------------------------------------------------------------------

// Half the width of an explosion's quads at birth, in radii of the ball that collided: about
// the tutorial's proportion, so the spark starts a little larger than the ball.
constexpr double kExplosionSizePerRadius = 2.0;
constexpr double kDefaultBallRadius = 0.5;  // when the record names no ball the scene has
constexpr int kExplosionFrameMilliseconds = 16;

// ---- Drawing ------------------------------------------------------------------------------------

constexpr GLint kSamples = 4;  // multisampling, when antialiasing is on

const Vec3 kLightDirection = Vec3(0.35, 1.0, 0.55).normalized();

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
  QOpenGLFunctions_3_3_Core* const gl = this;  // a protected base: make_unique cannot see it
  // Each renderer starts with everything to upload.
  ballRenderer_ = std::make_unique<BallRenderer>(gl, kPointSpriteBalls);
  staticsRenderer_ = std::make_unique<StaticsRenderer>(gl);
  lineRenderer_ = std::make_unique<LineRenderer>(gl);
  explosionRenderer_ = std::make_unique<ExplosionRenderer>(gl);
  multisample_ = std::make_unique<RenderTarget>(gl, multisamples(gl));
  pictureTargets_ = std::make_unique<PictureTargets>(gl);
  glReady_ = true;
  staticDataDirty_ = true;
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

void SceneView::releaseGl() {
  if (!glReady_) return;
  glReady_ = false;
  cancelPicture();
  multisample_.reset();
  pictureTargets_.reset();
  ballRenderer_.reset();
  staticsRenderer_.reset();
  lineRenderer_.reset();
  explosionRenderer_.reset();
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
  ballRenderer_->uploadAttributes(scene_.get(), highlightedBalls_,
                                  std::numeric_limits<std::size_t>::max());
  staticsRenderer_->upload(scene_.get(), highlightedPlanes_, highlightedCylinders_,
                           highlightedBoxes_);
}

void SceneView::markBallAttributesDirty() {
  if (ballRenderer_) ballRenderer_->markAttributesDirty();
}

void SceneView::uploadBallPositions() {
  positionsDirty_ = false;
  ballRenderer_->uploadPositions(scene_.get(), ballPositions_);
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
  // Cylinders, boxes and planes.
  staticsRenderer_->draw(frame, scene_.get());
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

FrameCamera SceneView::frameCamera(const Camera& camera) const {
  return {
      camera.viewProjection(), camera.eye(),
      QVector3D(static_cast<float>(kLightDirection.x()), static_cast<float>(kLightDirection.y()),
                static_cast<float>(kLightDirection.z()))};
}

void SceneView::drawBalls(const FrameCamera& frame, double pixelHeight) {
  drawBallRange(frame, pixelHeight, 0, prepareBalls(frame, pixelHeight));
}

// Per device pixel, so that the soft edge is a pixel wide on any screen.
double SceneView::pixelAngle(double pixelHeight) const {
  const double viewHeightAtUnitDistance =
      2.0 * std::tan(0.5 * camera_.verticalFov() * std::numbers::pi / 180.0);
  return viewHeightAtUnitDistance / std::max(1.0, pixelHeight);
}

int SceneView::prepareBalls(const FrameCamera& frame, double pixelHeight) {
  return ballRenderer_->prepare(scene_.get(), ballPositions_, frame, pixelAngle(pixelHeight));
}

void SceneView::drawBallRange(const FrameCamera& frame, double pixelHeight, int first, int count) {
  ballRenderer_->drawRange(frame, pixelAngle(pixelHeight), first, count);
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
