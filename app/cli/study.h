#pragma once
// `carom-cli study`: the Speed vs accuracy study of a scene on a thread pool, as a table of runs
// and how much running them side by side gained.

#include "app/cli/cli_arguments.h"
#include "sim/model/scene.h"

#include <QTextStream>

namespace carom::cli {

int runStudy(const Scene& scene, const StudyOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
