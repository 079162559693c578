#include "ui/auto_method.h"

#include "ui/editor/number_text.h"
#include "ui/editor/scene_document.h"
#include "ui/run/call_queue.h"
#include "ui/run/thread_handover.h"

#include <functional>

namespace carom::ui {
namespace {

// QThreadPool hands its task over under a lock ThreadSanitizer cannot see (see
// accuracy_study_runner.cpp): the task takes over on this mark first.
char pilotHandOver;

QString text(std::string_view name) {
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

QString settingsText(const StudyCase& settings) {
  const QString method = text(methodName(settings.method));
  if (settings.method == Method::Exact) return method;
  return AutoMethod::tr("%1 (%2, step %3 s)")
      .arg(method, text(integratorName(settings.integrator)),
           editor::formatNumber(settings.timeStep, 'g', 4));
}

}  // namespace

struct AutoMethod::Pilot {
  Scene scene;
  AccuracyTolerance tolerance;
  MethodChoice choice;  // written by the task before it posts
  std::atomic<bool> cancel{false};
};

AutoMethod::AutoMethod(editor::SceneDocument* document, QObject* parent)
    : QObject(parent), document_(document), calls_(new CallQueue(this)) {
  pool_.setMaxThreadCount(1);
  connect(document_, &editor::SceneDocument::sceneChanged, this,
          [this](const editor::SceneChange& change) {
            if (change.world) worldChanged(change.replaced);
          });
  worldChanged(true);
}

AutoMethod::~AutoMethod() {
  if (running_) running_->cancel = true;
  pool_.waitForDone();
}

// A pilot runs when auto is asked for anew: chosen, given another tolerance, or opened with a
// scene. Its own choice (method, integrator, step) and their undo ask for nothing new.
void AutoMethod::worldChanged(bool newScene) {
  const std::optional<AccuracyTolerance>& asked = document_->scene().world.autoMethod;
  const bool anew = asked && (newScene || asked != asked_);
  asked_ = asked;
  if (asked) tolerance_ = *asked;
  if (anew) {
    pilot();
  } else if (!asked && running_) {
    running_->cancel = true;
    running_.reset();
  }
}

void AutoMethod::pilot() {
  if (!document_->scene().world.autoMethod) return;
  if (running_) running_->cancel = true;  // its result would be stale
  auto pilot = std::make_shared<Pilot>();
  pilot->scene = document_->scene();
  pilot->tolerance = *document_->scene().world.autoMethod;
  running_ = pilot;
  emit choosingStarted();
  // The task and its captures are made before the hand-over mark: the pool's thread outlives a
  // task, and the next one it runs reads captures written after the mark it took over.
  std::function<void()> task = [this, pilot] {
    takeOver(&pilotHandOver);
    pilot->choice =
        chooseMethod(pilot->scene, kPlannedRunSeconds, pilot->tolerance, &pilot->cancel);
    calls_->post([this, pilot] { apply(pilot); });
  };
  handOver(&pilotHandOver);
  pool_.start(std::move(task));
}

void AutoMethod::apply(const std::shared_ptr<Pilot>& pilot) {
  if (pilot != running_) return;  // cancelled or overtaken
  running_.reset();
  // The scene changed while the pilot ran (another file, an edit): its choice was for another.
  if (!(document_->scene() == pilot->scene)) {
    this->pilot();
    return;
  }
  const MethodChoice& choice = pilot->choice;
  if (choice.cancelled || choice.candidates.empty()) return;
  const QString tolerance = editor::formatNumber(pilot->tolerance.energyPerSecond, 'g', 3);
  const PilotMeasure& pick = choice.pick();
  const QString settings = settingsText(pick.settings);
  if (!choice.chosen) {
    emit finished(tr("Auto: no setting meets the accuracy; the settings are kept"),
                  tr("No setting meets an energy error of %1 per second; the closest is %2. "
                     "The settings are kept.")
                      .arg(tolerance, settings));
    return;
  }
  World world = document_->scene().world;
  world.method = pick.settings.method;
  world.integrator = pick.settings.integrator;
  world.timeStep = pick.settings.timeStep;
  // The History names the choice, where it stays to be read.
  const QString error = document_->editWorld(world, tr("Auto: %1").arg(settings));
  if (!error.isEmpty()) {
    emit finished(error, error);
    return;
  }
  emit finished(tr("Auto chose %1").arg(settings),
                tr("Auto chose %1: the cheapest setting with an energy error under %2 per "
                   "second (%3 s of computing per simulated second; pilot %4 s).")
                    .arg(settings, tolerance, editor::formatNumber(pick.costPerSecond, 'g', 2),
                         editor::formatNumber(choice.pilotSeconds, 'g', 2)));
}

}  // namespace carom::ui
