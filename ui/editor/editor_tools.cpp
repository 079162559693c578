#include "ui/editor/editor_tools.h"

#include "sim/geometry/ray_cast.h"
#include "sim/geometry/shapes.h"
#include "ui/editor/object_kinds.h"
#include "ui/editor/scene_document.h"
#include "ui/render/scene_view.h"

#include <QKeyEvent>
#include <QMouseEvent>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace carom::editor {
namespace {

constexpr double kClickSlopPixels = 4.0;  // a press and release closer than this is a click
constexpr double kTipGrabPixels = 8.0;
// The throw takes the cursor's velocity over this last stretch of a grab (and none when the
// cursor rested that long before the release).
constexpr qint64 kThrowWindowNs = 80'000'000;
constexpr double kDefaultBallRadius = 0.5;
constexpr double kDefaultCylinderRadius = 0.3;
constexpr double kDefaultBoxHalfExtent = 0.5;
// Normals closer than this (1 - cosine) count as the same direction: a box on the floor or on
// an unturned box's top stands unturned.
constexpr double kSameDirection = 1e-9;
constexpr int kNudgeRings = 4;  // free spots tried around a refused placement

Vec3 toVec3(const QVector3D& v) {
  return Vec3(v.x(), v.y(), v.z());
}

// Two unit vectors across `normal`.
std::pair<Vec3, Vec3> tangents(const Vec3& normal) {
  const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = normal.cross(helper).normalized();
  return {u, normal.cross(u)};
}

// The point of the line through `point` along the unit `axis` nearest to the ray; none when
// the ray runs along the line.
std::optional<Vec3> closestOnLine(const Vec3& origin, const Vec3& direction, const Vec3& point,
                                  const Vec3& axis) {
  const Vec3 w = origin - point;
  const double b = axis.dot(direction);
  const double denominator = 1.0 - b * b;
  if (denominator < 1e-9) return std::nullopt;
  const double s = (axis.dot(w) - b * direction.dot(w)) / denominator;
  return point + s * axis;
}

}  // namespace

EditorTools::EditorTools(SceneDocument* document, render::SceneView* view, QObject* parent)
    : QObject(parent), document_(document), view_(view) {
  view_->installEventFilter(this);
  if (!document_->scene().cylinders.empty())
    cylinderLength_ = document_->scene().cylinders.back().length;
  connect(document_, &SceneDocument::sceneChanged, this, &EditorTools::followCylinderLength);
}

void EditorTools::setCylinderLength(std::optional<double> length) {
  if (length == cylinderLength_) return;
  cylinderLength_ = length;
  emit cylinderLengthChanged();
}

void EditorTools::followCylinderLength(const SceneChange& change) {
  const std::vector<Cylinder>& cylinders = document_->scene().cylinders;
  if (change.replaced) {
    setCylinderLength(cylinders.empty() ? std::nullopt : cylinders.back().length);
    return;
  }
  std::optional<int> last;
  for (const Selection* refs : {&change.inserted, &change.edited})
    for (const ObjectRef& ref : *refs)
      if (ref.kind == ObjectKind::Cylinder) last = ref.index;
  if (last) setCylinderLength(cylinders[*last].length);
}

void EditorTools::setTool(Tool tool) {
  if (tool == tool_) return;
  tool_ = tool;
  if (std::exchange(drag_, Drag::None) == Drag::Grab) emit grabReleased(Vec3::Zero());
  emit toolChanged(tool);
}

bool EditorTools::eventFilter(QObject* watched, QEvent* event) {
  if (watched != view_) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress:
      return mousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove:
      return mouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
      return mouseRelease(static_cast<QMouseEvent*>(event));
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
      auto* key = static_cast<QKeyEvent*>(event);
      if (key->key() == Qt::Key_Escape) {
        if (event->type() != QEvent::KeyPress || drag_ == Drag::None || drag_ == Drag::Cancelled)
          return false;
        cancelDrag();
        return true;
      }
      const int axis = key->key() == Qt::Key_X   ? 0
                       : key->key() == Qt::Key_Y ? 1
                       : key->key() == Qt::Key_Z ? 2
                                                 : -1;
      if (axis < 0 || key->isAutoRepeat()) return false;
      axisLock_ = event->type() == QEvent::KeyPress ? axis : -1;
      return drag_ == Drag::Objects || drag_ == Drag::Handle || drag_ == Drag::Grab;
    }
    default:
      return false;
  }
}

std::optional<EditorTools::Picked> EditorTools::pick(const QPointF& position) const {
  const auto [origin, direction] = view_->rayAt(position);
  const Eigen::AlignedBox3d clip = view_->clipBox();
  const std::optional<RayHit> hit = castRay(document_->scene(), origin, direction, &clip);
  if (!hit) return std::nullopt;
  return Picked{{kindOfShape(hit->kind), hit->index}, hit->point};
}

std::vector<EditorTools::Handle> EditorTools::handles() const {
  const Selection& selection = document_->selection();
  if (selection.size() != 1) return {};
  const double arrow = kDirectionArrowFraction * view_->clipBox().diagonal().norm();
  return objectHandles(document_->scene(), selection.front(), arrow);
}

std::optional<EditorTools::Handle> EditorTools::handleAt(const QPointF& position) const {
  std::optional<Handle> nearest;
  double nearestPixels = kTipGrabPixels;
  for (const Handle& arrow : handles()) {
    const QPointF tip = view_->project(arrow.tip);
    const double pixels = std::hypot(tip.x() - position.x(), tip.y() - position.y());
    if (pixels > nearestPixels) continue;
    nearest = arrow;
    nearestPixels = pixels;
  }
  return nearest;
}

std::optional<Vec3> EditorTools::onDragPlane(const QPointF& position, const Vec3& point) const {
  const auto [origin, direction] = view_->rayAt(position);
  const Vec3 facing = toVec3(view_->camera().eye() - view_->camera().target()).normalized();
  // On the locked axis through `point`, nowhere when looking along it.
  if (axisLock_ >= 0) return closestOnLine(origin, direction, point, Vec3::Unit(axisLock_));
  const std::optional<double> t = rayPlaneDistance(origin, direction, point, facing);
  if (!t) return std::nullopt;
  return origin + *t * direction;
}

double EditorTools::draggedSize(double size) const {
  // Never snapped to nothing while the drag still leaves some size: one step is the least.
  if (!snapToGrid_ || size <= 0.0) return size;
  return std::max(1.0, std::round(size / gridStep())) * gridStep();
}

std::optional<Vec3> EditorTools::onHandlePath(const QPointF& position) const {
  const auto [origin, direction] = view_->rayAt(position);
  if (grabbedHandle_.role == HandleRole::CylinderEnd)
    return closestOnLine(origin, direction, grabPoint_,
                         draggedAtPress_.cylinders.front().axis.normalized());
  const BoxShape shape = boxShape(draggedAtPress_.boxes.front());
  if (grabbedHandle_.role == HandleRole::BoxFace)
    return closestOnLine(origin, direction, grabPoint_, shape.axes.col(grabbedHandle_.axis));
  const Vec3 up = shape.axes.col(1);
  const std::optional<double> t = rayPlaneDistance(origin, direction, grabPoint_, up);
  if (!t) return std::nullopt;
  return origin + *t * direction;
}

bool EditorTools::mousePress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  pressPosition_ = event->position();
  refusedDuringDrag_ = false;
  selectionAtPress_ = document_->selection();
  if (tool_ != Tool::Select) {
    drag_ = Drag::Pending;  // a click places; a drag orbits as usual
    return false;
  }
  const bool extend = event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier);
  const bool altDrag = event->modifiers() & Qt::AltModifier;
  // In a run in progress a ball is grabbed before any of the scene's handles is.
  if (!extend && !altDrag && pressOnRunningBall(pressPosition_)) return true;
  if (const std::optional<Handle> grabbed = extend ? std::nullopt : handleAt(pressPosition_)) {
    grabbedHandle_ = *grabbed;
    grabPoint_ = grabbed->tip;
    beginDrag(Drag::Handle, document_->selection());
    return true;
  }
  const std::optional<Picked> picked = pick(pressPosition_);
  if (!picked) {
    drag_ = extend ? Drag::None : Drag::Pending;  // a click on nothing clears the selection
    return false;
  }
  const ObjectRef hit = picked->ref;
  Selection selection = document_->selection();
  const bool selected = std::find(selection.begin(), selection.end(), hit) != selection.end();
  if (extend) {
    if (selected)
      std::erase(selection, hit);
    else
      selection.push_back(hit);
    document_->setSelection(selection);
    drag_ = Drag::None;
    return true;
  }
  if (!selected) document_->setSelection({hit});
  if (altDrag && hit.kind == ObjectKind::Ball) {
    // Alt-drag from a ball draws its velocity from the centre, for balls at rest.
    document_->setSelection({hit});
    grabPoint_ = document_->scene().balls[hit.index].position;
    grabbedHandle_ = Handle{grabPoint_, grabPoint_};
    beginDrag(Drag::Handle, {hit});
    return true;
  }
  grabPoint_ = picked->point;
  beginDrag(Drag::Objects, document_->selection());
  return true;
}

void EditorTools::beginDrag(Drag drag, const Selection& objects) {
  drag_ = drag;
  dragged_ = objects;
  draggedAtPress_ = extract(document_->scene(), dragged_);
  gesture_ = document_->newGesture();
  standingOn_.clear();
  if (drag != Drag::Objects) return;
  for (const ObjectRef& ref : dragged_)
    for (const Surface& surface : surfacesUnder(document_->scene(), ref, dragged_))
      standingOn_.push_back(surface);
}

void EditorTools::cancelDrag() {
  const Drag drag = std::exchange(drag_, Drag::Cancelled);
  if (drag == Drag::Grab) emit grabCancelled();
  if (drag == Drag::Objects || drag == Drag::Handle) {
    // Merged into the drag's command, the values at the press leave it changing nothing, and
    // the stack drops it: no undo step is left behind.
    document_->editObjects(dragged_, draggedAtPress_, QString(), gesture_);
  }
  document_->setSelection(selectionAtPress_);
}

Vec3 EditorTools::keptOnSurfaces(const QPointF& position, Vec3 offset) const {
  bool slid = false;
  for (const Surface& surface : standingOn_) {
    const double into = offset.dot(surface.normal);
    if (into >= 0.0) continue;
    // Held to an axis that leads into the surface: it stays where it stood.
    if (axisLock_ >= 0) return Vec3::Zero();
    // As placing does, the cursor's ray finds the spot on the surface; the grabbed point keeps
    // its height above it.
    const auto [origin, direction] = view_->rayAt(position);
    const std::optional<double> t =
        slid ? std::nullopt : rayPlaneDistance(origin, direction, grabPoint_, surface.normal);
    if (t) {
      offset = origin + *t * direction - grabPoint_;
      slid = true;
    }
    offset -= offset.dot(surface.normal) * surface.normal;
  }
  return offset;
}

bool EditorTools::pressOnRunningBall(const QPointF& position) {
  if (runningBalls_.empty() || runningBalls_.size() != document_->scene().balls.size())
    return false;
  // The balls where the run has them; the static shapes where the scene has them.
  Scene running = document_->scene();
  for (std::size_t i = 0; i < runningBalls_.size(); ++i)
    running.balls[i].position = runningBalls_[i];
  const auto [origin, direction] = view_->rayAt(position);
  const Eigen::AlignedBox3d clip = view_->clipBox();
  const std::optional<RayHit> hit = castRay(running, origin, direction, &clip);
  if (!hit || kindOfShape(hit->kind) != ObjectKind::Ball) return false;
  document_->setSelection({{ObjectKind::Ball, hit->index}});
  // The grab begins when the cursor moves: a click only selects, and leaves the ball alone.
  drag_ = Drag::PendingGrab;
  grabbedBall_ = hit->index;
  grabPoint_ = hit->point;
  grabbedCentre_ = runningBalls_[hit->index];
  return true;
}

void EditorTools::moveGrab(const QPointF& position) {
  const std::optional<Vec3> point = onDragPlane(position, grabPoint_);
  if (!point) return;
  const Vec3 target = snapped(grabbedCentre_ + (*point - grabPoint_));
  const qint64 now = grabClock_.nsecsElapsed();
  grabSamples_.push_back({now, target});
  // The throw takes the cursor's velocity over the last moments of the drag.
  while (grabSamples_.size() > 2 && now - grabSamples_.front().nanoseconds > kThrowWindowNs)
    grabSamples_.erase(grabSamples_.begin());
  emit grabMoved(target);
}

Vec3 EditorTools::releaseVelocity() const {
  if (grabSamples_.size() < 2) return Vec3::Zero();
  const GrabSample& first = grabSamples_.front();
  const GrabSample& last = grabSamples_.back();
  // A cursor that stopped before the button was let go throws nothing.
  if (grabClock_.nsecsElapsed() - last.nanoseconds > kThrowWindowNs) return Vec3::Zero();
  const double seconds = (last.nanoseconds - first.nanoseconds) * 1e-9;
  if (!(seconds > 0.0)) return Vec3::Zero();
  return (last.target - first.target) / seconds;
}

Vec3 EditorTools::snapped(Vec3 position) const {
  if (!snapToGrid_) return position;
  for (int a = 0; a < 3; ++a)
    if (axisLock_ < 0 || axisLock_ == a)
      position[a] = gridStep() * std::round(position[a] / gridStep());
  return position;
}

bool EditorTools::mouseMove(QMouseEvent* event) {
  if (drag_ == Drag::PendingGrab) {
    const QPointF moved = event->position() - pressPosition_;
    if (std::hypot(moved.x(), moved.y()) <= kClickSlopPixels) return true;
    drag_ = Drag::Grab;
    grabSamples_.clear();
    grabClock_.start();
    emit grabStarted(grabbedBall_);
  }
  if (drag_ == Drag::Grab) {
    moveGrab(event->position());
    return true;
  }
  if (drag_ == Drag::Cancelled) return true;
  if (drag_ != Drag::Objects && drag_ != Drag::Handle) return false;
  // A face, end or turn handle keeps to its own path whatever axis key is held.
  const bool onPath = drag_ == Drag::Handle && grabbedHandle_.role != HandleRole::Direction;
  const std::optional<Vec3> point =
      onPath ? onHandlePath(event->position()) : onDragPlane(event->position(), grabPoint_);
  if (!point) return true;
  // Only the dragged objects are copied and changed, never the whole scene.
  const Selection local = extractedRefs(dragged_);
  Scene edited = draggedAtPress_;
  QString text;
  if (drag_ == Drag::Handle) {
    text = dragHandle(
        edited, local.front(),
        {grabbedHandle_, grabPoint_, *point, [this](double size) { return draggedSize(size); }});
  } else {
    const Vec3 offset = keptOnSurfaces(event->position(), *point - grabPoint_);
    for (const ObjectRef& ref : local) {
      const Vec3 from = objectPosition(draggedAtPress_, ref);
      Vec3 moved = snapped(from + offset);
      // Nor does snapping sink it into them.
      for (const Surface& surface : standingOn_)
        moved -= std::min(0.0, (moved - from).dot(surface.normal)) * surface.normal;
      setObjectPosition(edited, ref, moved);
    }
    text = tr("Move");
  }
  QString error = document_->editObjects(dragged_, edited, text, gesture_);
  if (!error.isEmpty() && drag_ == Drag::Objects && axisLock_ < 0) {
    // Most often the move pushes a ball resting on the floor into it: keep the height and
    // slide instead.
    for (const ObjectRef& ref : local) {
      Vec3 moved = objectPosition(edited, ref);
      moved.y() = objectPosition(draggedAtPress_, ref).y();
      setObjectPosition(edited, ref, moved);
    }
    if (document_->editObjects(dragged_, edited, text, gesture_).isEmpty()) error.clear();
  }
  if (!error.isEmpty() && !refusedDuringDrag_) {
    refusedDuringDrag_ = true;  // once per drag; the objects stay at their last valid place
    emit refused(error);
  }
  return true;
}

bool EditorTools::mouseRelease(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  const Drag drag = std::exchange(drag_, Drag::None);
  if (drag == Drag::Cancelled) return true;
  if (drag == Drag::PendingGrab) return true;  // a click on a running ball: selected
  if (drag == Drag::Grab) {
    emit grabReleased(releaseVelocity());
    return true;
  }
  if (drag == Drag::Pending) {
    const QPointF moved = event->position() - pressPosition_;
    if (std::hypot(moved.x(), moved.y()) <= kClickSlopPixels) {
      if (tool_ == Tool::Select)
        document_->setSelection({});
      else
        place(event->position());
    }
    return false;
  }
  return drag == Drag::Objects || drag == Drag::Handle;
}

Box EditorTools::boxOn(const Vec3& point, const Vec3& normal,
                       const std::optional<RayHit>& hit) const {
  const Scene& scene = document_->scene();
  Box box;
  box.halfExtents =
      scene.boxes.empty() ? Vec3::Constant(kDefaultBoxHalfExtent) : scene.boxes.back().halfExtents;
  Vec3 up = normal;
  if (hit && hit->kind == ShapeKind::Box &&
      1.0 - boxShape(scene.boxes[hit->index]).axes.col(1).dot(normal) < kSameDirection) {
    // On a box's top it stands turned as that box is, so that stacks line up.
    box.rotation = scene.boxes[hit->index].rotation;
  } else if (1.0 - normal.dot(Vec3::UnitY()) >= kSameDirection) {
    // Elsewhere turned from upright onto the surface; upside down (a ceiling) about x.
    const Vec3 across = Vec3::UnitY().cross(normal);
    const Vec3 axis = across.norm() > 1e-12 ? across.normalized() : Vec3::UnitX();
    const double angle = std::atan2(across.norm(), Vec3::UnitY().dot(normal));
    box.rotation = Rotation{axis, angle * 180.0 / std::numbers::pi};
  } else {
    up = Vec3::UnitY();  // on the floor: upright, with no turn to write to the file
  }
  box.center = point + box.halfExtents.y() * up;
  return box;
}

void EditorTools::place(const QPointF& position) {
  const Scene& scene = document_->scene();
  const auto [origin, direction] = view_->rayAt(position);
  const Eigen::AlignedBox3d clip = view_->clipBox();
  Vec3 point;
  Vec3 normal = Vec3::UnitY();
  const std::optional<RayHit> hit = castRay(scene, origin, direction, &clip);
  if (hit) {
    point = hit->point;
    normal = hit->normal;
  } else if (const std::optional<double> t =
                 rayPlaneDistance(origin, direction, Vec3::Zero(), Vec3::UnitY())) {
    point = origin + *t * direction;  // the ground, y = 0
    if (origin.y() < 0.0) normal = -Vec3::UnitY();
  } else {
    emit refused(tr("Click on a surface or on the ground to place an object."));
    return;
  }

  Scene added;
  QString text;
  QString error;
  if (tool_ == Tool::AddBall) {
    Ball ball;
    ball.radius = scene.balls.empty() ? kDefaultBallRadius : scene.balls.back().radius;
    ball.mass = scene.balls.empty() ? 1.0 : scene.balls.back().mass;
    // Resting on the surface clicked; if that spot is taken, the nearest free one around it.
    const auto [u, v] = tangents(normal);
    const Vec3 centre = point + ball.radius * normal;
    for (int ring = 0; ring <= kNudgeRings; ++ring) {
      const int spots = ring == 0 ? 1 : 8 * ring;
      for (int spot = 0; spot < spots; ++spot) {
        const double angle = 2.0 * std::numbers::pi * spot / spots;
        const double distance = 2.05 * ball.radius * ring;
        ball.position = centre + distance * (std::cos(angle) * u + std::sin(angle) * v);
        Scene attempt;
        attempt.balls.push_back(ball);
        const QString problem = document_->addObjects(attempt, tr("Add Ball"));
        if (problem.isEmpty()) return;
        if (error.isEmpty()) error = problem;
      }
    }
    emit refused(tr("No room for a ball there: %1").arg(error));
    return;
  }
  if (tool_ == Tool::AddPlane) {
    // A wall through the point, facing the camera across the floor.
    Plane plane;
    plane.point = point;
    Vec3 facing = toVec3(view_->camera().eye()) - point;
    facing.y() = 0.0;
    plane.normal = facing.norm() > 1e-9 ? facing.normalized() : Vec3::UnitZ();
    added.planes.push_back(plane);
    text = tr("Add Plane");
  } else if (tool_ == Tool::AddBox) {
    added.boxes.push_back(boxOn(point, normal, hit));
    text = tr("Add Box");
  } else {
    // A post standing on the surface clicked, with the last cylinder's radius and the tool's
    // length: an infinite one through the point, a capped one with its lower cap on it.
    Cylinder cylinder;
    cylinder.axis = normal;
    cylinder.radius =
        scene.cylinders.empty() ? kDefaultCylinderRadius : scene.cylinders.back().radius;
    cylinder.length = cylinderLength_;
    cylinder.point = point + 0.5 * cylinder.length.value_or(0.0) * normal;
    added.cylinders.push_back(cylinder);
    text = tr("Add Cylinder");
  }
  error = document_->addObjects(added, text);
  if (!error.isEmpty()) emit refused(tr("Cannot place it there: %1").arg(error));
}

}  // namespace carom::editor
