#pragma once
// carom-cli: run, validate and benchmark scenes without a window.

#include "app/cli/exit_code.h"

#include <QStringList>
#include <QTextStream>

namespace carom::cli {

// Runs the command in `arguments` (without the program name), writing results to `out` and
// messages and progress to `err`.
int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
