#pragma once
// How validation spells its problems: numbers as its messages quote them, objects and fields by
// the paths of the scene file, and the list the problems are gathered in, up to a limit.

#include "sim/validation/validation.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace carom::validation {

// Shortest text that reads back as the same double, with the exponent tidied ("1e300", not
// "1e+300") so that messages stay short.
std::string formatNumber(double value, int significantDigits = 0);

// Overlap depths are derived quantities; six digits keep "0.05" from printing as
// "0.04999999999999999".
std::string formatDepth(double value);

// An object's path, such as "balls[3]" or "world".
std::string objectPath(const ValidationObject& object);

// The path below the object, such as ".position"; a tolerance is spelled as its subject's file
// or command line spells it.
std::string_view fieldPath(ValidationField field, ValidationSubject subject);

// A ball's overlap with `other`, reported on the ball's position: by `depth`, or, for a plane,
// with its centre `behind` the surface.
ValidationError overlapError(std::size_t ball, ValidationObject other, double depth,
                             std::optional<double> behind = std::nullopt);

class ErrorList {
 public:
  explicit ErrorList(std::size_t maxErrors) : maxErrors_(maxErrors) {}

  bool full() const { return errors_.size() >= maxErrors_; }
  std::size_t room() const { return full() ? 0 : maxErrors_ - errors_.size(); }
  void add(ValidationError error) {
    if (!full()) errors_.push_back(std::move(error));
  }
  std::vector<ValidationError> take() { return std::move(errors_); }

 private:
  std::size_t maxErrors_;
  std::vector<ValidationError> errors_;
};

}  // namespace carom::validation
