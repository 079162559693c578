#include "ui/run/run_session.h"

#include "ui/run/simulation_snapshot.h"

#include <utility>

namespace carom::ui {

RunSession::RunSession(QObject* parent) : QObject(parent) {
  connect(&controller_, &SimulationController::snapshotPublished, this, &RunSession::takeSnapshot);
}

RunSession::~RunSession() = default;

void RunSession::start(std::shared_ptr<const carom::Scene> scene) {
  ++currentStart_;
  controller_.loadScene(scene, currentStart_);
  emit restarted(currentStart_, std::move(scene));
}

std::shared_ptr<const SimulationSnapshot> RunSession::latest() const {
  std::shared_ptr<const SimulationSnapshot> snapshot = controller_.latest();
  if (snapshot && snapshot->startNumber != currentStart_) return nullptr;
  return snapshot;
}

void RunSession::takeSnapshot() {
  // Taken even when stale, so that the worker announces the next one.
  std::shared_ptr<const SimulationSnapshot> snapshot = controller_.take();
  if (!snapshot || snapshot->startNumber != currentStart_) return;
  emit snapshotReady(std::move(snapshot));
}

}  // namespace carom::ui
