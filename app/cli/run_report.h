#pragma once
// `carom-cli run`: runs a scene and reports what happened, as text or as one JSON object.

#include "app/cli/cli_arguments.h"
#include "sim/scene.h"

#include <QTextStream>

namespace carom::cli {

int runScene(const Scene& scene, const RunOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
