#pragma once
// `carom-cli bench --timeline`: what recording a run costs (sim/run_recording.h): the memory it
// holds under its budget and how long showing an earlier frame takes, for the magic room after
// an hour of simulated time and the bench's gas of 10,000 balls after a minute.

#include "app/cli/cli_arguments.h"

#include <QTextStream>

namespace carom::cli {

int runTimelineBench(const BenchOptions& options, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
