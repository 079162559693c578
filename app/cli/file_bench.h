#pragma once
// `carom-cli bench --files`: what a scene file of a million balls costs: its size, and the time
// and memory of saving it, loading and validating it, and the first prediction of its run.

#include "app/cli/cli_arguments.h"

#include <QTextStream>

namespace carom::cli {

int runFileBench(const BenchOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
