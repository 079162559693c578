#pragma once
// The view's editing tools, as Tiled's: Select (click to pick, drag to move), Add Ball, Add
// Plane, Add Cylinder and Add Box (click to place). They watch the view's mouse and keys and
// change the scene only through the document, one command per click or drag.

#include "sim/geometry/ray_cast.h"
#include "sim/model/scene.h"
#include "ui/editor/object_handles.h"
#include "ui/editor/object_ref.h"
#include "ui/editor/scene_change.h"
#include "ui/editor/standing.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointF>

#include <optional>
#include <vector>

class QMouseEvent;

namespace carom::render {
class SceneView;
}

namespace carom::editor {

class SceneDocument;

class EditorTools : public QObject {
  Q_OBJECT
 public:
  enum class Tool { Select, AddBall, AddPlane, AddCylinder, AddBox };

  EditorTools(SceneDocument* document, render::SceneView* view, QObject* parent = nullptr);

  Tool tool() const { return tool_; }
  void setTool(Tool tool);
  // Moves land on multiples of gridStep() on every axis.
  bool snapToGrid() const { return snapToGrid_; }
  void setSnapToGrid(bool on) { snapToGrid_ = on; }
  static constexpr double gridStep() { return 0.25; }
  // The length of the cylinders Add Cylinder places (none: infinite). It follows the cylinder
  // last added or changed, or the last one of a scene opened.
  std::optional<double> cylinderLength() const { return cylinderLength_; }
  void setCylinderLength(std::optional<double> length);

  // A plane's normal and a cylinder's axis arrows are this fraction of the view's clip box.
  static constexpr double kDirectionArrowFraction = 0.12;

  // The selected object's handles (object_handles.h).
  using Handle = editor::Handle;
  using HandleRole = editor::HandleRole;
  // A run is in progress and the view shows its balls at `positions` (empty: the scene's
  // start, being edited). Then a Select drag on a ball grabs it in the running world
  // (grabStarted, grabMoved, grabReleased) instead of moving it in the scene.
  void setRunningBalls(std::vector<Vec3> positions) { runningBalls_ = std::move(positions); }

  // The arrows a single selected object shows (objectHandles()).
  std::vector<Handle> handles() const;

 signals:
  void toolChanged(Tool tool);
  // A placement or move was refused; the text says why.
  void refused(const QString& message);
  // A grab (setRunningBalls): the ball, where its centre is to go (in the plane facing the
  // camera, on the axis held, snapped as moves are), and the cursor's velocity at the release
  // in world units per real second (zero when it had stopped).
  void grabStarted(int ball);
  void grabMoved(const carom::Vec3& target);
  void grabReleased(const carom::Vec3& velocity);
  // Escape during a grab: the ball is let go without a throw (GrabControl says how).
  void grabCancelled();
  void cylinderLengthChanged();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  // Cancelled: Escape ended the drag; the rest of it, up to the release, does nothing.
  enum class Drag { None, Pending, Objects, Handle, PendingGrab, Grab, Cancelled };
  bool mousePress(QMouseEvent* event);
  bool mouseMove(QMouseEvent* event);
  bool mouseRelease(QMouseEvent* event);
  void place(const QPointF& position);
  // Escape: everything as it was before the press.
  void cancelDrag();
  // The move `offset` of the dragged objects, stopped where it would take them through a
  // surface they stood on at the press: they slide along it under the cursor instead.
  Vec3 keptOnSurfaces(const QPointF& position, Vec3 offset) const;
  void followCylinderLength(const SceneChange& change);
  // A box resting on the surface clicked at `point`: its bottom face on it, its up axis along
  // the surface's `normal`.
  Box boxOn(const Vec3& point, const Vec3& normal, const std::optional<RayHit>& hit) const;
  // The object under the cursor, by ray casting against the true shapes, and where the ray
  // meets it.
  struct Picked {
    ObjectRef ref;
    Vec3 point;
  };
  std::optional<Picked> pick(const QPointF& position) const;
  // The handle whose tip is under the cursor, if any.
  std::optional<Handle> handleAt(const QPointF& position) const;
  // Where the cursor's ray meets the plane through `point` facing the camera.
  std::optional<Vec3> onDragPlane(const QPointF& position, const Vec3& point) const;
  // Where the grabbed face, end or turn handle's tip follows the cursor: along the face's axis
  // or the cylinder's, or in the plane across the box's up axis.
  std::optional<Vec3> onHandlePath(const QPointF& position) const;
  // A box's size or a cylinder's length a face or end drag gives: on the grid when snapping.
  double draggedSize(double size) const;
  void beginDrag(Drag drag, const Selection& objects);
  // Snaps a moved position to the grid when snapping is on, on the locked axis only if one is.
  Vec3 snapped(Vec3 position) const;
  bool pressOnRunningBall(const QPointF& position);
  void moveGrab(const QPointF& position);
  Vec3 releaseVelocity() const;

  SceneDocument* document_;
  render::SceneView* view_;
  Tool tool_ = Tool::Select;
  bool snapToGrid_ = false;
  int axisLock_ = -1;  // 0, 1, 2 while X, Y or Z is held

  Drag drag_ = Drag::None;
  QPointF pressPosition_;
  Vec3 grabPoint_ = Vec3::Zero();
  Handle grabbedHandle_;
  // The dragged objects, and their values when the drag began (as extract() gives them).
  Selection dragged_;
  Scene draggedAtPress_;
  std::vector<Surface> standingOn_;  // what the moved objects stood on at the press
  Selection selectionAtPress_;
  int gesture_ = 0;
  bool refusedDuringDrag_ = false;
  std::vector<Vec3> runningBalls_;
  int grabbedBall_ = -1;
  Vec3 grabbedCentre_ = Vec3::Zero();  // the grabbed ball's centre at the press
  // The grab's recent targets with the real time they were given, for the throw's velocity.
  struct GrabSample {
    qint64 nanoseconds;
    Vec3 target;
  };
  std::vector<GrabSample> grabSamples_;
  QElapsedTimer grabClock_;
  std::optional<double> cylinderLength_;
};

}  // namespace carom::editor
