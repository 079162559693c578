#include "app/cli/cli.h"

#include "app/cli/bench.h"
#include "app/cli/cli_arguments.h"
#include "app/cli/file_bench.h"
#include "app/cli/method_report.h"
#include "app/cli/run_report.h"
#include "app/cli/size_bench.h"
#include "app/cli/study.h"
#include "app/cli/timeline_bench.h"
#include "sim/io/file_names.h"
#include "sim/io/scene_file.h"
#include "sim/validation/validation.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonDocument>

#include <exception>
#include <new>

namespace carom::cli {
namespace {

QString joined(const std::vector<std::string_view>& names) {
  QStringList list;
  for (std::string_view name : names) list << QString::fromUtf8(name.data(), name.size());
  return list.join(", ");
}

// Loads the scene and applies the command line's overrides, checked by the one scene validation.
std::optional<Scene> prepareScene(const RunOptions& options, QTextStream& err) {
  io::SceneLoadResult loaded = io::loadSceneFile(options.scenePath);
  if (!loaded.scene) {
    err << loaded.error << "\n";
    return std::nullopt;
  }
  Scene scene = std::move(*loaded.scene);
  if (options.method) {
    const auto method = methodFromName(options.method->toStdString());
    if (!method) {
      err << "carom-cli: unknown method '" << *options.method << "' (choose "
          << joined(methodNames()) << ")\n";
      return std::nullopt;
    }
    scene.world.method = *method;
    scene.world.autoMethod.reset();
  }
  if (options.integrator) {
    const auto integrator = integratorFromName(options.integrator->toStdString());
    if (!integrator) {
      err << "carom-cli: unknown integrator '" << *options.integrator << "' (choose "
          << joined(integratorNames()) << ")\n";
      return std::nullopt;
    }
    scene.world.integrator = *integrator;
  }
  if (options.timeStep) {
    scene.world.timeStep = *options.timeStep;
    const std::vector<ValidationError> errors = validateScene(scene, 1);
    if (!errors.empty()) {
      err << "carom-cli: --dt " << QString::fromStdString(errors.front().message) << "\n";
      return std::nullopt;
    }
  }
  return scene;
}

// --method auto: the pilot, then the run of its choice, or the pilot's report alone and
// kNoSettingMeets when nothing meets the tolerance and the closest was not asked for.
int runAuto(const Scene& scene, const RunOptions& options, const QElapsedTimer& started,
            QTextStream& out, QTextStream& err) {
  err << "carom-cli: auto: piloting " << autoCandidates(scene.world).size() << " settings...\n";
  err.flush();
  const MethodChoice choice = chooseMethod(scene, options.duration, options.tolerance);
  if (choice.candidates.empty()) return kInternalError;
  if (!choice.chosen && !options.acceptClosest) {
    if (options.json)
      out << QJsonDocument(QJsonObject{{"auto", choiceJson(choice, options.tolerance)}})
                 .toJson(QJsonDocument::Compact)
          << "\n";
    else
      printChoice(out, choice, options.tolerance);
    const PilotMeasure& closest = choice.pick();
    err << "carom-cli: no setting meets the tolerance (energy error "
        << options.tolerance.energyPerSecond << " per simulated second, penetration "
        << options.tolerance.penetrationFraction << " of the radius); the closest is "
        << settingsText(closest.settings) << ", " << QString::fromStdString(closest.verdict)
        << "; give --accept-closest to run it, or a looser --tolerance\n";
    return kNoSettingMeets;
  }
  Scene chosen = scene;
  chosen.world.method = choice.pick().settings.method;
  chosen.world.integrator = choice.pick().settings.integrator;
  chosen.world.timeStep = choice.pick().settings.timeStep;
  return runScene(chosen, options, started, out, err, &choice);
}

int dispatch(const Command& command, QTextStream& out, QTextStream& err) {
  switch (command.kind) {
    case Command::Help:
      out << usageText();
      return kOk;
    case Command::Version:
      out << "carom-cli " << QCoreApplication::applicationVersion() << "\n";
      return kOk;
    case Command::Validate: {
      if (!prepareScene(command.run, err)) return kBadInput;
      out << "ok\n";
      return kOk;
    }
    case Command::Run: {
      QElapsedTimer started;  // the report's wall time includes loading and checking the scene
      started.start();
      RunOptions run = command.run;
      if (run.trajectoryPath && io::isSameFile(*run.trajectoryPath, run.scenePath)) {
        err << "carom-cli: --trajectory " << *run.trajectoryPath << " is the scene file "
            << run.scenePath << " itself; give the trajectory another file\n";
        return kBadInput;
      }
      const std::optional<Scene> scene = prepareScene(run, err);
      if (!scene) return kBadInput;
      // A scene saved under method auto asks for the pilot, unless a method is given.
      if (scene->world.autoMethod && !run.method) {
        if (run.integrator) {
          err << "carom-cli: the scene's method is auto, which chooses the integrator: give "
                 "--method too, or leave --integrator out\n";
          return kBadInput;
        }
        run.autoMethod = true;
        if (!run.toleranceGiven) run.tolerance = *scene->world.autoMethod;
      }
      if (run.autoMethod) return runAuto(*scene, run, started, out, err);
      return runScene(*scene, run, started, out, err);
    }
    case Command::Bench:
      if (command.bench.files) return runFileBench(command.bench, out, err);
      if (command.bench.sizes) return runSizeBench(command.bench, out, err);
      return command.bench.timeline ? runTimelineBench(command.bench, out, err)
                                    : runBench(command.bench, out, err);
    case Command::Study: {
      RunOptions load;
      load.scenePath = command.study.scenePath;
      const std::optional<Scene> scene = prepareScene(load, err);
      if (!scene) return kBadInput;
      return runStudy(*scene, command.study, out, err);
    }
  }
  return kInternalError;
}

}  // namespace

int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err) {
  const ParseResult parsed = parseArguments(arguments);
  if (!parsed.command) {
    err << "carom-cli: " << parsed.error << "\nTry 'carom-cli --help'.\n";
    return kBadInput;
  }
  try {
    return dispatch(*parsed.command, out, err);
  } catch (const std::bad_alloc&) {
    err << "carom-cli: not enough memory for this scene\n";
    return kInternalError;
  } catch (const std::exception& e) {
    err << "carom-cli: internal error: " << e.what() << "\n";
    return kInternalError;
  }
}

}  // namespace carom::cli
