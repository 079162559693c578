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
  std::string name;
  std::string color;  // "#rrggbb", or empty for the default
  std::string extra;
  friend bool operator==(const ObjectInfo&, const ObjectInfo&) = default;
};

struct Ball : ObjectInfo {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
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

}  // namespace carom
