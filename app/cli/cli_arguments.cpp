#include "app/cli/cli_arguments.h"

#include <cmath>

namespace carom::cli {
namespace {

// A number option: finite and within [low, high].
std::optional<double> parseNumber(const QString& text, double low, double high) {
  bool ok = false;
  const double value = text.toDouble(&ok);
  if (!ok || !std::isfinite(value) || value < low || value > high) return std::nullopt;
  return value;
}

ParseResult failure(const QString& message) {
  return {std::nullopt, message};
}

ParseResult durationFailure(const QString& value) {
  return failure(
      QString("--duration must be a number of seconds from 0 to 1e12 (got '%1')").arg(value));
}

// A word that is no option's value: the scene file, once; anything else is refused with the
// message returned.
std::optional<QString> takeScene(const QString& arg, QString& scenePath, bool& haveScene) {
  if (arg.startsWith("-") && arg != "-") return QString("unknown option '%1'").arg(arg);
  if (haveScene) return QString("unexpected argument '%1': give one scene file").arg(arg);
  scenePath = arg;
  haveScene = true;
  return std::nullopt;
}

ParseResult success(Command::Kind kind) {
  Command command;
  command.kind = kind;
  return {command, {}};
}

// The checks named in a --watch-off list ("energy-rise,escape"), into `settings`; the word not
// understood, if any.
std::optional<QString> turnChecksOff(const QString& list, WatchSettings& settings) {
  for (const QString& word : list.split(',')) {
    bool known = false;
    for (const WatchCheck& check : kWatchChecks) {
      if (word != QString::fromUtf8(check.name.data(), check.name.size())) continue;
      known = true;
      settings.*check.on = false;
    }
    if (!known) return word;
  }
  return std::nullopt;
}

// The watch's options: --watch-off and a tolerance a check. True when `arg` was one of them
// (its value taken from args[i + 1]); `error` says what was wrong.
bool parseWatchOption(const QStringList& args, int& i, WatchSettings& settings, bool& given,
                      QString& error) {
  const QString& arg = args[i];
  double* tolerance = arg == "--watch-energy-rise"   ? &settings.energyRiseTolerance
                      : arg == "--watch-escape"      ? &settings.escapeTolerance
                      : arg == "--watch-penetration" ? &settings.penetrationTolerance
                                                     : nullptr;
  if (!tolerance && arg != "--watch-off") return false;
  given = true;
  if (i + 1 >= args.size()) {
    error = QString("%1 needs a value").arg(arg);
    return true;
  }
  const QString value = args[++i];
  if (!tolerance) {
    if (const auto word = turnChecksOff(value, settings))
      error = QString(
                  "--watch-off takes checks from non-finite, energy-rise, escape, "
                  "penetration, separated by commas (got '%1')")
                  .arg(*word);
    return true;
  }
  const auto number = parseNumber(value, 0.0, kMaxWatchTolerance);
  if (!number)
    error = QString("%1 must be a number from 0 to %2 (got '%3')")
                .arg(arg)
                .arg(kMaxWatchTolerance)
                .arg(value);
  else
    *tolerance = *number;
  return true;
}

ParseResult parseRun(const QStringList& args, bool validateOnly) {
  Command command;
  command.kind = validateOnly ? Command::Validate : Command::Run;
  RunOptions& run = command.run;
  bool haveScene = false;
  bool watchGiven = false;
  for (int i = 0; i < args.size(); ++i) {
    const QString& arg = args[i];
    QString watchError;
    if (!validateOnly && parseWatchOption(args, i, run.watch, watchGiven, watchError)) {
      if (!watchError.isEmpty()) return failure(watchError);
      continue;
    }
    const bool takesValue =
        !validateOnly && (arg == "--duration" || arg == "--method" || arg == "--integrator" ||
                          arg == "--dt" || arg == "--trajectory" || arg == "--tolerance");
    if (takesValue) {
      if (i + 1 >= args.size()) return failure(QString("%1 needs a value").arg(arg));
      const QString value = args[++i];
      if (arg == "--duration") {
        const auto d = parseNumber(value, 0.0, 1e12);
        if (!d) return durationFailure(value);
        run.duration = *d;
      } else if (arg == "--dt") {
        const auto d = parseNumber(value, -1e300, 1e300);
        if (!d) return failure(QString("--dt must be a number of seconds (got '%1')").arg(value));
        run.timeStep = *d;  // range checked by scene validation with the rest of the world
      } else if (arg == "--method") {
        run.autoMethod = value == "auto";
        if (run.autoMethod)
          run.method.reset();
        else
          run.method = value;
      } else if (arg == "--tolerance") {
        // ENERGY or ENERGY,PENETRATION.
        const QStringList parts = value.split(',');
        const auto energy = parseNumber(parts.value(0), -1e300, 1e300);
        const auto penetration =
            parts.size() == 2 ? parseNumber(parts[1], -1e300, 1e300) : std::optional<double>();
        if (parts.size() > 2 || !energy || (parts.size() == 2 && !penetration))
          return failure(QString("--tolerance must be ENERGY or ENERGY,PENETRATION: the relative "
                                 "energy error per simulated second and the deepest penetration "
                                 "as a fraction of the radius (got '%1')")
                             .arg(value));
        run.tolerance.energyPerSecond = *energy;
        if (penetration) run.tolerance.penetrationFraction = *penetration;
        const std::vector<ValidationError> errors = validateTolerance(run.tolerance);
        if (!errors.empty())
          return failure(QString("--tolerance: %1").arg(QString::fromStdString(errors[0].text())));
        run.toleranceGiven = true;
      } else if (arg == "--integrator") {
        run.integrator = value;
      } else {
        run.trajectoryPath = value;
      }
    } else if (!validateOnly && arg == "--json") {
      run.json = true;
    } else if (!validateOnly && arg == "--stop-on-divergence") {
      run.stopOnDivergence = true;
    } else if (!validateOnly && arg == "--accept-closest") {
      run.acceptClosest = true;
    } else if (const auto problem = takeScene(arg, run.scenePath, haveScene)) {
      return failure(*problem);
    }
  }
  if (!haveScene) return failure("no scene file given");
  if (watchGiven && !run.stopOnDivergence)
    return failure("the --watch-... options set the watch of --stop-on-divergence: give it too");
  if ((run.toleranceGiven || run.acceptClosest) && !run.autoMethod)
    return failure("--tolerance and --accept-closest are for --method auto: give it too");
  if (run.autoMethod && run.integrator)
    return failure("--method auto chooses the integrator: leave --integrator out");
  return {command, {}};
}

ParseResult parseStudy(const QStringList& args) {
  Command command;
  command.kind = Command::Study;
  StudyOptions& study = command.study;
  bool haveScene = false;
  for (int i = 0; i < args.size(); ++i) {
    const QString& arg = args[i];
    if (arg == "--duration" || arg == "--threads") {
      if (i + 1 >= args.size()) return failure(QString("%1 needs a value").arg(arg));
      const QString value = args[++i];
      if (arg == "--duration") {
        const auto d = parseNumber(value, 0.0, 1e12);
        if (!d) return durationFailure(value);
        study.duration = *d;
      } else {
        bool ok = false;
        const int threads = value.toInt(&ok);
        if (!ok || threads < 1 || threads > 256)
          return failure(
              QString("--threads must be a whole number from 1 to 256 (got '%1')").arg(value));
        study.threads = threads;
      }
    } else if (const auto problem = takeScene(arg, study.scenePath, haveScene)) {
      return failure(*problem);
    }
  }
  if (!haveScene) return failure("no scene file given");
  return {command, {}};
}

}  // namespace

ParseResult parseArguments(const QStringList& arguments) {
  if (arguments.isEmpty()) return failure("no command given");
  const QString& verb = arguments.first();
  const QStringList rest = arguments.mid(1);
  if (verb == "--help" || verb == "-h" || verb == "help") return success(Command::Help);
  if (verb == "--version") return success(Command::Version);
  if (verb == "run") return parseRun(rest, false);
  if (verb == "validate") return parseRun(rest, true);
  if (verb == "study") return parseStudy(rest);
  if (verb == "bench") {
    Command command;
    command.kind = Command::Bench;
    for (const QString& arg : rest) {
      if (arg == "--quick")
        command.bench.quick = true;
      else if (arg == "--timeline")
        command.bench.timeline = true;
      else if (arg == "--files")
        command.bench.files = true;
      else if (arg == "--sizes")
        command.bench.sizes = true;
      else
        return failure(QString("unknown bench option '%1'").arg(arg));
    }
    if (int(command.bench.timeline) + int(command.bench.files) + int(command.bench.sizes) > 1)
      return failure("--timeline, --files and --sizes are three benches: give one of them");
    return {command, {}};
  }
  return failure(QString("unknown command '%1'").arg(verb));
}

QString usageText() {
  return QStringLiteral(
      "Usage:\n"
      "  carom-cli run SCENE [--duration S] [--method exact|swept|discrete|auto]\n"
      "                      [--integrator explicit-euler|symplectic-euler|velocity-verlet]\n"
      "                      [--dt S] [--trajectory FILE.csv] [--json]\n"
      "                      [--tolerance E[,P]] [--accept-closest]\n"
      "                      [--stop-on-divergence [--watch-off CHECK,...]\n"
      "                       [--watch-energy-rise F] [--watch-escape F]\n"
      "                       [--watch-penetration F]]\n"
      "      --stop-on-divergence checks every step for numbers gone wrong and stops at the\n"
      "      first: a non-finite position or velocity (non-finite), total energy above its\n"
      "      start by more than F (default 0.05) of the scene's energy scale when no\n"
      "      restitution exceeds 1 (energy-rise), a ball's centre F radii (default 0) inside a\n"
      "      solid (escape), an overlap deeper than F (default 0.5) of the smaller radius\n"
      "      (penetration). It prints the report so far and the event (kind, ball, time)\n"
      "      and exits with 3. --watch-off turns the checks named off.\n"
      "      --method auto pilots the scene for at most 5% of the run's expected computing\n"
      "      time under exact, and swept and discrete (symplectic Euler, velocity Verlet) at\n"
      "      1/4, 1 and 4 times the time step (--dt or the scene's), then runs the cheapest\n"
      "      that meets --tolerance: E the relative energy error per simulated second\n"
      "      (default 1e-3), P the deepest penetration as a fraction of the smallest radius\n"
      "      (default 0.05). The report lists every candidate and why it was or was not\n"
      "      chosen. When none meets it, the run exits with 4 unless --accept-closest asks\n"
      "      for the closest. A scene saved under auto runs so unless --method is given,\n"
      "      with its own tolerance unless --tolerance is.\n"
      "  carom-cli validate SCENE\n"
      "  carom-cli bench [--quick] [--timeline | --files | --sizes]\n"
      "  carom-cli study SCENE [--duration S] [--threads N]\n"
      "      The Speed vs accuracy study of the window (exact, then swept and discrete with\n"
      "      every integrator and 1/4 to 4 times the scene's time step), each run S seconds\n"
      "      long (default 5), its runs side by side on N threads (default: one per core).\n"
      "      Prints each run, then the wall time, the summed computing time and the speed-up.\n"
      "  carom-cli --help | --version\n"
      "A run shows progress on standard error (a bar on a terminal, a line every 10 s\n"
      "otherwise); Ctrl+C stops it and prints the report so far, marked as interrupted.\n"
      "Exit codes: 0 success, 2 bad input, 1 internal failure, 3 stopped by the watch\n"
      "(--stop-on-divergence), 4 no setting meets the tolerance (--method auto), 130\n"
      "interrupted by Ctrl+C.\n");
}

}  // namespace carom::cli
