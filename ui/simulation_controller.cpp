#include "ui/simulation_controller.h"

#include "ui/call_queue.h"
#include "ui/simulation_worker.h"
#include "ui/thread_handover.h"

namespace carom::ui {

SimulationController::SimulationController(QObject* parent)
    : QObject(parent),
      thread_(new QThread(this)),
      worker_(new SimulationWorker(exchange_)),
      calls_(new CallQueue(worker_)) {  // a child of the worker, so on its thread
  thread_->setObjectName("physics");
  worker_->moveToThread(thread_);
  connect(thread_, &QThread::finished, worker_, &QObject::deleteLater);
  // Emitted on the physics thread once its event loop has ended, before the worker is deleted
  // and before wait() returns.
  connect(
      thread_, &QThread::finished, thread_,
      [this] {
        takeOver(thread_);
        handOver(thread_);
      },
      Qt::DirectConnection);
  connect(worker_, &SimulationWorker::snapshotPublished, this,
          &SimulationController::snapshotPublished, Qt::QueuedConnection);
  thread_->start();
}

SimulationController::~SimulationController() {
  handOver(thread_);
  thread_->quit();
  thread_->wait();
  takeOver(thread_);
}

void SimulationController::post(std::function<void()> call) {
  calls_->post(std::move(call));
}

std::uint64_t SimulationController::loadScene(std::shared_ptr<const carom::Scene> scene) {
  const std::uint64_t number = ++loads_;
  post([worker = worker_, scene = std::move(scene), number] { worker->loadScene(*scene, number); });
  return number;
}
void SimulationController::setRunning(bool running) {
  post([worker = worker_, running] { worker->setRunning(running); });
}
void SimulationController::stepOnce() {
  post([worker = worker_] { worker->stepOnce(); });
}
void SimulationController::reset() {
  post([worker = worker_] { worker->reset(); });
}
void SimulationController::setSpeed(double factor) {
  post([worker = worker_, factor] { worker->setSpeed(factor); });
}
void SimulationController::setWorld(const carom::World& world) {
  post([worker = worker_, world] { worker->setWorld(world); });
}
void SimulationController::setWatchSettings(const carom::WatchSettings& settings) {
  post([worker = worker_, settings] { worker->setWatchSettings(settings); });
}

}  // namespace carom::ui
