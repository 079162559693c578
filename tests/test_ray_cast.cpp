// Ray casting against balls, planes, cylinders and boxes: closed forms, the rules of what counts as
// a hit, numerically hard rays, and random rays against brute-force marching.

#include "sim/geometry/ray_cast.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>

using namespace carom;

namespace {

Ball makeBall(const Vec3& position, double radius) {
  Ball ball;
  ball.position = position;
  ball.radius = radius;
  return ball;
}

Plane makePlane(const Vec3& point, const Vec3& normal) {
  Plane plane;
  plane.point = point;
  plane.normal = normal;
  return plane;
}

Cylinder makeCylinder(const Vec3& point, const Vec3& axis, double radius) {
  Cylinder cylinder;
  cylinder.point = point;
  cylinder.axis = axis;
  cylinder.radius = radius;
  return cylinder;
}

Box makeBox(const Vec3& center, const Vec3& halfExtents, std::optional<Rotation> rotation = {}) {
  Box box;
  box.center = center;
  box.halfExtents = halfExtents;
  box.rotation = rotation;
  return box;
}

const char* kindName(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Ball:
      return "ball";
    case ShapeKind::Plane:
      return "plane";
    case ShapeKind::Cylinder:
      return "cylinder";
    case ShapeKind::Box:
      return "box";
  }
  return "?";
}

QString vec(const Vec3& v) {
  return QStringLiteral("(%1, %2, %3)")
      .arg(v.x(), 0, 'g', 17)
      .arg(v.y(), 0, 'g', 17)
      .arg(v.z(), 0, 'g', 17);
}

QString describe(const std::optional<RayHit>& hit) {
  if (!hit) return QStringLiteral("no hit");
  return QStringLiteral("%1 %2 at %3, point %4, normal %5")
      .arg(kindName(hit->kind))
      .arg(hit->index)
      .arg(hit->distance, 0, 'g', 17)
      .arg(vec(hit->point), vec(hit->normal));
}

struct Expected {
  ShapeKind kind;
  int index;
  double distance;
  Vec3 point;
  Vec3 normal;
};

// Empty when `hit` is the expected one: distance and point to `tolerance` relative to the
// distance (and to how far the point is from the world's origin), the normal to 1e-9.
QString mismatch(const std::optional<RayHit>& hit, const Expected& e, double tolerance = 1e-12) {
  const QString wanted = QStringLiteral("wanted %1 %2 at %3, point %4, normal %5; got ")
                             .arg(kindName(e.kind))
                             .arg(e.index)
                             .arg(e.distance, 0, 'g', 17)
                             .arg(vec(e.point), vec(e.normal));
  if (!hit || hit->kind != e.kind || hit->index != e.index) return wanted + describe(hit);
  const double scale = e.distance + e.point.norm();
  const bool good = std::abs(hit->distance - e.distance) <= tolerance * e.distance &&
                    (hit->point - e.point).norm() <= tolerance * scale &&
                    (hit->normal - e.normal).norm() <= 1e-9 &&
                    std::abs(hit->normal.norm() - 1.0) <= 1e-14;
  return good ? QString() : wanted + describe(hit);
}

// Inside the solid of each kind, by definition and nothing more.
bool insideBall(const Ball& b, const Vec3& x) {
  return (x - b.position).norm() < b.radius;
}
bool insidePlane(const Plane& p, const Vec3& x) {
  return p.normal.normalized().dot(x - p.point) < 0.0;
}
double cylinderDistance(const Cylinder& c, const Vec3& x) {
  const Vec3 a = c.axis.normalized();
  const Vec3 offset = x - c.point;
  return (offset - a.dot(offset) * a).norm();
}
bool insideCylinder(const Cylinder& c, const Vec3& x) {
  return cylinderDistance(c, x) < c.radius;
}
// How far outside the box's slabs `x` is, at most: negative inside, zero on the surface.
double boxExcess(const Box& b, const Vec3& x) {
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  if (b.rotation)
    turn = Eigen::AngleAxisd(b.rotation->degrees * std::numbers::pi / 180.0,
                             b.rotation->axis.normalized())
               .toRotationMatrix();
  return ((turn.transpose() * (x - b.center)).cwiseAbs() - b.halfExtents).maxCoeff();
}
bool insideBox(const Box& b, const Vec3& x) {
  return boxExcess(b, x) < 0.0;
}

// First distance in (0, limit] at which the ray is inside the solid, found by stepping `step` at
// a time and then bisecting; infinity when the origin is already inside or no sample is.
constexpr double kNone = std::numeric_limits<double>::infinity();
template <typename Inside>
double marchToEntry(const Inside& inside, const Vec3& origin, const Vec3& unit, double step,
                    double limit) {
  if (inside(origin)) return kNone;
  for (double t = step; t <= limit; t += step) {
    if (!inside(origin + t * unit)) continue;
    double outside = t - step;
    double in = t;
    for (int i = 0; i < 200 && outside < in; ++i) {
      const double middle = 0.5 * (outside + in);
      if (middle <= outside || middle >= in) break;
      (inside(origin + middle * unit) ? in : outside) = middle;
    }
    return in;
  }
  return kNone;
}

}  // namespace

class TestRayCast : public QObject {
  Q_OBJECT

 private slots:
  void ballHits() {
    Scene scene;
    scene.balls.push_back(makeBall({1, 2, 3}, 2.0));
    // Straight at the centre: the surface is 10 - 2 away.
    QString problem = mismatch(castRay(scene, {1, 2, 13}, {0, 0, -5}),
                               {ShapeKind::Ball, 0, 8.0, {1, 2, 5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Passing 1 from the centre: half chord sqrt(4 - 1).
    const double root3 = std::sqrt(3.0);
    problem = mismatch(castRay(scene, {1, 3, 13}, {0, 0, -1}),
                       {ShapeKind::Ball, 0, 10.0 - root3, {1, 3, 3 + root3}, {0, 0.5, root3 / 2}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Along a diagonal, with a direction of another length.
    const Vec3 diagonal = Vec3(1, 1, 1).normalized();
    problem = mismatch(castRay(scene, Vec3(1, 2, 3) + 10 * diagonal, {-2, -2, -2}),
                       {ShapeKind::Ball, 0, 8.0, Vec3(1, 2, 3) + 2 * diagonal, diagonal});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Passing 3 from the centre, and looking away.
    QVERIFY(!castRay(scene, {1, 5, 13}, {0, 0, -1}));
    QVERIFY(!castRay(scene, {1, 2, 13}, {0, 0, 1}));
    // No direction, no ray.
    QVERIFY(!castRay(scene, {1, 2, 13}, Vec3::Zero()));
  }

  void planeHits() {
    Scene scene;
    scene.planes.push_back(makePlane({0, 1, 0}, {0, 3, 0}));
    // From height 4 above it, going down 2 for every 1 across: sqrt(5) per 2 of height.
    const double root5 = std::sqrt(5.0);
    QString problem = mismatch(castRay(scene, {2, 5, 1}, {1, -2, 0}),
                               {ShapeKind::Plane, 0, 2 * root5, {4, 1, 1}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // A slanted plane x + y + z = 1, met head on from (3, 3, 3): 8 / sqrt(3) away.
    scene.planes[0] = makePlane({1, 0, 0}, {1, 1, 1});
    const double root3 = std::sqrt(3.0);
    problem =
        mismatch(castRay(scene, {3, 3, 3}, {-7, -7, -7}),
                 {ShapeKind::Plane, 0, 8 / root3, Vec3::Constant(1.0 / 3), Vec3::Ones() / root3});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(!castRay(scene, {3, 3, 3}, {1, 0.5, 0}));
  }

  // A capped cylinder is picked on its side between the caps and on its caps, never beyond.
  void cappedCylinderHits() {
    Scene scene;
    Cylinder stump = makeCylinder({0, 0, 0}, {0, 3, 0}, 0.5);
    stump.length = 2.0;
    scene.cylinders.push_back(stump);
    // Straight down the axis onto the top cap.
    QString problem = mismatch(castRay(scene, {0.2, 5, 0}, {0, -1, 0}),
                               {ShapeKind::Cylinder, 0, 4.0, {0.2, 1, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Up onto the bottom cap.
    problem = mismatch(castRay(scene, {0, -4, 0.1}, {0, 2, 0}),
                       {ShapeKind::Cylinder, 0, 3.0, {0, -1, 0.1}, {0, -1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // The side between the caps.
    problem = mismatch(castRay(scene, {3, 0.5, 0}, {-1, 0, 0}),
                       {ShapeKind::Cylinder, 0, 2.5, {0.5, 0.5, 0}, {1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Above the top cap and beside the bottom one: nothing there.
    QVERIFY(!castRay(scene, {3, 1.5, 0}, {-1, 0, 0}));
    QVERIFY(!castRay(scene, {0.7, 5, 0}, {0, -1, 0}));
    // Slanting down past the side's top edge onto the cap: enters at y = 1 through the cap.
    problem = mismatch(castRay(scene, {1.4, 2, 0}, {-1, -1, 0}),
                       {ShapeKind::Cylinder, 0, std::sqrt(2.0), {0.4, 1, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void cylinderHits() {
    Scene scene;
    scene.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 5, 0}, 1.0));
    QString problem = mismatch(castRay(scene, {5, 7, 0}, {-1, 0, 0}),
                               {ShapeKind::Cylinder, 0, 4.0, {1, 7, 0}, {1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Slanted down at 45 degrees: only the part across the axis closes in.
    problem = mismatch(castRay(scene, {5, 7, 0}, {-1, -1, 0}),
                       {ShapeKind::Cylinder, 0, 4 * std::sqrt(2.0), {1, 3, 0}, {1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Off-centre by 0.6: enters at x = 0.8.
    problem = mismatch(castRay(scene, {5, 2, 0.6}, {-3, 0, 0}),
                       {ShapeKind::Cylinder, 0, 4.2, {0.8, 2, 0.6}, {0.8, 0, 0.6}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(!castRay(scene, {5, 2, 1.2}, {-3, 0, 0}));
    QVERIFY(!castRay(scene, {5, 2, 0}, {3, 0, 0}));
    // A slanted axis given backwards and not of unit length.
    scene.cylinders[0] = makeCylinder({1, 1, 1}, {-2, -2, 0}, 0.5);
    problem = mismatch(castRay(scene, {4, 4, 6}, {0, 0, -1}),
                       {ShapeKind::Cylinder, 0, 4.5, {4, 4, 1.5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void boxHits() {
    Scene scene;
    scene.boxes.push_back(makeBox({1, 2, 3}, {1, 2, 0.5}));
    // Straight down the z axis onto the front face, and from the side with a long direction.
    QString problem = mismatch(castRay(scene, {1, 2, 13}, {0, 0, -1}),
                               {ShapeKind::Box, 0, 9.5, {1, 2, 3.5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    problem = mismatch(castRay(scene, {10, 3.5, 3.25}, {-4, 0, 0}),
                       {ShapeKind::Box, 0, 8, {2, 3.5, 3.25}, {1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Slanted onto the top, y = 4: 6 down and 3 across, sqrt(45) long.
    problem = mismatch(castRay(scene, {-2, 10, 3}, {1, -2, 0}),
                       {ShapeKind::Box, 0, std::sqrt(45.0), {1, 4, 3}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(!castRay(scene, {5, 2, 13}, {0, 0, -1}));  // beside it
    QVERIFY(!castRay(scene, {1, 2, 13}, {0, 0, 1}));   // looking away

    // Past the corner (2, 4) of the z = 3 cross-section, across the diagonal at 0.01 from it:
    // outside it misses; inside it enters the face x = 2 at s = 0.01 from the corner's line.
    const Vec3 corner(2, 4, 3);
    const Vec3 across(-1, 1, 0);
    const Vec3 outward = Vec3(1, 1, 0).normalized();
    QVERIFY2(!castRay(scene, corner + 0.01 * outward - 5 * across, across),
             qPrintable(describe(castRay(scene, corner + 0.01 * outward - 5 * across, across))));
    const double d = 0.01 / std::sqrt(2.0);  // the offset along each axis
    problem =
        mismatch(castRay(scene, corner - 0.01 * outward - 5 * across, across),
                 {ShapeKind::Box, 0, (5 - d) * std::sqrt(2.0), {2, 4 - 2 * d, 3}, {1, 0, 0}}, 1e-9);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void turnedBoxHits() {
    // A cube turned 45 degrees about y: seen from above, a diamond |x| + |z| <= sqrt(2) * 1.
    Scene scene;
    scene.boxes.push_back(makeBox({0, 0, 0}, {1, 1, 1}, Rotation{{0, 3, 0}, 45}));
    const double root2 = std::sqrt(2.0);
    QString problem = mismatch(
        castRay(scene, {0.5, 0, 10}, {0, 0, -1}),
        {ShapeKind::Box, 0, 10 - (root2 - 0.5), {0.5, 0, root2 - 0.5}, {1 / root2, 0, 1 / root2}},
        1e-9);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Past the diamond's corner at x = sqrt(2), and over and under the top and bottom faces.
    QVERIFY(!castRay(scene, {1.45, 0, 10}, {0, 0, -1}));
    QVERIFY(castRay(scene, {1.4, 0, 10}, {0, 0, -1}));
    QVERIFY(!castRay(scene, {0.5, 1.01, 10}, {0, 0, -1}));
    QVERIFY(castRay(scene, {0.5, 0.99, 10}, {0, 0, -1}));
    QVERIFY(!castRay(scene, {0.5, -1.01, 10}, {0, 0, -1}));
    // Along its own x axis, turned by 30 degrees about a slanted axis, to the face 2 from the
    // centre.
    const Rotation turn{Vec3(1, 2, 3), 30};
    const Vec3 centre(4, -1, 2);
    scene.boxes[0] = makeBox(centre, {2, 0.5, 1}, turn);
    const Vec3 ownX =
        Eigen::AngleAxisd(30 * std::numbers::pi / 180, turn.axis.normalized()) * Vec3::UnitX();
    problem = mismatch(castRay(scene, centre + 10 * ownX, -3 * ownX),
                       {ShapeKind::Box, 0, 8, centre + 2 * ownX, ownX}, 1e-12);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Not from inside, nor from on its surface outwards.
    QVERIFY(!castRay(scene, centre, {1, 0, 0}));
    QVERIFY(!castRay(scene, centre + 2 * ownX, ownX));
  }

  void boxAmongOthers() {
    // The nearest wins whatever its kind: a box in front of a ball, then behind it.
    Scene scene;
    scene.balls.push_back(makeBall({0, 0, 0}, 1.0));
    scene.boxes.push_back(makeBox({0, 0, 3}, {0.5, 0.5, 0.5}));
    QString problem = mismatch(castRay(scene, {0, 0, 10}, {0, 0, -1}),
                               {ShapeKind::Box, 0, 6.5, {0, 0, 3.5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.boxes[0].center = Vec3(0, 0, -3);
    problem = mismatch(castRay(scene, {0, 0, 10}, {0, 0, -1}),
                       {ShapeKind::Ball, 0, 9, {0, 0, 1}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Boxes are finite: a clip box never hides them.
    const Eigen::AlignedBox3d clip(Vec3::Constant(-1), Vec3::Constant(1));
    scene.balls.clear();
    problem = mismatch(castRay(scene, {0, 0, 10}, {0, 0, -1}, &clip),
                       {ShapeKind::Box, 0, 12.5, {0, 0, -2.5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void nearestOfSeveral() {
    Scene scene;
    // Listed farthest first, so that the order of the vectors cannot be what decides.
    scene.planes.push_back(makePlane({0, 0, -6}, {0, 0, 1}));
    scene.planes.push_back(makePlane({0, 0, -3}, {0, 0, 1}));
    scene.cylinders.push_back(makeCylinder({0, 1, -1}, {1, 0, 0}, 0.5));
    scene.cylinders.push_back(makeCylinder({0, 1, 0}, {1, 0, 0}, 0.5));
    scene.balls.push_back(makeBall({4, 1, 8}, 1.0));  // beside the ray
    scene.balls.push_back(makeBall({0, 1, 2}, 1.0));
    scene.balls.push_back(makeBall({0, 1, 5}, 1.0));
    const Vec3 origin(0, 1, 20);
    const Vec3 down(0, 0, -1);
    QString problem =
        mismatch(castRay(scene, origin, down), {ShapeKind::Ball, 2, 14, {0, 1, 6}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.balls.pop_back();
    problem =
        mismatch(castRay(scene, origin, down), {ShapeKind::Ball, 1, 17, {0, 1, 3}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.balls.clear();
    problem = mismatch(castRay(scene, origin, down),
                       {ShapeKind::Cylinder, 1, 19.5, {0, 1, 0.5}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.cylinders.clear();
    problem =
        mismatch(castRay(scene, origin, down), {ShapeKind::Plane, 1, 23, {0, 1, -3}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void planesSeenFromBehindAreIgnored() {
    Scene scene;
    scene.planes.push_back(makePlane({0, 0, 0}, {0, 1, 0}));  // floor
    // From under the floor: up through it, and down into it.
    QVERIFY(!castRay(scene, {0, -2, 0}, {0, 1, 0.3}));
    QVERIFY(!castRay(scene, {0, -2, 0}, {0, -1, 0.3}));
    // The ball above it is seen through the floor's back.
    scene.balls.push_back(makeBall({0, 3, 0}, 1.0));
    QString problem = mismatch(castRay(scene, {0, -2, 0}, {0, 1, 0}),
                               {ShapeKind::Ball, 0, 4, {0, 2, 0}, {0, -1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // A ceiling faces down: met from below, not from above.
    scene.planes.push_back(makePlane({0, 5, 0}, {0, -1, 0}));
    problem = mismatch(castRay(scene, {2, 1, 0}, {0, 1, 0}),
                       {ShapeKind::Plane, 1, 4, {2, 5, 0}, {0, -1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    problem = mismatch(castRay(scene, {0, 7, 0}, {0, -1, 0}),
                       {ShapeKind::Ball, 0, 3, {0, 4, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void clippingIgnoresUndrawnPlanesAndCylinders() {
    const Eigen::AlignedBox3d box(Vec3::Constant(-5), Vec3::Constant(5));
    Scene scene;
    scene.planes.push_back(makePlane({0, -5, 0}, {0, 1, 0}));  // on the box's bottom face
    // Within the box, from awkward angles: some hit points round off the face, but count.
    int roundedOff = 0;
    for (int i = 0; i < 100; ++i) {
      const Vec3 origin(2.3 + 0.37 * i, 7.1 - 0.013 * i, -1.7 + 0.11 * i);
      const Vec3 towards = Vec3(-0.9 + 0.04 * i, -5, 3.3 - 0.083 * i) - origin;
      const std::optional<RayHit> onFace = castRay(scene, origin, towards, &box);
      QVERIFY2(onFace && onFace->kind == ShapeKind::Plane, qPrintable(describe(onFace)));
      QVERIFY(std::abs(onFace->distance - towards.norm()) < 1e-12 * towards.norm());
      if (onFace->point.y() < -5) ++roundedOff;
    }
    QVERIFY(roundedOff > 0);  // or the loop above proves nothing

    // The floor far outside: hit only without the box or with a margin of more than 15.
    const Vec3 far(20, -5, 0);
    const Vec3 fromAbove(20, 0, 0);
    QVERIFY(castRay(scene, fromAbove, far - fromAbove));
    QVERIFY(!castRay(scene, fromAbove, far - fromAbove, &box));
    QVERIFY(!castRay(scene, fromAbove, far - fromAbove, &box, 14.0));
    QVERIFY(castRay(scene, fromAbove, far - fromAbove, &box, 16.0));
    // A ball out there is hit all the same.
    scene.balls.push_back(makeBall({20, -3, 0}, 1.0));
    QString problem = mismatch(castRay(scene, fromAbove, far - fromAbove, &box),
                               {ShapeKind::Ball, 0, 2, {20, -2, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.balls.clear();

    // A wall at x = 8, outside the box, does not hide the ball behind it.
    scene.planes.push_back(makePlane({8, 0, 0}, {-1, 0, 0}));
    scene.balls.push_back(makeBall({12, 0, 0}, 1.0));
    problem = mismatch(castRay(scene, Vec3::Zero(), Vec3::UnitX()),
                       {ShapeKind::Plane, 1, 8, {8, 0, 0}, {-1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    problem = mismatch(castRay(scene, Vec3::Zero(), Vec3::UnitX(), &box),
                       {ShapeKind::Ball, 0, 11, {11, 0, 0}, {-1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.balls.clear();
    scene.planes.pop_back();

    // A post: hit inside the box, not far above it.
    scene.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 0.5));
    problem = mismatch(castRay(scene, {3, 2, 0}, {-1, 0, 0}, &box),
                       {ShapeKind::Cylinder, 0, 2.5, {0.5, 2, 0}, {1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(castRay(scene, {3, 20, 0}, {-1, 0, 0}));
    QVERIFY(!castRay(scene, {3, 20, 0}, {-1, 0, 0}, &box));
    scene.cylinders.clear();

    // A rod whose axis is inside the box is drawn whole, even where its surface bulges out.
    scene.cylinders.push_back(makeCylinder({0, 4.8, 0}, {1, 0, 0}, 0.5));
    problem = mismatch(castRay(scene, {1, 10, 0}, {0, -1, 0}, &box),
                       {ShapeKind::Cylinder, 0, 4.7, {1, 5.3, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // One whose axis is 0.3 outside is not drawn: the ray goes on to the floor, unless the
    // margin covers it.
    scene.cylinders[0].point = Vec3(0, 5.3, 0);
    problem = mismatch(castRay(scene, {1, 10, 0}, {0, -1, 0}, &box),
                       {ShapeKind::Plane, 0, 15, {1, -5, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    problem = mismatch(castRay(scene, {1, 10, 0}, {0, -1, 0}, &box, 0.5),
                       {ShapeKind::Cylinder, 0, 4.2, {1, 5.8, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Beyond the end of the box along its axis.
    scene.cylinders[0].point = Vec3(0, 0, 0);
    QVERIFY(castRay(scene, {20, 3, 0}, {0, -1, 0}));
    QVERIFY(!castRay(scene, {20, 3, 0}, {0, -1, 0}, &box));
  }

  void raysStartingInside() {
    Scene scene;
    scene.balls.push_back(makeBall({0, 0, 0}, 2.0));
    scene.balls.push_back(makeBall({10, 0, 0}, 1.0));
    // From inside the first ball: not its far side, but the next ball.
    QString problem = mismatch(castRay(scene, {0.5, 0, 0}, {1, 0, 0}),
                               {ShapeKind::Ball, 1, 8.5, {9, 0, 0}, {-1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(!castRay(scene, {0.5, 0, 0}, {-1, 0, 0}));
    // Barely inside, next to the surface.
    QVERIFY(!castRay(scene, {-2 + 1e-12, 0, 0}, {-1, 0.1, 0}));

    // Inside a thick post, with a ball inside it too and another post outside.
    scene.balls.clear();
    scene.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 3.0));
    scene.cylinders.push_back(makeCylinder({0, 0, -10}, {0, 1, 0}, 1.0));
    scene.balls.push_back(makeBall({1, 0, 0}, 0.5));
    problem = mismatch(castRay(scene, {-1, 0, 0}, {1, 0, 0}),
                       {ShapeKind::Ball, 0, 1.5, {0.5, 0, 0}, {-1, 0, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(!castRay(scene, {-1, 0, 0}, {-1, 0, 0}));
    problem = mismatch(castRay(scene, {0, 0, 0}, {0, 0, -1}),
                       {ShapeKind::Cylinder, 1, 9, {0, 0, -9}, {0, 0, 1}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void parallelRays() {
    // Above the floor, along it: never meets it.
    Scene scene;
    scene.planes.push_back(makePlane({0, 0, 0}, {0, 1, 0}));
    QVERIFY(!castRay(scene, {0, 1, 0}, {1, 0, 1}));
    QVERIFY(!rayPlaneDistance({0, 1, 0}, {1, 0, 1}, {0, 0, 0}, {0, 1, 0}));
    // Slanted planes and directions along them built by cross products: off by rounding only,
    // which must not turn into hits some 1e16 away, on either side.
    for (const Vec3& normal : {Vec3(1, 2, 3), Vec3(-0.3, 0.01, 7), Vec3(5, -4, 0.2)}) {
      scene.planes[0] = makePlane({0.5, -1, 2}, normal);
      for (int turn = 0; turn < 8; ++turn) {
        const Vec3 along = normal.cross(Vec3(std::cos(turn), std::sin(turn), 0.7)) * (turn + 0.3);
        for (double height : {1e-7, 1.0, 1e6}) {
          const Vec3 origin = scene.planes[0].point + height * normal.normalized();
          for (const Vec3& direction : {along, Vec3(-along)}) {
            QVERIFY2(!castRay(scene, origin, direction),
                     qPrintable(describe(castRay(scene, origin, direction))));
            QVERIFY(!rayPlaneDistance(origin, direction, scene.planes[0].point, normal));
          }
        }
      }
    }

    // Outside (some just outside) and inside slanted cylinders, all around them, along their
    // axis either way and with directions of several lengths.
    scene.planes.clear();
    for (const Vec3& slanted : {Vec3(0.3, -0.7, 0.2), Vec3(-5, 1, 0.01), Vec3(1e-3, 7, -2)}) {
      scene.cylinders = {makeCylinder({0.5, -1, 2}, slanted, 1.0)};
      const Vec3 unit = slanted.normalized();
      const Vec3 first = unit.cross(Vec3(0.3, -1, 0.7)).normalized();
      const Vec3 second = unit.cross(first);
      for (int turn = 0; turn < 8; ++turn) {
        const Vec3 out = std::cos(turn) * first + std::sin(turn) * second;
        for (double distance : {1 + 1e-7, 3.0, 0.5}) {
          const Vec3 origin = scene.cylinders[0].point + distance * out + 0.7 * unit;
          for (double length : {0.37, 1.0, -1.0, -3.3, 1e-3, 7e5}) {
            QVERIFY2(!castRay(scene, origin, length * slanted),
                     qPrintable(describe(castRay(scene, origin, length * slanted))));
          }
        }
      }
    }

    // Along a slanted axis from outside, to a ball ahead; then closing in on it very slowly.
    const Vec3 axis(1, 2, 3);
    const Vec3 unitAxis = axis.normalized();
    const Vec3 side = axis.cross(Vec3(0.3, -1, 0.7)).normalized();
    scene.cylinders = {makeCylinder({0, 0, 0}, axis, 1.0)};
    scene.balls.push_back(makeBall(3 * side + 5 * unitAxis, 0.5));
    QString problem = mismatch(castRay(scene, 3 * side, 2 * axis),
                               {ShapeKind::Ball, 0, 4.5, 3 * side + 4.5 * unitAxis, -unitAxis});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    scene.balls.clear();
    // Nearly along the axis, closing in by 1e-6 per unit: enters after 2 / sin(1e-6).
    const double angle = 1e-6;
    const Vec3 slant = std::cos(angle) * unitAxis - std::sin(angle) * side;
    const double expected = 2.0 / std::sin(angle);
    problem = mismatch(castRay(scene, 3 * side, slant),
                       {ShapeKind::Cylinder, 0, expected, 3 * side + expected * slant, side}, 1e-9);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
  }

  void grazingRays() {
    Scene scene;
    scene.balls.push_back(makeBall({0, 0, 0}, 1.0));
    // Exactly tangent: touches at the top.
    QString problem = mismatch(castRay(scene, {-1000, 1, 0}, {1, 0, 0}),
                               {ShapeKind::Ball, 0, 1000, {0, 1, 0}, {0, 1, 0}});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // Just inside the outline: a half chord of about 4.5e-5 that b^2 - c would get wrong in the
    // second digit from this far away.
    const double height = 1 - 1e-9;
    const double halfChord = std::sqrt((1 - height) * (1 + height));
    const std::optional<RayHit> hit = castRay(scene, {-1000, height, 0}, {1, 0, 0});
    QVERIFY2(hit && std::abs(hit->distance - (1000 - halfChord)) < 1e-9, qPrintable(describe(hit)));
    QVERIFY((hit->normal - Vec3(-halfChord, height, 0)).norm() < 1e-9);
    QVERIFY(!castRay(scene, {-1000, 1 + 1e-9, 0}, {1, 0, 0}));
    // Starting a hair away from the surface: the distance keeps its relative precision.
    const double x = 1 + 1e-12;
    const std::optional<RayHit> close = castRay(scene, {x, 0, 0}, {-1, 0, 0});
    QVERIFY2(close && std::abs(close->distance - (x - 1)) <= 1e-6 * (x - 1),
             qPrintable(describe(close)));

    // The same on a cylinder's side.
    scene.balls.clear();
    scene.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 1.0));
    const std::optional<RayHit> side = castRay(scene, {-1000, 5, height}, {1, 0, 0});
    QVERIFY2(side && std::abs(side->distance - (1000 - halfChord)) < 1e-9,
             qPrintable(describe(side)));
    QVERIFY(!castRay(scene, {-1000, 5, 1 + 1e-9}, {1, 0, 0}));
    const std::optional<RayHit> sideClose = castRay(scene, {0, 7, x}, {0, 0.5, -1});
    QVERIFY2(
        sideClose && std::abs(sideClose->distance - (x - 1) * std::sqrt(1.25)) <= 1e-6 * (x - 1),
        qPrintable(describe(sideClose)));
  }

  void rayPlaneDistanceFromEitherSide() {
    // The ground from above and from below, with directions of any length.
    QCOMPARE(rayPlaneDistance({1, 4, 2}, {0, -0.5, 0}, {7, 0, -3}, {0, 1, 0}).value_or(-1), 4.0);
    QCOMPARE(rayPlaneDistance({1, -4, 2}, {0, 3, 0}, {7, 0, -3}, {0, 1, 0}).value_or(-1), 4.0);
    const std::optional<double> slanted =
        rayPlaneDistance({0, 3, 0}, {4, -3, 0}, Vec3::Zero(), {0, 2, 0});
    QVERIFY(slanted && std::abs(*slanted - 5.0) < 1e-15);
    // Behind the origin, and at it.
    QVERIFY(!rayPlaneDistance({1, 4, 2}, {0, 1, 0}, Vec3::Zero(), {0, 1, 0}));
    QVERIFY(!rayPlaneDistance({1, 0, 2}, {0, -1, 0}, Vec3::Zero(), {0, 1, 0}));
    // A plane facing a camera, through a point the camera sees.
    const Vec3 eye(3, 4, 12);
    const Vec3 target(0.5, 1, -1);
    const Vec3 point(2, 3, 0.25);
    const std::optional<double> facing = rayPlaneDistance(eye, point - eye, target, eye - target);
    QVERIFY(facing);
    const Vec3 onPlane = eye + *facing * (point - eye).normalized();
    QVERIFY(std::abs((onPlane - target).dot(eye - target)) < 1e-12);
  }

  void scales_data() {
    QTest::addColumn<double>("scale");
    QTest::newRow("1e-6") << 1e-6;
    QTest::newRow("1") << 1.0;
    QTest::newRow("1e6") << 1e6;
  }

  // The same scene at every size, moved away from the origin: the answers scale with it.
  void scales() {
    QFETCH(double, scale);
    const Vec3 shift = scale * Vec3(100, -50, 30);
    const auto at = [&](const Vec3& p) -> Vec3 { return shift + scale * p; };
    Scene scene;
    scene.balls.push_back(makeBall(at({1, 2, 3}), 2 * scale));
    scene.planes.push_back(makePlane(at({0, -10, 0}), {0, 1e-3, 0}));
    scene.cylinders.push_back(makeCylinder(at({0, 0, -20}), {0, 5, 0}, scale));
    const double root3 = std::sqrt(3.0);
    QString problem = mismatch(
        castRay(scene, at({1, 3, 13}), {0, 0, -scale}),
        {ShapeKind::Ball, 0, (10 - root3) * scale, at({1, 3, 3 + root3}), {0, 0.5, root3 / 2}},
        1e-11);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    problem = mismatch(
        castRay(scene, at({5, 7, -20}), {-1, -1, 0}),
        {ShapeKind::Cylinder, 0, 4 * std::sqrt(2.0) * scale, at({1, 3, -20}), {1, 0, 0}}, 1e-11);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    const double root5 = std::sqrt(5.0);
    problem =
        mismatch(castRay(scene, at({10, -6, 1}), {1, -2, 0}),
                 {ShapeKind::Plane, 0, 2 * root5 * scale, at({12, -10, 1}), {0, 1, 0}}, 1e-11);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    // From inside the ball.
    QVERIFY(!castRay(scene, at({1, 2.5, 3}), {0, 0, 1}));
    // Grazing, and starting a hundredth of the radius away.
    const double height = 2 - 2e-9;
    const std::optional<RayHit> graze = castRay(scene, at({-1000, 2 + height, 3}), {1, 0, 0});
    const double halfChord = std::sqrt((2 - height) * (2 + height));
    QVERIFY2(graze && std::abs(graze->distance / scale - (1001 - halfChord)) < 1e-8,
             qPrintable(describe(graze)));
    QVERIFY(!castRay(scene, at({-1000, 4 + 2e-9, 3}), {1, 0, 0}));
    const std::optional<RayHit> close = castRay(scene, at({1, 2, 5.02}), {0, 0, -1});
    QVERIFY2(close && std::abs(close->distance / scale - 0.02) < 1e-10,
             qPrintable(describe(close)));
    // Placing on the ground.
    const std::optional<double> ground =
        rayPlaneDistance(at({3, 4, 5}), {0, -scale, scale}, at({0, -10, 0}), {0, 1, 0});
    QVERIFY(ground && std::abs(*ground / scale - 14 * std::sqrt(2.0)) < 1e-11);
  }

  void randomRaysMatchMarching_data() {
    QTest::addColumn<double>("scale");
    QTest::newRow("1e-6") << 1e-6;
    QTest::newRow("1") << 1.0;
    QTest::newRow("1e6") << 1e6;
  }

  // Each object alone against marching along the ray; the whole scene against the nearest of
  // those. Half the rays are clipped to a box.
  void randomRaysMatchMarching() {
    QFETCH(double, scale);
    std::mt19937_64 random(20240607);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::normal_distribution<double> normal;
    // Coordinates drawn one by one: the order of a constructor's arguments is unspecified.
    const auto draw = [&](auto& distribution) {
      Vec3 v;
      for (int i = 0; i < 3; ++i) v[i] = distribution(random);
      return v;
    };
    const auto gaussian = [&] { return draw(normal); };
    const auto within = [&](double size) -> Vec3 { return size * draw(uniform); };

    const auto between = [&](double low, double high) {
      return low + 0.5 * (uniform(random) + 1.0) * (high - low);
    };
    const Vec3 shift = scale * Vec3(100, -50, 30);
    const Eigen::AlignedBox3d box(shift - Vec3::Constant(5 * scale),
                                  shift + Vec3::Constant(5 * scale));
    constexpr double kStep = 0.004;
    constexpr double kLimit = 60.0;
    int rays = 0;
    int hits = 0;
    int grazes = 0;
    for (int round = 0; round < 60; ++round) {
      Scene scene;
      for (int i = 0; i < 3; ++i) {
        // Facing the middle from 6 to 7 away, so that some origins are behind them.
        const Vec3 n = gaussian().normalized();
        scene.planes.push_back(makePlane(shift - between(6, 7) * scale * n, n * between(0.1, 10)));
      }
      for (int i = 0; i < 3; ++i) {
        scene.cylinders.push_back(
            makeCylinder(shift + within(4 * scale), gaussian(), between(0.2, 0.7) * scale));
      }
      for (int i = 0; i < 6; ++i) {
        scene.balls.push_back(makeBall(shift + within(5 * scale), between(0.3, 1.2) * scale));
      }
      for (int i = 0; i < 2; ++i) {
        const Vec3 center = shift + within(4 * scale);
        const Vec3 half(between(0.2, 1.0) * scale, between(0.2, 1.0) * scale,
                        between(0.2, 1.0) * scale);
        const Vec3 axis = gaussian();
        scene.boxes.push_back(makeBox(center, half, Rotation{axis, between(-180, 180)}));
      }
      for (int ray = 0; ray < 8; ++ray, ++rays) {
        const Vec3 origin = shift + within(8 * scale);
        const Vec3 direction = gaussian() * between(1e-3, 1e3);
        const Vec3 unit = direction.normalized();
        const Eigen::AlignedBox3d* clip = ray % 2 ? &box : nullptr;

        std::optional<RayHit> nearest;
        const auto check = [&](ShapeKind kind, int index, const Scene& alone, const auto& inside,
                               const auto& drawn, const auto& surfaceGap) {
          const std::optional<RayHit> hit = castRay(alone, origin, direction, clip);
          double marched = marchToEntry(inside, origin, unit, kStep * scale, kLimit * scale);
          if (marched < kNone && !drawn(origin + marched * unit)) marched = kNone;
          const auto what = [&] {
            return QStringLiteral("%1 %2 of round %3, ray %4: cast %5, marched %6")
                .arg(kindName(kind))
                .arg(index)
                .arg(round)
                .arg(ray)
                .arg(describe(hit))
                .arg(marched, 0, 'g', 17);
          };
          if (hit && (!nearest || hit->distance < nearest->distance)) {
            nearest = hit;
            nearest->index = index;
          }
          if (hit && hit->distance > (kLimit - kStep) * scale) return true;  // past the march
          if (marched < kNone) {
            ++hits;
            const double slope = std::max(std::abs(hit ? hit->normal.dot(unit) : 0.0), 1e-300);
            const bool same = hit && hit->kind == kind && hit->index == 0 &&
                              std::abs(hit->distance - marched) <= 1e-9 * scale * (1 + 1 / slope);
            if (!same) qWarning("%s", qPrintable(what()));
            return same;
          }
          if (!hit) return true;
          // Marching stepped over it: only a graze, entering and leaving between two samples,
          // and exactly on the surface.
          ++grazes;
          const bool graze = !inside(origin) &&
                             !inside(origin + (hit->distance + kStep * scale) * unit) &&
                             std::abs(surfaceGap(hit->point)) <= 1e-9 * scale;
          if (!graze) qWarning("%s", qPrintable(what()));
          return graze;
        };
        const auto always = [](const Vec3&) { return true; };
        for (int i = 0; i < 6; ++i) {
          Scene alone;
          const Ball& ball = scene.balls[i];
          alone.balls.push_back(ball);
          QVERIFY(check(
              ShapeKind::Ball, i, alone, [&](const Vec3& x) { return insideBall(ball, x); }, always,
              [&](const Vec3& x) { return (x - ball.position).norm() - ball.radius; }));
        }
        for (int i = 0; i < 3; ++i) {
          Scene alone;
          const Plane& plane = scene.planes[i];
          alone.planes.push_back(plane);
          QVERIFY(check(
              ShapeKind::Plane, i, alone, [&](const Vec3& x) { return insidePlane(plane, x); },
              [&](const Vec3& x) { return !clip || clip->exteriorDistance(x) < 1e-9 * scale; },
              [&](const Vec3& x) { return plane.normal.normalized().dot(x - plane.point); }));
        }
        for (int i = 0; i < 3; ++i) {
          Scene alone;
          const Cylinder& cylinder = scene.cylinders[i];
          alone.cylinders.push_back(cylinder);
          const Vec3 axis = cylinder.axis.normalized();
          QVERIFY(check(
              ShapeKind::Cylinder, i, alone,
              [&](const Vec3& x) { return insideCylinder(cylinder, x); },
              [&](const Vec3& x) {
                const Vec3 onAxis = cylinder.point + axis.dot(x - cylinder.point) * axis;
                return !clip || clip->exteriorDistance(onAxis) < 1e-9 * scale;
              },
              [&](const Vec3& x) { return cylinderDistance(cylinder, x) - cylinder.radius; }));
        }
        for (int i = 0; i < 2; ++i) {
          Scene alone;
          const Box& box = scene.boxes[i];
          alone.boxes.push_back(box);
          QVERIFY(check(
              ShapeKind::Box, i, alone, [&](const Vec3& x) { return insideBox(box, x); }, always,
              [&](const Vec3& x) { return boxExcess(box, x); }));
        }
        // The whole scene gives the nearest of the objects taken alone.
        const std::optional<RayHit> all = castRay(scene, origin, direction, clip);
        QVERIFY2(all.has_value() == nearest.has_value(), qPrintable(describe(all)));
        if (all) {
          QVERIFY2(all->kind == nearest->kind && all->index == nearest->index &&
                       all->distance == nearest->distance,
                   qPrintable(describe(all) + " vs " + describe(nearest)));
        }
      }
    }
    // Enough real comparisons, and grazes as rare as they should be.
    qInfo("%d rays, %d hits compared, %d grazes", rays, hits, grazes);
    QVERIFY2(2 * hits > rays, qPrintable(QStringLiteral("%1 hits in %2 rays").arg(hits).arg(rays)));
    QVERIFY2(grazes * 50 < hits, qPrintable(QStringLiteral("%1 grazes").arg(grazes)));
  }
};

QTEST_APPLESS_MAIN(TestRayCast)
#include "test_ray_cast.moc"
