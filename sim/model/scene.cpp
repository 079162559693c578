#include "sim/model/scene.h"

#include <array>
#include <utility>

namespace carom {
namespace {

constexpr std::array<std::pair<Method, std::string_view>, 3> kMethods{{
    {Method::Exact, "exact"},
    {Method::Swept, "swept"},
    {Method::Discrete, "discrete"},
}};

constexpr std::array<std::pair<Integrator, std::string_view>, 3> kIntegrators{{
    {Integrator::ExplicitEuler, "explicit-euler"},
    {Integrator::SymplecticEuler, "symplectic-euler"},
    {Integrator::VelocityVerlet, "velocity-verlet"},
}};

template <typename Table, typename Value>
std::string_view nameOf(const Table& table, Value value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return {};
}

template <typename Table>
auto valueOf(const Table& table, std::string_view name)
    -> std::optional<typename Table::value_type::first_type> {
  for (const auto& [v, n] : table)
    if (n == name) return v;
  return std::nullopt;
}

template <typename Table>
std::vector<std::string_view> namesOf(const Table& table) {
  std::vector<std::string_view> names;
  for (const auto& entry : table) names.push_back(entry.second);
  return names;
}

}  // namespace

std::string_view methodName(Method method) {
  return nameOf(kMethods, method);
}
std::string_view integratorName(Integrator integrator) {
  return nameOf(kIntegrators, integrator);
}
std::optional<Method> methodFromName(std::string_view name) {
  return valueOf(kMethods, name);
}
std::optional<Integrator> integratorFromName(std::string_view name) {
  return valueOf(kIntegrators, name);
}
std::vector<std::string_view> methodNames() {
  return namesOf(kMethods);
}
std::vector<std::string_view> integratorNames() {
  return namesOf(kIntegrators);
}

ContactFriction objectFriction(const World& world, const ObjectInfo& object) {
  return {object.friction.value_or(world.friction),
          object.rollingResistance.value_or(world.rollingResistance),
          object.spinningFriction.value_or(world.spinningFriction)};
}

ContactFriction contactFriction(const World& world, const ObjectInfo& a, const ObjectInfo& b) {
  return larger(objectFriction(world, a), objectFriction(world, b));
}

namespace {

bool ownFriction(const ObjectInfo& object) {
  for (const std::optional<double>& value :
       {object.friction, object.rollingResistance, object.spinningFriction})
    if (value && *value != 0.0) return true;
  return false;
}

template <typename Objects>
bool anyOwnFriction(const Objects& objects) {
  for (const auto& object : objects)
    if (ownFriction(object)) return true;
  return false;
}

}  // namespace

bool hasFrictionCoefficients(const Scene& scene) {
  const World& w = scene.world;
  return w.friction != 0.0 || w.rollingResistance != 0.0 || w.spinningFriction != 0.0 ||
         anyOwnFriction(scene.planes) || anyOwnFriction(scene.cylinders) ||
         anyOwnFriction(scene.boxes) || anyOwnFriction(scene.balls);
}

bool usesFriction(const Scene& scene) {
  if (hasFrictionCoefficients(scene) || scene.world.tangentialRestitution != 0.0) return true;
  for (const Ball& ball : scene.balls)
    if (!ball.angularVelocity.isZero(0.0)) return true;
  return false;
}

}  // namespace carom
