#pragma once
// The scene file format's names and versions (docs/scene-format.md), shared by its readers and
// its writer.

#include <string_view>

namespace carom::io::format {

inline constexpr std::string_view kName = "carom-scene";
// The newest version this Carom reads and writes. A scene with no box and no capped cylinder is
// still written as version 1, so that files older Carom can read stay readable by it.
inline constexpr int kVersion = 2;
inline constexpr int kFirstVersionWithBoxes = 2;  // and capped cylinders

// The keys each object may have; any other is kept as it is (ObjectInfo::extra).
inline constexpr std::string_view kTopKeys[] = {"format",    "version", "world", "planes",
                                                "cylinders", "boxes",   "balls"};
// Version 1 had no boxes: a "boxes" key there is one it does not know, kept as it is.
inline constexpr std::string_view kTopKeysVersion1[] = {"format", "version",   "world",
                                                        "planes", "cylinders", "balls"};
inline constexpr std::string_view kWorldKeys[] = {"gravity", "timeStep",   "restitution",
                                                  "method",  "integrator", "tolerance"};
// "method": "auto" asks for the pilot's choice; "tolerance": [energy, penetration] is what the
// choice must meet, and belongs to auto alone.
inline constexpr std::string_view kAutoMethodName = "auto";
inline constexpr std::string_view kPlaneKeys[] = {"name", "point", "normal", "restitution",
                                                  "color"};
inline constexpr std::string_view kCylinderKeys[] = {"name",   "point",       "axis", "radius",
                                                     "length", "restitution", "color"};
// Version 1 had no capped cylinders: there "length" is a key it does not know.
inline constexpr std::string_view kCylinderKeysVersion1[] = {"name",   "point",       "axis",
                                                             "radius", "restitution", "color"};
inline constexpr std::string_view kBoxKeys[] = {"name",     "center",      "halfExtents",
                                                "rotation", "restitution", "color"};
inline constexpr std::string_view kBallKeys[] = {"name", "position",    "velocity", "radius",
                                                 "mass", "restitution", "color"};

}  // namespace carom::io::format
