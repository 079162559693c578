#pragma once
// What stays fixed during a run: the static shapes and each ball's size, mass, restitution and
// friction, resolved once against the world so the steppers need not look at the scene again.

#include "sim/dynamics/run_stats.h"
#include "sim/geometry/shapes.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace carom {

struct Bodies {
  std::vector<PlaneShape> planes;
  std::vector<double> planeRestitution;
  std::vector<CylinderShape> cylinders;
  std::vector<double> cylinderRestitution;
  std::vector<BoxShape> boxes;
  std::vector<double> boxRestitution;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inverseMass;
  std::vector<double> restitution;  // each ball's own value, or the world's
  double maxRadius = 0.0;
  // The objects' own values (none: the world's), kept to resolve the world's again.
  std::vector<std::optional<double>> planeOwnRestitution;
  std::vector<std::optional<double>> cylinderOwnRestitution;
  std::vector<std::optional<double>> boxOwnRestitution;
  std::vector<std::optional<double>> ownRestitution;

  // Friction (docs/physics.md, "Friction and spin"). `rough` is whether any contact can have
  // friction; without it the lists below stay empty and the steppers run the frictionless
  // physics alone, bit for bit as before friction existed.
  bool rough = false;
  double tangentialRestitution = 0.0;  // the world's β
  std::vector<ContactFriction> planeFriction;
  std::vector<ContactFriction> cylinderFriction;
  std::vector<ContactFriction> boxFriction;
  std::vector<ContactFriction> friction;  // each ball's
  // The objects' own values, kept to resolve the world's again; all four empty when no object
  // of the scene has one (every object then takes the world's).
  struct OwnFriction {
    std::optional<double> sliding, rolling, spinning;
  };
  std::vector<OwnFriction> planeOwnFriction, cylinderOwnFriction, boxOwnFriction, ownFriction;
  bool ownRough = false;  // an object's own value is above zero

  int ballCount() const { return static_cast<int>(radius.size()); }
  // Every object without a value of its own takes the world's from now on.
  void setWorldRestitution(double worldRestitution);
  void setWorldFriction(const World& world);

  // The impact law of a contact of ball i with the other ball j, or with a plane, cylinder or
  // box whose coefficients are `shape` (shapeFriction).
  ImpactFriction impactFriction(int i, int j) const {
    return {std::max(friction[i].sliding, friction[j].sliding), tangentialRestitution};
  }
  ImpactFriction impactFriction(int i, const ContactFriction& shape) const {
    return {std::max(friction[i].sliding, shape.sliding), tangentialRestitution};
  }
  // The coefficients of the plane, cylinder or box `index` (by the kind of its contact).
  const ContactFriction& shapeFriction(ContactKind kind, int index) const {
    return kind == ContactKind::BallBox        ? boxFriction[index]
           : kind == ContactKind::BallCylinder ? cylinderFriction[index]
                                               : planeFriction[index];
  }
  // Every coefficient of such a contact.
  ContactFriction contactFriction(int i, const ContactFriction& shape) const {
    return larger(friction[i], shape);
  }
};

Bodies makeBodies(const Scene& scene);

// The state that moves: what steppers hand over to each other when the method changes.
struct BallState {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  bool resting = false;
  Vec3 angularVelocity =
      Vec3::Zero();  // put to rest by the rest policy: immovable until hit hard enough
};

}  // namespace carom
