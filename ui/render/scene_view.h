#pragma once
// The 3D view of a running scene: OpenGL 3.3 core, the balls as ray-cast impostors nearest
// first, and additive sparks where they collide. Huge scenes are drawn in pieces
// (scene_view_pieces.cpp), so that the window stays responsive while a picture is drawn.
// The view keeps what it shows and when it draws; the GL side of each kind of thing is its
// renderer's (BallRenderer, StaticsRenderer, LineRenderer, ExplosionRenderer).

#include "sim/dynamics/run_stats.h"
#include "ui/render/camera.h"
#include "ui/render/explosion_pool.h"
#include "ui/render/frame_camera.h"
#include "ui/render/render_scene.h"

#include <Eigen/Geometry>
#include <QColor>
#include <QElapsedTimer>
#include <QImage>
#include <QMatrix4x4>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLWidget>
#include <QPoint>
#include <QSize>
#include <QTimer>
#include <QVector3D>

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace carom::render {

class BallRenderer;
class ExplosionRenderer;
class LineRenderer;
class PictureTargets;
class RenderTarget;
class StaticsRenderer;

class SceneView : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
  Q_OBJECT

 public:
  // A ball's recent path, drawn as a line through its points in `color`.
  struct Trail {
    std::vector<Vec3> points;
    QColor color;
  };
  using Arrow = std::pair<Vec3, Vec3>;  // from its base to its tip

  // Everything one picture of the view shows: what renderPicture draws.
  struct Picture {
    std::shared_ptr<const RenderScene> scene;
    std::vector<Vec3> ballPositions;  // one per ball of the scene
    std::vector<ExplosionPool::Live> explosions;
    std::vector<Trail> trails;
    std::vector<Arrow> velocityArrows;
    std::vector<Arrow> handleArrows;
    Camera camera;  // its aspect ratio is the picture's own
    // The selection in its highlight colour and the markers of selected or followed balls out
    // of the picture, as the view shows them; off for a picture of the scene alone (an exported
    // image or video).
    bool highlights = true;
  };
  // Sides of a rendered picture, in pixels.
  static constexpr int kMinPictureSide = 16;
  static constexpr int kMaxPictureSide = 8192;
  // From this many balls on, those small on the screen are drawn as point sprites (ball.vert):
  // a software renderer spent 1.5 s on the squares of a million balls.
  static constexpr int kPointSpriteBalls = 100'000;
  // From this many balls on, a picture is drawn offscreen in pieces of at most kMaxPieceBalls
  // balls, each taking about kPieceMilliseconds, and the GUI thread handles events between
  // them; the view shows the last whole picture meanwhile. A software renderer takes 0.6 s to
  // draw a million balls, which would otherwise stall the whole window at every frame.
  static constexpr int kPiecewiseBalls = 250'000;
  static constexpr int kMaxPieceBalls = 100'000;
  static constexpr int kMinPieceBalls = 5'000;
  static constexpr double kPieceMilliseconds = 25.0;
  // A new scene's ball radii and colours are uploaded this many at a piece (about 1 us each).
  static constexpr int kAttributePieceBalls = 25'000;

  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // OpenGL 3.3 core for every GL surface; call before QApplication exists.
  static void setDefaultFormat();

  // 4x multisampling. Unless set, it is on except on software renderers (llvmpipe), where it
  // costs about half the frame rate; known once the view has been shown.
  bool antialiasing() const;
  void setAntialiasing(bool on);
  bool softwareRenderer() const { return softwareRenderer_; }

  // The first scene set also places the camera (Camera::home); later ones keep it.
  void setScene(std::shared_ptr<const RenderScene> scene);
  std::shared_ptr<const RenderScene> scene() const { return scene_; }
  // One position per ball of the scene, in its order; schedules a repaint.
  void setBallPositions(const std::vector<Vec3>& positions);
  const std::vector<Vec3>& ballPositions() const { return ballPositions_; }

  // Whoever changes the camera calls update(). Taking it for writing also stops the view from
  // re-framing the scene on resize, which it does only until someone moves the camera.
  Camera& camera();
  const Camera& camera() const { return camera_; }
  // Widget coordinates (device-independent pixels) of a world point.
  QPointF project(const Vec3& world) const;
  // Its inverse: the eye and the unit direction of the ray under a point of the widget.
  std::pair<Vec3, Vec3> rayAt(const QPointF& widgetPosition) const;

  // The scene's bounds: infinite planes and cylinders are drawn beyond them, fading out, but
  // picking ignores what lies outside.
  Eigen::AlignedBox3d clipBox() const;
  // Shown in the selection's colour (indices into the scene's balls, planes, cylinders, boxes).
  void setHighlighted(std::vector<int> balls, std::vector<int> planes, std::vector<int> cylinders,
                      std::vector<int> boxes);
  // Arrows drawn on top of everything, each from its base to its tip: the editor's handles of a
  // ball's velocity, a plane's normal, a cylinder's axis, or a box's faces and turn.
  void setHandleArrows(std::vector<std::pair<Vec3, Vec3>> arrows);
  // The recent paths of the balls being watched (the Ball story), drawn in depth with the scene.
  void setTrails(std::vector<Trail> trails);
  const std::vector<Trail>& trails() const { return trails_; }
  // The watched balls' velocities, drawn on top like the handles, in their own colour.
  void setVelocityArrows(std::vector<Arrow> arrows);
  const std::vector<Arrow>& velocityArrows() const { return velocityArrows_; }

  // What the view shows now, with its camera.
  Picture picture() const;
  // Draws `picture` offscreen, into a framebuffer of `size` pixels (each side from
  // kMinPictureSide to kMaxPictureSide), as the view draws itself: the camera keeps its vertical
  // field of view and takes the picture's aspect ratio, and antialiasing is as the view's. Null
  // when the size is out of range, the view has no GL yet (never shown) or the driver refuses
  // the framebuffer. The view's own state is left as it was.
  QImage renderPicture(const Picture& picture, const QSize& size);

  // The camera target tracks this ball; -1 stops. Panning or Home stop it too.
  void setFollowedBall(int index);
  int followedBall() const { return followedBall_; }

  // A yellow spark at each collision's contact point, sized by the ball involved, fading out
  // over ExplosionPool::kLifetime of real time (also while the simulation is paused).
  void addExplosions(const std::vector<carom::CollisionRecord>& collisions);
  // The size given to a collision's explosion in `scene`: the larger ball's radius, scaled.
  static double explosionSize(const RenderScene* scene, const carom::CollisionRecord& collision);
  // Alive at the last frame or addition.
  int liveExplosions() const { return explosions_.count(); }
  // Explosions that did not fit in the pool since the view was made.
  std::uint64_t droppedExplosions() const { return explosions_.dropped(); }
  // Disabling also removes the ones showing.
  void setExplosionsEnabled(bool enabled);
  bool explosionsEnabled() const { return explosionsEnabled_; }
  // At most this many at once (default 20); more are dropped, not queued.
  void setExplosionLimit(int limit);
  int explosionLimit() const { return explosions_.limit(); }

 public slots:
  // Home: the default direction, framing the scene's bounds.
  void frameScene();

 signals:
  // After each picture, with how long drawing it took including the GPU's work: after each
  // paintGL, or after the last piece of a picture drawn in pieces (the sum of its pieces).
  void frameRendered(double milliseconds);
  void followedBallChanged(int index);
  void antialiasingChanged(bool on);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

 private:
  // What a picture shows; the view draws a new one in pieces when this differs.
  struct PictureKey {
    std::uint64_t content = 0;  // contentVersion_
    QMatrix4x4 viewProjection;
    QSize size;
    bool antialiasing = false;
    bool operator==(const PictureKey& other) const = default;
  };
  // The picture being drawn in pieces: what it was given when its first piece began.
  struct PiecewisePicture {
    bool drawing = false;
    int nextBall = -1;  // in drawing order; -1 before the first piece uploaded and sorted
    PictureKey key;
    FrameCamera frame;
    double pixelHeight = 1.0;
    bool multisampled = false;
    std::vector<ExplosionPool::Live> explosions;
    std::vector<Trail> trails;
    std::vector<Arrow> velocityArrows;
    std::vector<Arrow> handleArrows;
    double workMilliseconds = 0.0;
  };

  void detectSoftwareRenderer();
  void releaseGl();
  double clockSeconds() const;
  // The balls' radii and colours and the fixed shapes, with the selection's highlights.
  void uploadStaticData();
  void markBallAttributesDirty();
  void uploadBallPositions();
  void advanceExplosions();
  // Binds the framebuffer to draw into and clears it; true if it is the multisampled one.
  bool beginFrame();
  // Clears the bound framebuffer and sets the state every frame starts from.
  void clearFrame();
  FrameCamera frameCamera(const Camera& camera) const;
  // Everything after the clear, into the bound framebuffer `pixelHeight` device pixels high.
  void drawPicture(const FrameCamera& frame, double pixelHeight,
                   const std::vector<ExplosionPool::Live>& explosions);
  // What drawPicture draws after the balls.
  void drawAfterBalls(const FrameCamera& frame, const std::vector<ExplosionPool::Live>& explosions,
                      const std::vector<Trail>& trails, const std::vector<Arrow>& velocityArrows,
                      const std::vector<Arrow>& handleArrows);
  // At the view's edge, pointing to each selected or followed ball whose centre is outside the
  // picture (scene_view_markers.cpp).
  void drawOffscreenMarkers(const FrameCamera& frame);
  void drawBalls(const FrameCamera& frame, double pixelHeight);
  // The angle of one device pixel at the centre of a picture `pixelHeight` pixels high.
  double pixelAngle(double pixelHeight) const;
  // Sorts the balls for drawing (BallRenderer::prepare); returns how many there are to draw.
  int prepareBalls(const FrameCamera& frame, double pixelHeight);
  // Balls [first, first + count) in drawing order: the squares, then the sprites.
  void drawBallRange(const FrameCamera& frame, double pixelHeight, int first, int count);
  // Marks what the view shows as changed and schedules a repaint.
  void contentChanged();
  QSize devicePixelSize() const;
  // Drawing in pieces (scene_view_pieces.cpp).
  bool drawsInPieces() const;
  PictureKey currentPictureKey() const;
  // paintGL's part when drawing in pieces: shows the last whole picture, and starts the next
  // when what the view shows has changed since the last one began.
  void showLastPicture();
  void drawNextPiece();
  // Returns true when the picture is whole.
  bool drawPiece();
  bool bindPieceTarget();
  int pieceBalls() const;
  // Stops the picture being drawn; the next paint starts another.
  void cancelPicture();
  // Leaves the GL state as Qt's compositing expects it, once the GPU is done.
  void endFrame();
  void followBall();
  void userMovedCamera();

  std::shared_ptr<const RenderScene> scene_;
  std::vector<Vec3> ballPositions_;
  Camera camera_;
  int followedBall_ = -1;
  bool autoFrame_ = true;
  QPoint lastMousePosition_;
  ExplosionPool explosions_;
  bool explosionsEnabled_ = true;
  std::vector<int> highlightedBalls_;
  std::vector<int> highlightedPlanes_;
  std::vector<int> highlightedCylinders_;
  std::vector<int> highlightedBoxes_;
  std::vector<std::pair<Vec3, Vec3>> handleArrows_;
  std::vector<Trail> trails_;
  std::vector<Arrow> velocityArrows_;
  std::optional<bool> antialiasingChoice_;
  bool softwareRenderer_ = false;
  QElapsedTimer clock_;
  QTimer explosionFrameTimer_;  // keeps frames coming while explosions fade
  std::uint64_t contentVersion_ = 0;

  // Drawing in pieces, into pictureTargets_.
  QTimer pieceTimer_;
  PiecewisePicture piecewise_;
  std::optional<PictureKey> drawnKey_;  // of the picture shown or being drawn
  double ballsPerMillisecond_ = 0.0;    // measured in the last piece of balls

  // GL state, valid between initializeGL and releaseGl.
  bool glReady_ = false;
  bool staticDataDirty_ = true;
  bool positionsDirty_ = true;
  std::unique_ptr<BallRenderer> ballRenderer_;
  std::unique_ptr<StaticsRenderer> staticsRenderer_;
  std::unique_ptr<LineRenderer> lineRenderer_;
  std::unique_ptr<ExplosionRenderer> explosionRenderer_;
  std::unique_ptr<RenderTarget> multisample_;
  std::unique_ptr<PictureTargets> pictureTargets_;
};

}  // namespace carom::render
