#pragma once
// `carom-cli bench --sizes`: the cost of mixed ball sizes. A gas of 1 cm balls alone in a room,
// then with four balls of 10 cm to 10 m apart from it and sweeping through it, under `exact` and
// `swept`.

#include "app/cli/cli_arguments.h"

#include <QTextStream>

namespace carom::cli {

int runSizeBench(const BenchOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
