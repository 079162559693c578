#pragma once
// `carom-cli bench`: the benchmark scenes of docs/benchmarks.md, as a table.

#include "app/cli/cli_arguments.h"

#include <QTextStream>

namespace carom::cli {

int runBench(const BenchOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
