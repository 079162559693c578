#pragma once
// The command line of carom-cli, parsed into plain values; nothing runs here.

#include <QString>
#include <QStringList>

#include <optional>

namespace carom::cli {

struct RunOptions {
  QString scenePath;
  double duration = 10.0;
  std::optional<QString> method;
  std::optional<QString> integrator;
  std::optional<double> timeStep;
  std::optional<QString> trajectoryPath;
  bool json = false;
};

struct BenchOptions {
  bool quick = false;  // small sizes, for a smoke test
};

struct Command {
  enum Kind { Help, Version, Run, Validate, Bench } kind = Help;
  RunOptions run;      // Run; Validate uses run.scenePath
  BenchOptions bench;  // Bench
};

struct ParseResult {
  std::optional<Command> command;
  QString error;  // when command is empty: what is wrong with the arguments
};

ParseResult parseArguments(const QStringList& arguments);

QString usageText();

}  // namespace carom::cli
