#pragma once
// How carom-cli ends: its exit codes, shared by its commands.

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

}  // namespace carom::cli
