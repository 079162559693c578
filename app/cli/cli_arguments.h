#pragma once
// The command line of carom-cli, parsed into plain values; nothing runs here.

#include "sim/measure/method_choice.h"
#include "sim/measure/run_watch.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace carom::cli {

struct RunOptions {
  QString scenePath;
  double duration = 10.0;
  std::optional<QString> method;  // any name but "auto"
  // --method auto: a pilot chooses method, integrator and step for `tolerance`; with
  // --accept-closest the closest setting runs when none meets it.
  bool autoMethod = false;
  AccuracyTolerance tolerance;
  bool toleranceGiven = false;  // else a scene saved under auto brings its own
  bool acceptClosest = false;
  std::optional<QString> integrator;
  std::optional<double> timeStep;
  std::optional<QString> trajectoryPath;
  bool json = false;
  // --stop-on-divergence: the run watch checks every step and stops the run at its first event.
  bool stopOnDivergence = false;
  WatchSettings watch;  // valid (validateWatchSettings)
};

// The Speed vs accuracy study of a scene, as the window runs it, for timing its thread pool.
struct StudyOptions {
  QString scenePath;
  double duration = 5.0;       // simulated seconds per run, the window's default
  std::optional<int> threads;  // empty: one per core
};

struct BenchOptions {
  bool quick = false;     // small sizes, for a smoke test
  bool timeline = false;  // the timeline's memory and scrub latency instead
  bool files = false;     // saving, loading and first prediction of a million balls instead
  bool sizes = false;     // the cost of mixed ball sizes instead
};

struct Command {
  enum Kind { Help, Version, Run, Validate, Bench, Study } kind = Help;
  RunOptions run;      // Run; Validate uses run.scenePath
  BenchOptions bench;  // Bench
  StudyOptions study;  // Study
};

struct ParseResult {
  std::optional<Command> command;
  QString error;  // when command is empty: what is wrong with the arguments
};

ParseResult parseArguments(const QStringList& arguments);

QString usageText();

}  // namespace carom::cli
