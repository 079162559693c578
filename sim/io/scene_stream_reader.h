#pragma once
// A one-pass reader of scene files for the common case: well-formed JSON whose fields all have
// the types they must. It builds the scene straight from the text, with no document tree in
// between, so that a million balls load in a second and take little more memory than the scene.
//
// It words no errors. On anything out of the ordinary (a syntax error, a missing field, a
// field of the wrong type, a duplicate key, format and version not the first two keys, a
// number beyond the doubles) it gives up, and parseScene reads the text again with the
// reader that names the problem, field path or line and column. It accepts only what that
// reader accepts, and then builds the same scene (tests/fuzz/fuzz_scene_loader checks both).

#include "sim/model/scene.h"

#include <optional>
#include <string_view>

namespace carom::io {

std::optional<Scene> readSceneStreaming(std::string_view json);

}  // namespace carom::io
