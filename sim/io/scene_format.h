#pragma once
// The scene file format's names and versions (docs/scene-format.md), shared by its readers and
// its writer.

#include <span>
#include <string_view>

namespace carom::io::format {

inline constexpr std::string_view kName = "carom-scene";
// The newest version this Carom reads and writes. A scene is written in the oldest version that
// holds it, so that files older Carom can read stay readable by it: version 1 unless it has a box
// or a capped cylinder, version 3 only when it has friction or spin.
inline constexpr int kVersion = 3;
inline constexpr int kFirstVersionWithBoxes = 2;     // and capped cylinders
inline constexpr int kFirstVersionWithFriction = 3;  // and angular velocity

// The keys each object may have; any other is kept as it is (ObjectInfo::extra).
inline constexpr std::string_view kTopKeys[] = {"format",    "version", "world", "planes",
                                                "cylinders", "boxes",   "balls"};
// Version 1 had no boxes: a "boxes" key there is one it does not know, kept as it is.
inline constexpr std::string_view kTopKeysVersion1[] = {"format", "version",   "world",
                                                        "planes", "cylinders", "balls"};
inline constexpr std::string_view kWorldKeys[] = {
    "gravity",           "timeStep",         "restitution",           "friction",
    "rollingResistance", "spinningFriction", "tangentialRestitution", "method",
    "integrator",        "tolerance"};
// Versions 1 and 2 had no friction and no spin: there their keys are ones they do not know.
inline constexpr std::string_view kWorldKeysVersion2[] = {"gravity", "timeStep",   "restitution",
                                                          "method",  "integrator", "tolerance"};
// "method": "auto" asks for the pilot's choice; "tolerance": [energy, penetration] is what the
// choice must meet, and belongs to auto alone.
inline constexpr std::string_view kAutoMethodName = "auto";
inline constexpr std::string_view kPlaneKeys[] = {
    "name", "point", "normal", "restitution", "friction", "rollingResistance", "spinningFriction",
    "color"};
inline constexpr std::string_view kPlaneKeysVersion2[] = {"name", "point", "normal", "restitution",
                                                          "color"};
inline constexpr std::string_view kCylinderKeys[] = {"name",
                                                     "point",
                                                     "axis",
                                                     "radius",
                                                     "length",
                                                     "restitution",
                                                     "friction",
                                                     "rollingResistance",
                                                     "spinningFriction",
                                                     "color"};
inline constexpr std::string_view kCylinderKeysVersion2[] = {
    "name", "point", "axis", "radius", "length", "restitution", "color"};
// Version 1 had no capped cylinders: there "length" is a key it does not know.
inline constexpr std::string_view kCylinderKeysVersion1[] = {"name",   "point",       "axis",
                                                             "radius", "restitution", "color"};
inline constexpr std::string_view kBoxKeys[] = {
    "name",        "center",   "halfExtents",       "rotation",
    "restitution", "friction", "rollingResistance", "spinningFriction",
    "color"};
inline constexpr std::string_view kBoxKeysVersion2[] = {"name",     "center",      "halfExtents",
                                                        "rotation", "restitution", "color"};
inline constexpr std::string_view kBallKeys[] = {
    "name",        "position", "velocity",          "angularVelocity",  "radius", "mass",
    "restitution", "friction", "rollingResistance", "spinningFriction", "color"};
inline constexpr std::string_view kBallKeysVersion2[] = {
    "name", "position", "velocity", "radius", "mass", "restitution", "color"};

// The keys a file of one version knows, each object's.
struct VersionKeys {
  std::span<const std::string_view> top, world, plane, cylinder, box, ball;
};
constexpr VersionKeys versionKeys(int version) {
  if (version >= kFirstVersionWithFriction)
    return {kTopKeys, kWorldKeys, kPlaneKeys, kCylinderKeys, kBoxKeys, kBallKeys};
  return {version >= kFirstVersionWithBoxes ? std::span<const std::string_view>(kTopKeys)
                                            : std::span<const std::string_view>(kTopKeysVersion1),
          kWorldKeysVersion2,
          kPlaneKeysVersion2,
          version >= kFirstVersionWithBoxes
              ? std::span<const std::string_view>(kCylinderKeysVersion2)
              : std::span<const std::string_view>(kCylinderKeysVersion1),
          kBoxKeysVersion2,
          kBallKeysVersion2};
}

}  // namespace carom::io::format
