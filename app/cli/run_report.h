#pragma once
// `carom-cli run`: runs a scene and reports what happened, as text or as one JSON object.

#include "app/cli/cli_arguments.h"
#include "sim/measure/method_choice.h"
#include "sim/model/scene.h"

#include <QElapsedTimer>
#include <QTextStream>

namespace carom::cli {

// `started` was started before the scene was loaded: the report's wall time is all the work,
// its set-up part included. Returns kInterrupted, after the report so far, when Ctrl+C stopped
// the run, and kDiverged when the watch (options.stopOnDivergence) did. `choice`, when `--method
// auto` chose the scene's settings, goes into the report with the pilot's share of the run.
int runScene(const Scene& scene, const RunOptions& options, const QElapsedTimer& started,
             QTextStream& out, QTextStream& err, const MethodChoice* choice = nullptr);

}  // namespace carom::cli
