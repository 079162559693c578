#pragma once
// The one validation of scenes: the loader, the CLI and the editor all call this.

#include "sim/scene.h"

#include <string>
#include <vector>

namespace carom {

struct ValidationError {
  std::string path;     // field path such as "balls[3].radius" or "world.timeStep"
  std::string message;  // what is wrong, such as "must be positive (got -1)"
  std::string text() const { return path.empty() ? message : path + ": " + message; }
};

// All problems of the scene, in file order (at most `maxErrors`); empty when the scene is valid.
// Checks every number is finite and within the limits of tolerances.h, radii and masses are
// positive, restitution is in [0, 1], normals and axes are not zero-length, colours are
// "#rrggbb", and that no ball overlaps another ball, a plane or a cylinder (touching is fine).
std::vector<ValidationError> validateScene(const Scene& scene, std::size_t maxErrors = 20);

}  // namespace carom
