#pragma once
// `carom-cli bench`: the benchmark scenes of the README, as a table.

#include "app/cli/cli_arguments.h"

#include <QTextStream>

namespace carom::cli {

int runBench(const BenchOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
