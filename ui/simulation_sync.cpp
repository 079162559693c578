#include "ui/simulation_sync.h"

#include "sim/validation.h"
#include "ui/editor/running_state.h"
#include "ui/editor/scene_document.h"
#include "ui/simulation_controller.h"

namespace carom::ui {

SimulationSync::SimulationSync(editor::SceneDocument* document, SimulationController* simulation,
                               QObject* parent)
    : QObject(parent), document_(document), simulation_(simulation) {
  connect(document_, &editor::SceneDocument::sceneChanged, this, &SimulationSync::documentChanged);
}

void SimulationSync::documentChanged(const editor::SceneChange& change) {
  if (!change.objectsChanged()) {
    // World settings change live, from the running state on; the simulation decides what that
    // rebuilds.
    if (change.world) simulation_->setWorld(document_->scene().world);
    return;
  }
  const bool keepRunningState = applyToRunningState_ && start_ && !change.replaced;
  auto start = std::make_shared<const Scene>(keepRunningState ? withRunningState(change)
                                                              : document_->scene());
  start_ = start;
  startNumber_ = simulation_->loadScene(start);
  emit restarted(start);
}

// The edited scene, with every ball the edit left alone where the running simulation has it.
// When that state would overlap what the edit added, the edited scene as it is.
Scene SimulationSync::withRunningState(const editor::SceneChange& change) {
  const Scene& edited = document_->scene();
  // The run's state in the order of the scene before this change. A snapshot of an older start
  // (the worker has not yet answered the last restart) is of no use: that start is, then.
  const std::shared_ptr<const SimulationSnapshot> snapshot = simulation_->latest();
  std::vector<Vec3> positions, velocities;
  if (snapshot && snapshot->startNumber == startNumber_) {
    positions = snapshot->positions;
    velocities = snapshot->velocities;
  } else {
    for (const Ball& ball : start_->balls) {
      positions.push_back(ball.position);
      velocities.push_back(ball.velocity);
    }
  }
  const Scene start = editor::withRunningBalls(edited, change, positions, velocities);
  if (const std::vector<ValidationError> errors = validateScene(start, 1); !errors.empty()) {
    emit message(
        tr("The edit does not fit the running state (%1): restarted from the edited scene.")
            .arg(QString::fromStdString(errors.front().text())));
    return edited;
  }
  return start;
}

}  // namespace carom::ui
