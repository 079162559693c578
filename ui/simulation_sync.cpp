#include "ui/simulation_sync.h"

#include "sim/validation/validation.h"
#include "ui/editor/running_state.h"
#include "ui/editor/scene_document.h"
#include "ui/editor/validation_text.h"
#include "ui/run/call_queue.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <chrono>
#include <utility>
#include <vector>

namespace carom::ui {

SimulationSync::SimulationSync(editor::SceneDocument* document, RunSession* run, QObject* parent)
    : QObject(parent), document_(document), run_(run), calls_(new CallQueue(this)) {
  connect(document_, &editor::SceneDocument::sceneChanged, this, &SimulationSync::documentChanged);
  // The thread making a start reads the document: it must not change under it.
  connect(document_, &editor::SceneDocument::aboutToChange, this, &SimulationSync::finishStart,
          Qt::DirectConnection);
}

SimulationSync::~SimulationSync() {
  if (pendingStart_.valid()) pendingStart_.wait();
}

void SimulationSync::documentChanged(const editor::SceneChange& change) {
  if (!change.objectsChanged()) {
    // World settings change live, from the running state on; the simulation decides what that
    // rebuilds.
    if (change.world) run_->controls().setWorld(document_->scene().world);
    return;
  }
  finishStart();
  const bool keepRunningState = applyToRunningState_ && start_ && !change.replaced;
  std::shared_ptr<const Scene> runningFrom = keepRunningState ? start_ : nullptr;
  // Of the last start only (RunSession): the worker may not have answered that restart yet.
  std::shared_ptr<const SimulationSnapshot> snapshot = keepRunningState ? run_->latest() : nullptr;
  const Scene& edited = document_->scene();
  if (edited.balls.size() < kBackgroundBalls) {
    restart(makeStart(edited, change, runningFrom, snapshot));
    return;
  }
  // The start before goes with the thread, which frees it if it is the last to hold it: a
  // million balls took 50 ms to free.
  pendingStart_ = std::async(std::launch::async, [this, &edited, change, runningFrom, snapshot,
                                                  previous = std::move(start_)]() mutable {
    Start start = makeStart(edited, change, runningFrom, snapshot);
    runningFrom.reset();
    previous.reset();
    calls_->post([this] { startMade(); });
    return start;
  });
}

void SimulationSync::finishStart() {
  if (pendingStart_.valid()) restart(pendingStart_.get());
}

void SimulationSync::startMade() {
  // A later start may be under way by now (the document changed and took the one this notice
  // is of): that one sends its own notice.
  if (pendingStart_.valid() &&
      pendingStart_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    finishStart();
}

void SimulationSync::restart(Start start) {
  if (start.unfitRunningState)
    emit message(
        tr("The edit does not fit the running state (%1): restarted from the edited scene.")
            .arg(editor::validationText(*start.unfitRunningState, *start.scene)));
  start_ = std::move(start.scene);
  run_->start(start_);
}

// The edited scene, with every ball the edit left alone where the running simulation has it
// (`snapshot`, or where it started from when there is none yet); when that state would overlap
// what the edit added, or there is no running state, the edited scene as it is.
SimulationSync::Start SimulationSync::makeStart(
    const Scene& edited, const editor::SceneChange& change,
    const std::shared_ptr<const Scene>& runningFrom,
    const std::shared_ptr<const SimulationSnapshot>& snapshot) {
  if (!runningFrom) return {std::make_shared<const Scene>(edited), {}};
  // The run's state in the order of the scene before this change.
  std::vector<Vec3> positions, velocities, angularVelocities;
  if (snapshot) {
    positions = snapshot->positions;
    velocities = snapshot->velocities;
    angularVelocities = snapshot->angularVelocities;
  } else {
    for (const Ball& ball : runningFrom->balls) {
      positions.push_back(ball.position);
      velocities.push_back(ball.velocity);
      angularVelocities.push_back(ball.angularVelocity);
    }
  }
  Scene start = editor::withRunningBalls(edited, change, positions, velocities, angularVelocities);
  if (const std::vector<ValidationError> errors = validateScene(start, 1); !errors.empty())
    return {std::make_shared<const Scene>(edited), errors.front()};
  return {std::make_shared<const Scene>(std::move(start)), {}};
}

}  // namespace carom::ui
