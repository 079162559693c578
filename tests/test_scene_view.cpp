// The 3D view: camera math, the static render data, and what actually lands in the framebuffer.

#include "ui/render/camera.h"
#include "ui/render/render_scene.h"
#include "ui/render/scene_view.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QSignalSpy>
#include <QTimer>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>
#include <memory>

using carom::Vec3;
using carom::render::Bounds;
using carom::render::Camera;
using carom::render::makeRenderScene;
using carom::render::RenderScene;
using carom::render::SceneView;

namespace {

enum Channel { Red, Green, Blue };

// Lighting scales a colour and adds a little white, but the ball's own channel stays on top.
bool hasHue(QRgb pixel, Channel channel) {
  const int values[3] = {qRed(pixel), qGreen(pixel), qBlue(pixel)};
  const int own = values[channel];
  for (int other = 0; other < 3; ++other) {
    if (other != channel && own < values[other] + 50) return false;
  }
  return own >= 80;
}

bool hasAnyBallHue(QRgb pixel) {
  return hasHue(pixel, Red) || hasHue(pixel, Green) || hasHue(pixel, Blue);
}

QString describe(QRgb pixel) {
  return QStringLiteral("rgb(%1, %2, %3)").arg(qRed(pixel)).arg(qGreen(pixel)).arg(qBlue(pixel));
}

carom::Ball ball(const Vec3& position, const char* color) {
  carom::Ball b;
  b.position = position;
  b.radius = 0.5;
  b.color = color;
  return b;
}

// A grey floor, a grey post, and three balls in pure red, green and blue side by side.
carom::Scene testScene() {
  carom::Scene scene;
  carom::Plane floor;
  floor.point = Vec3(0, 0, 0);
  floor.normal = Vec3(0, 1, 0);
  floor.color = "#808080";
  scene.planes.push_back(floor);
  carom::Cylinder post;
  post.point = Vec3(2.5, 0, -1.5);
  post.axis = Vec3(0, 1, 0);
  post.radius = 0.3;
  post.color = "#a0a0a0";
  scene.cylinders.push_back(post);
  scene.balls.push_back(ball(Vec3(-1.5, 1, 0), "#ff0000"));
  scene.balls.push_back(ball(Vec3(0, 1, 0), "#00ff00"));
  scene.balls.push_back(ball(Vec3(1.5, 1, 0), "#0000ff"));
  return scene;
}

// The room of resources/scenes/magic-room.json, without its balls' motion.
carom::Scene magicRoom() {
  carom::Scene scene;
  const auto plane = [&](Vec3 point, Vec3 normal) {
    carom::Plane p;
    p.point = point;
    p.normal = normal;
    scene.planes.push_back(p);
  };
  plane(Vec3(0, -3.2, 0), Vec3(0, 1, 0));
  plane(Vec3(3.2, 0, 0), Vec3(-1, 0, 0));
  plane(Vec3(-3.2, 0, 0), Vec3(1, 0, 0));
  plane(Vec3(0, 0, 3.2), Vec3(0, 0, -1));
  plane(Vec3(0, 0, -3.2), Vec3(0, 0, 1));
  carom::Cylinder rod;
  rod.point = Vec3(-2, 0, 0);
  rod.axis = Vec3(0, 1, 1);
  rod.radius = 0.3;
  scene.cylinders.push_back(rod);
  scene.balls.push_back(ball(Vec3(1.99, 1.8, 0.1), ""));
  scene.balls.push_back(ball(Vec3(-2.75, 3, -2.5), ""));
  return scene;
}

// Collisions of the test scene's red and green balls at `count` points on a line in the air in
// front of them.
std::vector<carom::CollisionRecord> collisionsAt(int count, const Vec3& first, const Vec3& step) {
  std::vector<carom::CollisionRecord> records;
  for (int i = 0; i < count; ++i) {
    carom::CollisionRecord r;
    r.kind = carom::ContactKind::BallBall;
    r.ball = 0;
    r.other = 1;
    r.point = first + i * step;
    r.normalSpeed = 1.0;
    records.push_back(r);
  }
  return records;
}

int brightness(QRgb pixel) {
  return qRed(pixel) + qGreen(pixel) + qBlue(pixel);
}

double distanceBetween(const QPointF& a, const QPointF& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// The editor's selection colour (255, 140, 13), as flat marks show it.
bool isSelectionColour(QRgb pixel) {
  return qRed(pixel) > 225 && std::abs(qGreen(pixel) - 140) < 30 && qBlue(pixel) < 60;
}

// Pixels of `image` in `area` that pass `test`.
template <typename Test>
int countPixels(const QImage& image, const QRect& area, Test test) {
  int count = 0;
  const QRect inside = area.intersected(image.rect());
  for (int y = inside.top(); y <= inside.bottom(); ++y)
    for (int x = inside.left(); x <= inside.right(); ++x) count += test(image.pixel(x, y));
  return count;
}

}  // namespace

class TestSceneView : public QObject {
  Q_OBJECT

 public:
  // QtTest calls this before it creates the QApplication.
  static void initMain() { SceneView::setDefaultFormat(); }

 private slots:
  void cameraFramePutsCentreInTheMiddle();
  void cameraOrbitKeepsDistance();
  void cameraZoomAndPan();
  void renderSceneClipsToTheRoom();
  void renderSceneDefaultsColours();
  void renderSceneHoldsEveryObject();
  void ballsShowTheirColours();
  void boxesAreDrawnSolid();
  void cappedCylindersEndAtTheirCaps();
  void movingABallMovesItsColour();
  void nearerBallHidesFartherOne_data();
  void nearerBallHidesFartherOne();
  void ballOnTheFloorIsWhole();
  void antialiasingDefaultsByRenderer();
  void antialiasingChangesOnlyEdges();
  void leftDragOrbits();
  void wheelZooms();
  void arrowKeysRotateAndFramingResets();
  void followingKeepsTheBallCentred();
  void explosionsKeepToTheirLimit();
  void explosionsFadeOutWhilePaused();
  void explosionsBrightenTheirPlace();
  void disabledExplosionsShowNothing();
  void rayAtInvertsProject();
  void trailsAndVelocityArrowsAreDrawn();
  void renderPictureDrawsAtItsOwnSize();
  void renderPictureWithoutHighlights();
  void infiniteShapesReachTowardsTheHorizon();
  void ballsOutOfViewAreMarkedAtTheEdge();
  void crowdsDrawSmallBallsAsSprites();
  void hugeScenesAreDrawnInPieces();

 private:
  struct ShownView {
    std::unique_ptr<SceneView> view;
    std::shared_ptr<int> frames = std::make_shared<int>(0);
  };
  ShownView showView(const carom::Scene& scene);
  QRgb pixelAt(SceneView& view, const QImage& image, const Vec3& world);
};

TestSceneView::ShownView TestSceneView::showView(const carom::Scene& scene) {
  ShownView shown;
  shown.view = std::make_unique<SceneView>();
  auto frames = shown.frames;
  QObject::connect(shown.view.get(), &SceneView::frameRendered, [frames](double) { ++*frames; });
  shown.view->resize(640, 480);
  shown.view->setScene(std::make_shared<const RenderScene>(makeRenderScene(scene)));
  shown.view->show();
  if (!QTest::qWaitForWindowExposed(shown.view.get())) qWarning("view was never exposed");
  return shown;
}

QRgb TestSceneView::pixelAt(SceneView& view, const QImage& image, const Vec3& world) {
  const QPointF point = view.project(world) * view.devicePixelRatioF();
  return image.pixel(qBound(0, qRound(point.x()), image.width() - 1),
                     qBound(0, qRound(point.y()), image.height() - 1));
}

void TestSceneView::cameraFramePutsCentreInTheMiddle() {
  const Bounds bounds{Vec3(-1, 2, -3), Vec3(5, 4, 1)};
  for (double yaw : {0.0, 0.7, -2.5}) {
    for (double pitch : {0.0, 0.6, -1.2}) {
      Camera camera;
      camera.setAspectRatio(16.0 / 9.0);
      camera.setYaw(yaw);
      camera.setPitch(pitch);
      camera.frame(bounds);
      const QPointF centre = camera.projectToNdc(bounds.center());
      QVERIFY2(std::abs(centre.x()) < 1e-4 && std::abs(centre.y()) < 1e-4,
               qPrintable(QStringLiteral("centre at %1, %2").arg(centre.x()).arg(centre.y())));
      // Every corner visible, and the box fills the view rather than floating in it.
      double widest = 0.0;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 point((corner & 1) ? bounds.max.x() : bounds.min.x(),
                         (corner & 2) ? bounds.max.y() : bounds.min.y(),
                         (corner & 4) ? bounds.max.z() : bounds.min.z());
        const QPointF ndc = camera.projectToNdc(point);
        QVERIFY(std::abs(ndc.x()) <= 1.0 && std::abs(ndc.y()) <= 1.0);
        widest = std::max({widest, std::abs(ndc.x()), std::abs(ndc.y())});
      }
      QVERIFY2(widest > 0.8, qPrintable(QString::number(widest)));
      QCOMPARE(camera.yaw(), yaw);
      QCOMPARE(camera.pitch(), pitch);
    }
  }
}

void TestSceneView::cameraOrbitKeepsDistance() {
  Camera camera;
  camera.setTarget(QVector3D(1, 2, 3));
  camera.setDistance(7.5);
  const double yaw = camera.yaw();
  const double pitch = camera.pitch();
  camera.orbit(0.4, -0.3);
  QVERIFY(std::abs(camera.yaw() - (yaw + 0.4)) < 1e-12);
  QVERIFY(std::abs(camera.pitch() - (pitch - 0.3)) < 1e-12);
  QVERIFY(std::abs((camera.eye() - camera.target()).length() - 7.5) < 1e-4);
  QCOMPARE(camera.distance(), 7.5);
  // Never over the top: the view would flip.
  camera.orbit(0.0, 10.0);
  QCOMPARE(camera.pitch(), Camera::kMaxPitch);
  QVERIFY(std::abs((camera.eye() - camera.target()).length() - 7.5) < 1e-4);
}

void TestSceneView::cameraZoomAndPan() {
  Camera camera;
  camera.setDistance(10.0);
  camera.zoom(2.0);
  QVERIFY(std::abs(camera.distance() - 10.0 * Camera::kZoomFactor * Camera::kZoomFactor) < 1e-9);
  camera.zoom(-2.0);
  QVERIFY(std::abs(camera.distance() - 10.0) < 1e-9);

  // Panning by a whole view height moves the old target to the top edge of the view.
  const QVector3D target = camera.target();
  camera.pan(0.0, 0.5);
  QVERIFY((camera.target() - target).length() > 1.0);
  QCOMPARE(camera.distance(), 10.0);
  const QPointF old = camera.projectToNdc(Vec3(target.x(), target.y(), target.z()));
  QVERIFY2(std::abs(old.x()) < 1e-4 && std::abs(old.y() + 1.0) < 1e-3,
           qPrintable(QStringLiteral("%1, %2").arg(old.x()).arg(old.y())));
}

void TestSceneView::renderSceneClipsToTheRoom() {
  const RenderScene scene = makeRenderScene(magicRoom());
  const Bounds& b = scene.bounds;
  QCOMPARE(b.min.x(), -3.2);
  QCOMPARE(b.max.x(), 3.2);
  QCOMPARE(b.min.z(), -3.2);
  QCOMPARE(b.max.z(), 3.2);
  QCOMPARE(b.min.y(), -3.2);
  QVERIFY(b.max.y() > 3.2 + 0.1 && b.max.y() < 5.0);  // a bit above the highest ball

  // Infinite planes and cylinders are drawn out to the horizon, a box as much larger on every
  // side.
  const Bounds& h = scene.horizon;
  const double margin = carom::render::kHorizonRadii * b.radius();
  QVERIFY((h.min - (b.min - Vec3::Constant(margin))).norm() < 1e-9);
  QVERIFY((h.max - (b.max + Vec3::Constant(margin))).norm() < 1e-9);
  QCOMPARE(scene.planes.size(), std::size_t{5});
  for (const auto& plane : scene.planes) {
    QCOMPARE(plane.polygon.size(), std::size_t{4});  // each cuts the horizon in a rectangle
    for (std::size_t i = 0; i < plane.polygon.size(); ++i) {
      const Vec3& p = plane.polygon[i];
      QVERIFY(((p - h.min).array() >= -1e-9).all() && ((h.max - p).array() >= -1e-9).all());
      // Counter-clockwise seen from the normal's side: the room's inside.
      const Vec3 turn = (plane.polygon[(i + 1) % 4] - p).cross(plane.polygon[(i + 2) % 4] - p);
      QVERIFY(turn.dot(plane.normal) > 0.0);
    }
  }
  const Vec3 floorSize = scene.planes[0].polygon[2] - scene.planes[0].polygon[0];
  QVERIFY(std::abs(std::abs(floorSize.x()) - (6.4 + 2 * margin)) < 1e-9);
  QVERIFY(std::abs(std::abs(floorSize.z()) - (6.4 + 2 * margin)) < 1e-9);

  // The slanted rod runs through the room from the bottom of the horizon at the back to its
  // front.
  QCOMPARE(scene.cylinders.size(), std::size_t{1});
  const auto& rod = scene.cylinders[0];
  const Vec3 low = rod.start.y() < rod.end.y() ? rod.start : rod.end;
  const Vec3 high = rod.start.y() < rod.end.y() ? rod.end : rod.start;
  QVERIFY((low - Vec3(-2, h.min.z(), h.min.z())).norm() < 1e-9);
  QVERIFY((high - Vec3(-2, h.max.z(), h.max.z())).norm() < 1e-9);

  // A plane that misses the box has nothing to draw.
  QVERIFY(carom::render::clipPlaneToBounds(Vec3(0, 50, 0), Vec3(0, 1, 0), b).empty());
  // A diagonal plane through the centre cuts a hexagon.
  QCOMPARE(carom::render::clipPlaneToBounds(b.center(), Vec3(1, 1, 1), b).size(), std::size_t{6});
}

// Planes and cylinders placed away from the balls, or beyond a wall, are drawn through their own
// points (the box was the balls' and hid them).
// A capped cylinder is drawn between its caps, closed, and not beyond them.
void TestSceneView::cappedCylindersEndAtTheirCaps() {
  carom::Scene scene = testScene();
  carom::Cylinder stump;
  stump.point = Vec3(1.2, 0.4, 1.3);
  stump.axis = Vec3(0, 2, 0);
  stump.radius = 0.3;
  stump.length = 0.8;
  stump.color = "#00ff00";
  scene.cylinders.push_back(stump);
  const RenderScene render = makeRenderScene(scene);
  QVERIFY((render.cylinders[1].start - Vec3(1.2, 0, 1.3)).norm() < 1e-12);
  QVERIFY((render.cylinders[1].end - Vec3(1.2, 0.8, 1.3)).norm() < 1e-12);

  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QImage image = view.grabFramebuffer();
  // The middle of the side towards the camera, and of the top cap.
  for (const Vec3& onStump : {Vec3(1.2, 0.4, 1.6), Vec3(1.2, 0.8, 1.3)}) {
    const QRgb pixel = pixelAt(view, image, onStump);
    QVERIFY2(hasHue(pixel, Green), qPrintable(describe(pixel)));
  }
  const QRgb above = pixelAt(view, image, Vec3(1.2, 1.3, 1.6));
  QVERIFY2(!hasHue(above, Green), qPrintable(describe(above)));
}

void TestSceneView::renderSceneHoldsEveryObject() {
  carom::Scene scene;
  carom::Plane floor;  // a wall of the box: y >= 0
  scene.planes.push_back(floor);
  carom::Ball ball;
  ball.position = Vec3(0, 0.5, 0);
  ball.radius = 0.5;
  scene.balls.push_back(ball);
  carom::Plane far;  // a wall facing the balls from 40 m behind them
  far.point = Vec3(0, 0, -40);
  far.normal = Vec3(0, 0, 1);
  scene.planes.push_back(far);
  carom::Plane below;  // a second floor under the first
  below.point = Vec3(0, -7, 0);
  scene.planes.push_back(below);
  carom::Cylinder post;  // a post 25 m to the side
  post.point = Vec3(-25, 0, 3);
  post.radius = 0.3;
  scene.cylinders.push_back(post);

  const RenderScene render = makeRenderScene(scene);
  const Bounds& b = render.bounds;
  for (const Vec3& point : {far.point, below.point, post.point})
    QVERIFY(((point - b.min).array() >= 0.0).all() && ((b.max - point).array() >= 0.0).all());
  for (const auto& plane : render.planes) QVERIFY(plane.polygon.size() >= 3);
  QVERIFY((render.cylinders[0].end - render.cylinders[0].start).norm() > 0.0);
  // The floor still closes the box where nothing stands beyond it: without the second floor the
  // bottom is the floor itself.
  scene.planes.pop_back();
  QCOMPARE(makeRenderScene(scene).bounds.min.y(), 0.0);
}

void TestSceneView::renderSceneDefaultsColours() {
  const RenderScene scene = makeRenderScene(magicRoom());
  QCOMPARE(scene.ballColors.size(), std::size_t{2});
  QCOMPARE(scene.ballRadii.size(), std::size_t{2});
  QVERIFY(scene.ballColors[0].isValid() && scene.ballColors[1].isValid());
  QVERIFY(scene.ballColors[0] != scene.ballColors[1]);
  const RenderScene colored = makeRenderScene(testScene());
  QCOMPARE(colored.ballColors[1], QColor(0, 255, 0));
  QCOMPARE(colored.planes[0].color, QColor(128, 128, 128));
}

void TestSceneView::ballsShowTheirColours() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QImage image = view.grabFramebuffer();
  QVERIFY(!image.isNull());
  const Channel channels[3] = {Red, Green, Blue};
  for (int i = 0; i < 3; ++i) {
    const QRgb pixel = pixelAt(view, image, scene.balls[i].position);
    QVERIFY2(hasHue(pixel, channels[i]), qPrintable(describe(pixel)));
  }
  // Near the top corner there is floor or background, nothing ball-coloured.
  const QRgb corner = image.pixel(4, 4);
  QVERIFY2(!hasAnyBallHue(corner), qPrintable(describe(corner)));
  const QRgb floor = pixelAt(view, image, Vec3(-1.5, 0, 1.5));
  QVERIFY2(!hasAnyBallHue(floor), qPrintable(describe(floor)));
}

// A blue box, turned, stands on the floor in front of the red ball: its top face and its front
// face show blue, and the floor beside it does not. The render scene keeps its own axes.
void TestSceneView::boxesAreDrawnSolid() {
  carom::Scene scene = testScene();
  carom::Box box;
  box.center = Vec3(-1.5, 0.6, 1.2);
  box.halfExtents = Vec3(0.6, 0.6, 0.3);
  box.rotation = carom::Rotation{Vec3::UnitY(), 20};
  box.color = "#0000ff";
  scene.boxes.push_back(box);
  const RenderScene render = makeRenderScene(scene);
  QCOMPARE(render.boxes.size(), std::size_t{1});
  QVERIFY(std::abs(render.boxes[0].halfAxes[0].norm() - 0.6) < 1e-12);
  QVERIFY(std::abs(render.boxes[0].halfAxes[1].y() - 0.6) < 1e-12);
  QCOMPARE(render.boxes[0].color, QColor(0, 0, 255));

  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QImage image = view.grabFramebuffer();
  // The top face's middle and the middle of the face towards the camera (+z).
  for (const Vec3& onBox : {Vec3(-1.5, 1.2, 1.2), Vec3(-1.5, 0.6, 1.5)}) {
    const QRgb pixel = pixelAt(view, image, onBox);
    QVERIFY2(hasHue(pixel, Blue), qPrintable(describe(pixel)));
  }
  const QRgb floor = pixelAt(view, image, Vec3(0.8, 0, 1.6));
  QVERIFY2(!hasHue(floor, Blue), qPrintable(describe(floor)));
}

void TestSceneView::movingABallMovesItsColour() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Vec3 from = scene.balls[0].position;
  const Vec3 to(0, 1, 1.5);
  QVERIFY(hasHue(pixelAt(view, view.grabFramebuffer(), from), Red));
  QVERIFY(!hasHue(pixelAt(view, view.grabFramebuffer(), to), Red));

  const int before = *shown.frames;
  view.setBallPositions({to, scene.balls[1].position, scene.balls[2].position});
  QTRY_VERIFY(*shown.frames > before);  // the view asked for a frame by itself
  const QImage image = view.grabFramebuffer();
  QVERIFY2(hasHue(pixelAt(view, image, to), Red), qPrintable(describe(pixelAt(view, image, to))));
  QVERIFY2(!hasHue(pixelAt(view, image, from), Red),
           qPrintable(describe(pixelAt(view, image, from))));
}

void TestSceneView::nearerBallHidesFartherOne_data() {
  QTest::addColumn<bool>("nearerFirst");  // in the scene's order
  QTest::newRow("nearer first") << true;
  QTest::newRow("nearer last") << false;
}

// Balls are drawn as flat discs, nearest first; the depth test must still hide the farther ball
// wherever the nearer one covers it, whatever their order in the scene.
void TestSceneView::nearerBallHidesFartherOne() {
  QFETCH(bool, nearerFirst);
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QVector3D eye = view.camera().eye();
  const Vec3 nearer = scene.balls[1].position;
  const Vec3 away = (nearer - Vec3(eye.x(), eye.y(), eye.z())).normalized();
  const Vec3 across = away.cross(Vec3::UnitY()).normalized();
  // Behind the nearer ball along the line of sight, and 0.35 to the side: within its outline.
  const Vec3 farther = nearer + 1.5 * away + 0.35 * across;
  const Vec3 elsewhere(0, 1, 30);  // the third ball, out of the way
  // Green is the nearer ball, red the farther.
  view.setBallPositions(nearerFirst ? std::vector<Vec3>{farther, nearer, elsewhere}
                                    : std::vector<Vec3>{nearer, farther, elsewhere});
  if (!nearerFirst) {
    carom::Scene swapped = scene;
    std::swap(swapped.balls[0].color, swapped.balls[1].color);
    view.setScene(std::make_shared<const RenderScene>(makeRenderScene(swapped)));
    view.setBallPositions({nearer, farther, elsewhere});
  }
  const int before = *shown.frames;
  QTRY_VERIFY(*shown.frames > before);
  const QImage image = view.grabFramebuffer();
  const QRgb covered = pixelAt(view, image, farther);
  QVERIFY2(hasHue(covered, Green), qPrintable(describe(covered)));
  // The farther ball shows beside the nearer one.
  const QRgb beside = pixelAt(view, image, farther + 0.45 * across);
  QVERIFY2(hasHue(beside, Red), qPrintable(describe(beside)));
}

// The floor, drawn after the balls, must not cut into a ball resting on it.
void TestSceneView::ballOnTheFloorIsWhole() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Vec3 resting(-1.5, 0.5, 0);  // radius 0.5: touching the floor
  view.setBallPositions({resting, scene.balls[1].position, scene.balls[2].position});
  const int before = *shown.frames;
  QTRY_VERIFY(*shown.frames > before);
  const QImage image = view.grabFramebuffer();
  // Points of the sphere a little above where it touches the floor, on the side facing the
  // camera, and its centre.
  const QVector3D eye = view.camera().eye();
  Vec3 towardsEye = Vec3(eye.x(), 0, eye.z()) - Vec3(resting.x(), 0, resting.z());
  towardsEye.normalize();
  for (const Vec3& point : {resting, Vec3(resting + 0.45 * towardsEye + Vec3(0, -0.15, 0))}) {
    const QRgb pixel = pixelAt(view, image, point);
    QVERIFY2(hasHue(pixel, Red), qPrintable(describe(pixel)));
  }
}

void TestSceneView::antialiasingDefaultsByRenderer() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  // Mesa's llvmpipe under Xvfb in CI: off there, on with a graphics card.
  QCOMPARE(view.antialiasing(), !view.softwareRenderer());
  QSignalSpy changed(&view, &SceneView::antialiasingChanged);
  view.setAntialiasing(!view.antialiasing());
  QCOMPARE(changed.count(), 1);
  QCOMPARE(view.antialiasing(), view.softwareRenderer());
  view.setAntialiasing(view.antialiasing());  // no change, no signal
  QCOMPARE(changed.count(), 1);
}

// Multisampling smooths outlines and leaves the inside of every shape as it was.
void TestSceneView::antialiasingChangesOnlyEdges() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  view.setAntialiasing(false);
  const QImage plain = view.grabFramebuffer();
  view.setAntialiasing(true);
  const QImage smooth = view.grabFramebuffer();
  QCOMPARE(smooth.size(), plain.size());
  int changed = 0;
  for (int y = 0; y < plain.height(); ++y) {
    for (int x = 0; x < plain.width(); ++x) {
      const QRgb a = plain.pixel(x, y), b = smooth.pixel(x, y);
      if (std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
              std::abs(qBlue(a) - qBlue(b)) >
          12)
        ++changed;
    }
  }
  // Outlines of three balls, a post and the floor's edge are a few thousand pixels of 300,000.
  QVERIFY2(changed > 50, qPrintable(QString::number(changed)));
  QVERIFY2(changed < plain.width() * plain.height() / 20, qPrintable(QString::number(changed)));
  for (const carom::Ball& ball : scene.balls) {
    const QRgb a = pixelAt(view, plain, ball.position), b = pixelAt(view, smooth, ball.position);
    QVERIFY2(std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
                     std::abs(qBlue(a) - qBlue(b)) <=
                 6,
             qPrintable(describe(a) + " vs " + describe(b)));
  }
}

void TestSceneView::leftDragOrbits() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const double yaw = view.camera().yaw();
  const double pitch = view.camera().pitch();
  const QPointF blueBefore = view.project(scene.balls[2].position);

  const QPoint start(320, 240);
  const QPoint end(400, 200);
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, start);
  QTest::mouseMove(&view, end);
  QTRY_VERIFY(view.camera().yaw() != yaw);
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, end);
  QVERIFY(view.camera().yaw() < yaw);      // dragging right turns the scene right
  QVERIFY(view.camera().pitch() < pitch);  // dragging up looks from lower
  QVERIFY(distanceBetween(view.project(scene.balls[2].position), blueBefore) > 5.0);

  // The new view is what gets drawn.
  const int before = *shown.frames;
  QTRY_VERIFY(*shown.frames > before);
  const QImage image = view.grabFramebuffer();
  QVERIFY(hasHue(pixelAt(view, image, scene.balls[2].position), Blue));
}

void TestSceneView::wheelZooms() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const double distance = view.camera().distance();
  const QPointF centre(320, 240);
  QWheelEvent closer(centre, view.mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                     Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(&view, &closer);
  QVERIFY(std::abs(view.camera().distance() - distance * Camera::kZoomFactor) < 1e-9);
  QWheelEvent away(centre, view.mapToGlobal(centre), QPoint(), QPoint(0, -240), Qt::NoButton,
                   Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(&view, &away);
  QVERIFY(view.camera().distance() > distance);
}

void TestSceneView::arrowKeysRotateAndFramingResets() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Camera home = view.camera();

  QTest::keyClick(&view, Qt::Key_Left);
  QVERIFY(std::abs(view.camera().yaw() - (home.yaw() + Camera::kKeyStep)) < 1e-9);
  QTest::keyClick(&view, Qt::Key_Right);
  QTest::keyClick(&view, Qt::Key_Right);
  QVERIFY(std::abs(view.camera().yaw() - (home.yaw() - Camera::kKeyStep)) < 1e-9);
  QTest::keyClick(&view, Qt::Key_Up);
  QVERIFY(std::abs(view.camera().pitch() - (home.pitch() + Camera::kKeyStep)) < 1e-9);
  QTest::keyClick(&view, Qt::Key_Down);
  QTest::keyClick(&view, Qt::Key_Down);
  QVERIFY(std::abs(view.camera().pitch() - (home.pitch() - Camera::kKeyStep)) < 1e-9);

  view.camera().zoom(-3);
  view.camera().pan(0.3, 0.1);
  view.frameScene();  // Home, in the window (test_main_window)
  QCOMPARE(view.camera().yaw(), Camera::kDefaultYaw);
  QCOMPARE(view.camera().pitch(), Camera::kDefaultPitch);
  QVERIFY(std::abs(view.camera().distance() - home.distance()) < 1e-9);
  const QPointF centre = view.project(view.scene()->bounds.center());
  QVERIFY(distanceBetween(centre, QPointF(320, 240)) < 0.5);
}

void TestSceneView::followingKeepsTheBallCentred() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  QSignalSpy changes(&view, &SceneView::followedBallChanged);
  view.setFollowedBall(1);
  QCOMPARE(view.followedBall(), 1);
  QCOMPARE(changes.count(), 1);

  const QPointF middle(320, 240);
  std::vector<Vec3> positions = {scene.balls[0].position, Vec3(-2, 1.5, 1.5),
                                 scene.balls[2].position};
  view.setBallPositions(positions);
  QVERIFY(distanceBetween(view.project(positions[1]), middle) < 0.5);
  const int before = *shown.frames;
  QTRY_VERIFY(*shown.frames > before);
  const QImage image = view.grabFramebuffer();
  const QRgb centrePixel = image.pixel(image.width() / 2, image.height() / 2);
  QVERIFY2(hasHue(centrePixel, Green), qPrintable(describe(centrePixel)));

  // Once released, the camera stays where it was.
  view.setFollowedBall(-1);
  positions[1] = Vec3(2, 0.5, -1);
  view.setBallPositions(positions);
  QVERIFY(distanceBetween(view.project(positions[1]), middle) > 20.0);
}

void TestSceneView::explosionsKeepToTheirLimit() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  QCOMPARE(view.explosionLimit(), 20);
  for (int batch = 0; batch < 10; ++batch) {
    view.addExplosions(collisionsAt(37, Vec3(-2, 0.5, 1), Vec3(0.1, 0, 0)));
    QVERIFY(view.liveExplosions() <= 20);
    QTest::qWait(20);  // frames in between, each one updating the pool
    QVERIFY(view.liveExplosions() <= 20);
  }
  QCOMPARE(view.liveExplosions(), 20);
  QCOMPARE(view.droppedExplosions(), std::uint64_t{370 - 20});

  view.setExplosionLimit(5);
  QVERIFY(view.liveExplosions() <= 5);
  view.addExplosions(collisionsAt(50, Vec3(-2, 0.5, 1), Vec3(0.1, 0, 0)));
  QVERIFY(view.liveExplosions() <= 5);
  const int before = *shown.frames;
  QTRY_VERIFY(*shown.frames > before + 3);
  QVERIFY(view.liveExplosions() <= 5);
}

void TestSceneView::explosionsFadeOutWhilePaused() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  QElapsedTimer clock;
  clock.start();
  view.addExplosions(collisionsAt(8, Vec3(-1, 0.5, 1), Vec3(0.25, 0, 0)));
  QCOMPARE(view.liveExplosions(), 8);
  // No new ball positions: the view must keep drawing by itself for them to fade.
  const int before = *shown.frames;
  QTRY_VERIFY_WITH_TIMEOUT(view.liveExplosions() == 0, 10000);
  const qint64 lasted = clock.elapsed();
  QVERIFY2(lasted >= 1500 && lasted < 4000, qPrintable(QString::number(lasted)));
  QVERIFY2(*shown.frames > before + 10, qPrintable(QString::number(*shown.frames - before)));
  // Once they are gone it stops asking for frames.
  const int afterFade = *shown.frames;
  QTest::qWait(300);
  QVERIFY(*shown.frames <= afterFade + 1);
  // And 1.7 s after an addition, none is left.
  view.addExplosions(collisionsAt(3, Vec3(0, 0.5, 1), Vec3(0.2, 0, 0)));
  QTest::qWait(1700);
  QTRY_COMPARE(view.liveExplosions(), 0);
}

void TestSceneView::explosionsBrightenTheirPlace() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Vec3 spot(-0.75, 0.6, 1.2);  // in the air in front of the balls, over the floor
  const QImage plain = view.grabFramebuffer();
  view.addExplosions(collisionsAt(1, spot, Vec3::Zero()));
  const QImage lit = view.grabFramebuffer();
  // To look at it: CAROM_EXPLOSIONS_PNG=/tmp/explosions.png.
  if (const QString file = qEnvironmentVariable("CAROM_EXPLOSIONS_PNG"); !file.isEmpty())
    lit.save(file);
  const QRgb before = pixelAt(view, plain, spot);
  const QRgb after = pixelAt(view, lit, spot);
  const QString both = describe(before) + " -> " + describe(after);
  // Yellow light added: red and green up a lot, blue much less.
  QVERIFY2(qRed(after) >= qRed(before) + 60 || qRed(after) == 255, qPrintable(both));
  QVERIFY2(qGreen(after) >= qGreen(before) + 60 || qGreen(after) == 255, qPrintable(both));
  QVERIFY2(qBlue(after) - qBlue(before) < qGreen(after) - qGreen(before), qPrintable(both));
  // Far from it, nothing changes: the corner, and the blue ball on the other side.
  QCOMPARE(lit.pixel(4, 4), plain.pixel(4, 4));
  const QRgb blue = pixelAt(view, lit, scene.balls[2].position);
  QVERIFY2(
      std::abs(brightness(blue) - brightness(pixelAt(view, plain, scene.balls[2].position))) < 6,
      qPrintable(describe(blue)));
}

void TestSceneView::disabledExplosionsShowNothing() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Vec3 spot(-0.75, 0.6, 1.2);
  const QImage plain = view.grabFramebuffer();
  view.addExplosions(collisionsAt(4, spot, Vec3(0.1, 0, 0)));
  QCOMPARE(view.liveExplosions(), 4);
  view.setExplosionsEnabled(false);
  QVERIFY(!view.explosionsEnabled());
  QCOMPARE(view.liveExplosions(), 0);
  view.addExplosions(collisionsAt(4, spot, Vec3(0.1, 0, 0)));
  QCOMPARE(view.liveExplosions(), 0);
  const QImage image = view.grabFramebuffer();
  const QRgb before = pixelAt(view, plain, spot);
  const QRgb after = pixelAt(view, image, spot);
  QVERIFY2(std::abs(brightness(after) - brightness(before)) < 6,
           qPrintable(describe(before) + " -> " + describe(after)));
  view.setExplosionsEnabled(true);
  view.addExplosions(collisionsAt(4, spot, Vec3(0.1, 0, 0)));
  QCOMPARE(view.liveExplosions(), 4);
}

// Picking: the ray under the point where a world point shows passes through that point, from
// the default framing and from a turned, closer, panned camera; and points along the ray under
// any pixel show at that pixel.
void TestSceneView::rayAtInvertsProject() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const std::vector<Vec3> points = {Vec3(0, 1, 0),    Vec3(-1.5, 1, 0), Vec3(2.5, 0, -1.5),
                                    Vec3(-2, 0.1, 2), Vec3(1, 3, -2),   Vec3(0.3, -0.4, 1.7)};
  for (int pose = 0; pose < 2; ++pose) {
    if (pose == 1) {
      view.camera().orbit(1.1, -0.4);
      view.camera().zoom(2.0);
      view.camera().pan(0.1, -0.05);
    }
    const QVector3D eye = view.camera().eye();
    for (const Vec3& point : points) {
      const auto [origin, direction] = view.rayAt(view.project(point));
      QVERIFY(std::abs(direction.norm() - 1.0) < 1e-12);
      const Vec3 toPoint = point - origin;
      const double along = toPoint.dot(direction);
      QVERIFY2(along > 0.0, "the ray points away from the point");
      const double off = (toPoint - along * direction).norm();
      QVERIFY2(off <= 1e-6 * toPoint.norm(),
               qPrintable(
                   QStringLiteral("pose %1: %2 off of %3").arg(pose).arg(off).arg(toPoint.norm())));
      QVERIFY((origin - Vec3(eye.x(), eye.y(), eye.z())).norm() <= 1e-5 * toPoint.norm());
    }
    for (const QPointF& pixel : {QPointF(0, 0), QPointF(view.width(), 0), QPointF(0, view.height()),
                                 QPointF(view.width(), view.height()), QPointF(123.5, 321.25)}) {
      const auto [origin, direction] = view.rayAt(pixel);
      for (double distance : {0.5, 5.0, 50.0}) {
        const QPointF back = view.project(origin + distance * direction);
        // project() works in float: near the eye that is a few 1e-4 of a pixel.
        QVERIFY2(distanceBetween(back, pixel) < 1e-2,
                 qPrintable(QStringLiteral("(%1, %2) came back at (%3, %4)")
                                .arg(pixel.x())
                                .arg(pixel.y())
                                .arg(back.x())
                                .arg(back.y())));
      }
    }
  }
}

// A trail in pure yellow over the floor and a velocity arrow (white) from the green ball show
// where they are put, and go when cleared.
void TestSceneView::trailsAndVelocityArrowsAreDrawn() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const Vec3 trailMiddle(0, 0.05, 2.0);
  const Vec3 arrowMiddle(0, 2.0, 0);  // above the green ball at (0, 1, 0)
  const auto yellow = [](QRgb p) { return qRed(p) > 200 && qGreen(p) > 200 && qBlue(p) < 80; };
  const auto white = [](QRgb p) { return qRed(p) > 220 && qGreen(p) > 220 && qBlue(p) > 220; };
  // Lines are a pixel wide: look within two pixels of where they should be.
  const auto near = [&](const QImage& image, const Vec3& world, auto colour) {
    const QPointF centre = view.project(world) * view.devicePixelRatioF();
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy) {
        const QPoint p(qRound(centre.x()) + dx, qRound(centre.y()) + dy);
        if (image.rect().contains(p) && colour(image.pixel(p))) return true;
      }
    return false;
  };
  QImage image = view.grabFramebuffer();
  QVERIFY(!near(image, trailMiddle, yellow));
  QVERIFY(!near(image, arrowMiddle, white));
  view.setTrails({{{Vec3(-2, 0.05, 2), trailMiddle, Vec3(2, 0.05, 2)}, QColor(255, 255, 0)}});
  view.setVelocityArrows({{Vec3(0, 1, 0), Vec3(0, 3, 0)}});
  QCOMPARE(view.trails().size(), std::size_t(1));
  int frames = *shown.frames;
  QTRY_VERIFY(*shown.frames > frames);
  image = view.grabFramebuffer();
  QVERIFY(near(image, trailMiddle, yellow));
  QVERIFY(near(image, arrowMiddle, white));
  view.setTrails({});
  view.setVelocityArrows({});
  frames = *shown.frames;
  QTRY_VERIFY(*shown.frames > frames);
  image = view.grabFramebuffer();
  QVERIFY(!near(image, trailMiddle, yellow));
  QVERIFY(!near(image, arrowMiddle, white));
}

// Offscreen at a size and aspect ratio of its own (the view is 640x480): the balls where the
// same camera at that aspect ratio puts them, each in its colour; sizes out of range give
// nothing; another scene is drawn without disturbing the view's own.
void TestSceneView::renderPictureDrawsAtItsOwnSize() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QSize size(800, 300);
  SceneView::Picture picture = view.picture();
  const QImage image = view.renderPicture(picture, size);
  QCOMPARE(image.size(), size);
  Camera camera = picture.camera;
  camera.setAspectRatio(800.0 / 300.0);
  const Channel channels[3] = {Red, Green, Blue};
  for (int i = 0; i < 3; ++i) {
    const QPointF ndc = camera.projectToNdc(scene.balls[i].position);
    const QPoint at(qRound(0.5 * (ndc.x() + 1.0) * size.width()),
                    qRound(0.5 * (1.0 - ndc.y()) * size.height()));
    QVERIFY2(hasHue(image.pixel(at), channels[i]), qPrintable(describe(image.pixel(at))));
  }
  QVERIFY(!hasAnyBallHue(image.pixel(4, 4)));
  QVERIFY(view.renderPicture(picture, QSize(SceneView::kMinPictureSide - 1, 100)).isNull());
  QVERIFY(view.renderPicture(picture, QSize(100, SceneView::kMaxPictureSide + 1)).isNull());
  // The red ball moved up in a picture of its own; the view still shows it where it was.
  picture.ballPositions[0] = Vec3(-1.5, 2.5, 0);
  const QImage moved = view.renderPicture(picture, size);
  const QPointF ndc = camera.projectToNdc(Vec3(-1.5, 2.5, 0));
  const QPoint at(qRound(0.5 * (ndc.x() + 1.0) * size.width()),
                  qRound(0.5 * (1.0 - ndc.y()) * size.height()));
  QVERIFY(hasHue(moved.pixel(at), Red));
  QCOMPARE(view.ballPositions()[0], scene.balls[0].position);
  view.update();
  const int frames = *shown.frames;
  QTRY_VERIFY(*shown.frames > frames);
  const QImage after = view.grabFramebuffer();
  QVERIFY(hasHue(pixelAt(view, after, scene.balls[0].position), Red));
  QVERIFY(!hasHue(pixelAt(view, after, Vec3(-1.5, 2.5, 0)), Red));
}

// A picture without highlights (a video's) shows a selected ball and plane as if nothing were
// selected, and the view keeps its highlight for the next picture.
void TestSceneView::renderPictureWithoutHighlights() {
  ShownView shown = showView(testScene());
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const QSize size(320, 240);
  SceneView::Picture picture = view.picture();
  QVERIFY(picture.highlights);
  const QImage unselected = view.renderPicture(picture, size);
  view.setHighlighted({0}, {0}, {}, {});
  const QImage selected = view.renderPicture(picture, size);
  QVERIFY(!unselected.isNull());
  QVERIFY(selected != unselected);
  picture.highlights = false;
  QCOMPARE(view.renderPicture(picture, size), unselected);
  picture.highlights = true;
  QCOMPARE(view.renderPicture(picture, size), selected);
}

// From SceneView::kPointSpriteBalls balls on, the small ones are point sprites: one ball more
// than a crowd drawn as squares (a copy of its first ball, which adds no pixel) draws the same
// picture, up to the soft edges and highlights of sprites lit in the screen's frame.
void TestSceneView::crowdsDrawSmallBallsAsSprites() {
  carom::Scene crowd = testScene();
  crowd.balls.clear();
  const int side = 47;  // 103,823 places, for kPointSpriteBalls - 1 balls
  for (int i = 0; static_cast<int>(crowd.balls.size()) + 1 < SceneView::kPointSpriteBalls; ++i) {
    carom::Ball b =
        ball(Vec3(i % side, (i / side) % side, i / (side * side)) * 0.06 + Vec3(-1.4, 0.3, -1.4),
             "#d04040");
    b.radius = 0.02;
    crowd.balls.push_back(b);
  }
  carom::Scene sprites = crowd;
  sprites.balls.push_back(crowd.balls.front());
  carom::Scene empty = crowd;
  empty.balls.clear();
  ShownView shown = showView(crowd);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  // The same camera for all three pictures.
  const auto picture = [&](const carom::Scene& scene) {
    view.setScene(std::make_shared<const RenderScene>(makeRenderScene(scene)));
    view.setBallPositions([&] {
      std::vector<Vec3> at;
      for (const carom::Ball& b : scene.balls) at.push_back(b.position);
      return at;
    }());
    const int before = *shown.frames;
    [&] { QTRY_VERIFY(*shown.frames > before); }();
    return view.grabFramebuffer();
  };
  view.camera();  // fixes the camera where it framed the crowd
  const QImage squares = picture(crowd);
  const QImage points = picture(sprites);
  const QImage room = picture(empty);
  const auto differs = [](QRgb a, QRgb b, int by) {
    return std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
               std::abs(qBlue(a) - qBlue(b)) >
           by;
  };
  int ballPixels = 0, spritePixels = 0, eitherOnly = 0, unlike = 0;
  for (int y = 0; y < room.height(); ++y)
    for (int x = 0; x < room.width(); ++x) {
      const bool square = differs(squares.pixel(x, y), room.pixel(x, y), 30);
      const bool sprite = differs(points.pixel(x, y), room.pixel(x, y), 30);
      ballPixels += square;
      spritePixels += sprite;
      eitherOnly += square != sprite;
      unlike += differs(squares.pixel(x, y), points.pixel(x, y), 60);
    }
  const QString figures = QString(
                              "ball pixels %1 as squares, %2 as sprites, %3 in one only, %4 "
                              "unlike")
                              .arg(ballPixels)
                              .arg(spritePixels)
                              .arg(eitherOnly)
                              .arg(unlike);
  qInfo("%s", qPrintable(figures));
  QVERIFY2(ballPixels > room.width() * room.height() / 10, qPrintable(figures));
  QVERIFY2(eitherOnly < ballPixels / 20, qPrintable(figures));
  QVERIFY2(unlike < ballPixels / 10, qPrintable(figures));
}

// A picture of kPiecewiseBalls or more is drawn offscreen in pieces, with events handled between
// them; the view shows the last whole picture until the next is whole, and that is the picture
// drawn at once.
void TestSceneView::hugeScenesAreDrawnInPieces() {
  carom::Scene crowd = testScene();
  crowd.balls.clear();
  const int count = SceneView::kPiecewiseBalls + 2 * SceneView::kMaxPieceBalls;
  const int side = 78;  // 474,552 places
  const char* colors[] = {"#d04040", "#40d040", "#4040d0"};
  for (int i = 0; i < count; ++i) {
    carom::Ball b =
        ball(Vec3(i % side, (i / side) % side, i / (side * side)) * 0.05 + Vec3(-1.7, 0.3, -1.7),
             colors[i % 3]);
    b.radius = 0.018;
    crowd.balls.push_back(b);
  }
  ShownView shown = showView(crowd);
  SceneView& view = *shown.view;
  QTRY_VERIFY_WITH_TIMEOUT(*shown.frames > 0, 60000);
  view.camera();  // fixes the camera where it framed the crowd
  const QImage first = view.grabFramebuffer();

  std::vector<Vec3> moved;
  for (const carom::Ball& b : crowd.balls) moved.push_back(b.position + Vec3(0.6, 0.0, 0.0));
  int turns = 0;  // of the event loop, while the next picture is drawn
  QTimer turn;
  turn.setInterval(0);
  QObject::connect(&turn, &QTimer::timeout, [&turns] { ++turns; });
  QObject::connect(&view, &SceneView::frameRendered, &turn, &QTimer::stop);
  const int before = *shown.frames;
  view.setBallPositions(moved);
  turn.start();
  // Until the moved picture is whole, the one before shows, never a part of the next.
  QCOMPARE(view.grabFramebuffer(), first);
  QTRY_VERIFY_WITH_TIMEOUT(*shown.frames > before, 60000);
  // At least four pieces of balls, the sort before them and the shapes after.
  QVERIFY2(turns >= 5, qPrintable(QString::number(turns)));
  const QImage pieces = view.grabFramebuffer();
  QVERIFY(pieces != first);
  const QImage atOnce = view.renderPicture(view.picture(), pieces.size());
  QCOMPARE(atOnce.size(), pieces.size());
  int unlike = 0, ballPixels = 0;
  for (int y = 0; y < pieces.height(); ++y)
    for (int x = 0; x < pieces.width(); ++x) {
      unlike += pieces.pixel(x, y) != atOnce.pixel(x, y);
      ballPixels += hasAnyBallHue(pieces.pixel(x, y));
    }
  QVERIFY2(ballPixels > pieces.width() * pieces.height() / 10,
           qPrintable(QString::number(ballPixels)));
  QCOMPARE(unlike, 0);
}

QTEST_MAIN(TestSceneView)
// Infinite planes and cylinders go on beyond the scene's bounds, fading, instead of ending at
// them: seen from twice as far as Home, a green rod along x and a blue floor reach the view's
// sides, where before the bounds ended well inside it and only the background showed.
void TestSceneView::infiniteShapesReachTowardsTheHorizon() {
  carom::Scene scene;
  carom::Plane floor;
  floor.color = "#0000ff";
  scene.planes.push_back(floor);
  carom::Cylinder rod;
  rod.point = Vec3(0, 1.5, 0);
  rod.axis = Vec3(1, 0, 0);
  rod.radius = 0.3;
  rod.color = "#00ff00";
  scene.cylinders.push_back(rod);
  scene.balls.push_back(ball(Vec3(0, 0.5, 1.5), "#ff0000"));
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  view.camera().zoom(-4.0);  // 1.9 times as far
  view.update();
  const int frames = *shown.frames;
  QTRY_VERIFY(*shown.frames > frames);
  const QImage image = view.grabFramebuffer();
  if (const QString folder = qEnvironmentVariable("CAROM_SCREENSHOT_DIR"); !folder.isEmpty())
    image.save(folder + "/infinite-shapes.png");
  // The bounds end this far inside the view: nothing of them in the side strips.
  const Bounds& bounds = view.scene()->bounds;
  double leftmost = image.width(), rightmost = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 point((corner & 1) ? bounds.max.x() : bounds.min.x(),
                     (corner & 2) ? bounds.max.y() : bounds.min.y(),
                     (corner & 4) ? bounds.max.z() : bounds.min.z());
    const double x = view.project(point).x() * view.devicePixelRatioF();
    leftmost = std::min(leftmost, x);
    rightmost = std::max(rightmost, x);
  }
  QVERIFY2(leftmost > 40 && rightmost < image.width() - 40,
           qPrintable(QStringLiteral("bounds from x = %1 to %2").arg(leftmost).arg(rightmost)));
  for (const QRect strip :
       {QRect(0, 0, 12, image.height()), QRect(image.width() - 12, 0, 12, image.height())}) {
    const int rod = countPixels(image, strip, [](QRgb p) { return hasHue(p, Green); });
    const int floorSeen = countPixels(image, strip, [](QRgb p) { return hasHue(p, Blue); });
    QVERIFY2(rod > 12, qPrintable(QStringLiteral("%1 rod pixels").arg(rod)));
    QVERIFY2(floorSeen > 100, qPrintable(QStringLiteral("%1 floor pixels").arg(floorSeen)));
  }
  // Fading: far out the floor is darker than under the ball, nearer the background.
  const QRgb near = pixelAt(view, image, Vec3(1.5, 0, 1.5));
  const QRgb far = image.pixel(6, image.height() - 6);
  QVERIFY2(qBlue(far) < qBlue(near) - 20, qPrintable(describe(near) + " vs " + describe(far)));
}

// A selected ball whose centre is out of the view gets a marker in the selection's colour at
// the view's edge on its side (right, left, and behind the camera somewhere); an unselected one
// gets none, nor does a selected ball in view.
void TestSceneView::ballsOutOfViewAreMarkedAtTheEdge() {
  const carom::Scene scene = testScene();
  ShownView shown = showView(scene);
  SceneView& view = *shown.view;
  QTRY_VERIFY(*shown.frames > 0);
  const auto frameWith = [&](const Vec3& redBall, std::vector<int> selected) {
    view.setHighlighted(std::move(selected), {}, {}, {});
    view.setBallPositions({redBall, scene.balls[1].position, scene.balls[2].position});
    const int frames = *shown.frames;
    [&] { QTRY_VERIFY(*shown.frames > frames); }();
    return view.grabFramebuffer();
  };
  const auto marks = [](const QImage& image, const QRect& area) {
    return countPixels(image, area, isSelectionColour);
  };
  const QVector3D eye = view.camera().eye();
  const QVector3D target = view.camera().target();
  const Vec3 forward = Vec3(target.x() - eye.x(), 0, target.z() - eye.z()).normalized();
  const Vec3 right = forward.cross(Vec3::UnitY());
  const Vec3 centre(target.x(), target.y(), target.z());
  QImage image = frameWith(centre + 40 * right, {0});
  const int w = image.width(), h = image.height();
  const QRect rightEdge(w - 30, 0, 30, h), leftEdge(0, 0, 30, h), middle(30, 30, w - 60, h - 60);
  if (const QString folder = qEnvironmentVariable("CAROM_SCREENSHOT_DIR"); !folder.isEmpty())
    image.save(folder + "/offscreen-marker.png");
  QVERIFY2(marks(image, rightEdge) > 40, qPrintable(QString::number(marks(image, rightEdge))));
  QCOMPARE(marks(image, leftEdge), 0);
  image = frameWith(centre - 40 * right, {0});
  QVERIFY2(marks(image, leftEdge) > 40, qPrintable(QString::number(marks(image, leftEdge))));
  QCOMPARE(marks(image, rightEdge), 0);
  // Behind the camera: marked at some edge, never in the middle.
  image = frameWith(Vec3(eye.x(), eye.y(), eye.z()) - 5 * forward, {0});
  QVERIFY(marks(image, image.rect()) > 40);
  QCOMPARE(marks(image, middle), 0);
  // Not selected, or in view: no marker.
  image = frameWith(centre + 40 * right, {});
  QCOMPARE(marks(image, image.rect()), 0);
  image = frameWith(scene.balls[0].position, {0});
  QCOMPARE(marks(image, rightEdge) + marks(image, leftEdge), 0);
}

#include "test_scene_view.moc"
