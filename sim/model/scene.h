#pragma once
// The scene model: plain data, shared by the physics, the scene files, the CLI and the editor.

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace carom {

using Vec3 = Eigen::Vector3d;

enum class Method { Exact, Swept, Discrete };
enum class Integrator { ExplicitEuler, SymplecticEuler, VelocityVerlet };

// Keys as written in scene files and on the command line ("exact", "velocity-verlet", ...).
std::string_view methodName(Method method);
std::string_view integratorName(Integrator integrator);
std::optional<Method> methodFromName(std::string_view name);
std::optional<Integrator> integratorFromName(std::string_view name);
std::vector<std::string_view> methodNames();
std::vector<std::string_view> integratorNames();

// Fields every object kind carries besides its geometry. `extra` holds the object's unknown
// scene-file keys as the text of a JSON object (empty when there are none), so that they survive
// a load/save round trip without the physics knowing JSON.
struct ObjectInfo {
  std::optional<double> restitution;  // none: the world's value
  // Coulomb friction μ, rolling resistance μ_r and spinning friction μ_sp (docs/physics.md,
  // "Friction and spin"); none: the world's value.
  std::optional<double> friction;
  std::optional<double> rollingResistance;
  std::optional<double> spinningFriction;
  std::string name;
  std::string color;  // "#rrggbb", or empty for the default
  std::string extra;
  friend bool operator==(const ObjectInfo&, const ObjectInfo&) = default;
};

struct Ball : ObjectInfo {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();  // rad/s; a uniform solid sphere, moment 2/5·m·r²
  double radius = 1.0;
  double mass = 1.0;
  friend bool operator==(const Ball&, const Ball&) = default;
};

// Solid half-space: balls live on the side the normal points to.
struct Plane : ObjectInfo {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();  // any non-zero length
  friend bool operator==(const Plane&, const Plane&) = default;
};

// Solid cylinder around the line through `point` along `axis`: infinite, or with a `length`
// and flat caps, `point` then being the middle of its axis.
struct Cylinder : ObjectInfo {
  Vec3 point = Vec3::Zero();
  Vec3 axis = Vec3::UnitY();  // any non-zero length
  double radius = 1.0;
  std::optional<double> length;
  friend bool operator==(const Cylinder&, const Cylinder&) = default;
};

// A turn by `degrees` about `axis` (any non-zero length), right-handed.
struct Rotation {
  Vec3 axis = Vec3::UnitY();
  double degrees = 0.0;
  friend bool operator==(const Rotation&, const Rotation&) = default;
};

// Solid cuboid around `center`, `halfExtents` along its own axes: the world's axes turned by
// `rotation` (none: not turned).
struct Box : ObjectInfo {
  Vec3 center = Vec3::Zero();
  Vec3 halfExtents = Vec3::Constant(0.5);
  std::optional<Rotation> rotation;
  friend bool operator==(const Box&, const Box&) = default;
};

// What method "auto" asks of the setting it chooses (sim/method_choice.h).
struct AccuracyTolerance {
  // Relative energy error per simulated second, by EnergyYardstick (accuracy_study.h).
  double energyPerSecond = 1e-3;
  // The deepest penetration, as a fraction of the smallest ball's radius.
  double penetrationFraction = 0.05;
  friend bool operator==(const AccuracyTolerance&, const AccuracyTolerance&) = default;
};

struct World {
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);
  double timeStep = 1.0 / 60.0;
  double restitution = 1.0;
  double friction = 0.0;
  double rollingResistance = 0.0;
  double spinningFriction = 0.0;
  // Walton's β: an impact turns the contact point's tangential velocity into at most -β times
  // itself (0: it at most stops the slip; 1: a perfectly rough, elastic reversal).
  double tangentialRestitution = 0.0;
  Method method = Method::Exact;
  Integrator integrator = Integrator::SymplecticEuler;
  // Method "auto": the window and carom-cli choose method, integrator and step for this
  // tolerance with a pilot of the scene. The three fields above then hold the latest choice,
  // or what the pilot starts from; the physics reads only them.
  std::optional<AccuracyTolerance> autoMethod;
  std::string extra;
  friend bool operator==(const World&, const World&) = default;
};

struct Scene {
  World world;
  std::vector<Plane> planes;
  std::vector<Cylinder> cylinders;
  std::vector<Box> boxes;
  std::vector<Ball> balls;
  std::string extra;  // unknown top-level keys
  friend bool operator==(const Scene&, const Scene&) = default;
};

// A contact's restitution: the smaller of the two objects' values, each defaulting to the world's.
inline double contactRestitution(const World& world, const ObjectInfo& a, const ObjectInfo& b) {
  const double ea = a.restitution.value_or(world.restitution);
  const double eb = b.restitution.value_or(world.restitution);
  return ea < eb ? ea : eb;
}

// A contact's friction coefficients: the larger of the two objects' values (MuJoCo's rule), each
// defaulting to the world's.
struct ContactFriction {
  double sliding = 0.0;
  double rolling = 0.0;
  double spinning = 0.0;
  friend bool operator==(const ContactFriction&, const ContactFriction&) = default;
};
ContactFriction contactFriction(const World& world, const ObjectInfo& a, const ObjectInfo& b);
// An object's own coefficients, each defaulting to the world's.
ContactFriction objectFriction(const World& world, const ObjectInfo& object);
inline ContactFriction larger(const ContactFriction& a, const ContactFriction& b) {
  return {a.sliding > b.sliding ? a.sliding : b.sliding,
          a.rolling > b.rolling ? a.rolling : b.rolling,
          a.spinning > b.spinning ? a.spinning : b.spinning};
}

// What Walton's law of an impact needs (sim/dynamics/response.h): the contact's μ and the
// world's β.
struct ImpactFriction {
  double friction = 0.0;
  double tangentialRestitution = 0.0;
};

// Whether the scene asks for friction or spin: any non-zero friction coefficient, β or angular
// velocity (scene format version 3). A scene that does not runs today's frictionless physics.
bool usesFriction(const Scene& scene);
// Whether any contact of the scene can have friction: a coefficient above zero somewhere.
bool hasFrictionCoefficients(const Scene& scene);

}  // namespace carom
