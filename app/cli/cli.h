#pragma once
// carom-cli: run, validate and benchmark scenes without a window.

#include <QStringList>
#include <QTextStream>

namespace carom::cli {

// Exit codes: 0 success, 2 bad input (usage, unreadable or invalid scene), 1 internal failure,
// 3 a run stopped by its watch (--stop-on-divergence, after its report so far), 130 a run
// stopped by Ctrl+C (after its report so far; the shells' code for SIGINT), 4 a `--method auto`
// run whose tolerance no setting meets (after the pilot's report; nothing ran).
enum ExitCode {
  kOk = 0,
  kInternalError = 1,
  kBadInput = 2,
  kDiverged = 3,
  kNoSettingMeets = 4,
  kInterrupted = 130
};

// Runs the command in `arguments` (without the program name), writing results to `out` and
// messages and progress to `err`.
int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err);

}  // namespace carom::cli
