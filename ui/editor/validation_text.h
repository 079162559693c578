#pragma once
// The scene validation's problems in the user's words and language: objects named as the
// Outline names them ("Ball 3", "floor"), fields as the Properties dock labels them, numbers in
// the current locale. The file paths of ValidationError::text() are for files and carom-cli.

#include "sim/model/scene.h"
#include "sim/validation/validation.h"

#include <QString>

namespace carom::editor {

// `scene` holds the objects `error` names: for an addition, with the added objects in it.
QString validationText(const ValidationError& error, const Scene& scene);

}  // namespace carom::editor
