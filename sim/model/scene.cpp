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

}  // namespace carom
