#include "ui/run/simulation_controller.h"

#include "ui/run/call_queue.h"
#include "ui/run/simulation_worker.h"
#include "ui/run/thread_handover.h"

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

void SimulationController::loadScene(std::shared_ptr<const carom::Scene> scene,
                                     std::uint64_t number) {
  post([worker = worker_, scene = std::move(scene), number] { worker->loadScene(*scene, number); });
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

void SimulationController::showFrame(std::uint64_t frame) {
  // A slider dragged fast asks for frames faster than they can be reproduced: only the newest
  // request is served.
  if (pendingFrame_.exchange(frame) != kNoFrame) return;
  post([this] { worker_->showFrame(pendingFrame_.exchange(kNoFrame)); });
}
void SimulationController::setRecordingBudget(std::size_t bytes) {
  post([worker = worker_, bytes] { worker->setRecordingBudget(bytes); });
}
void SimulationController::exportVideo(std::shared_ptr<VideoFrameQueue> frames, double from,
                                       double to, int fps) {
  post([worker = worker_, frames = std::move(frames), from, to, fps]() mutable {
    worker->exportVideo(std::move(frames), from, to, fps);
  });
}
void SimulationController::grab(int ball) {
  post([worker = worker_, ball] { worker->grab(ball); });
}
void SimulationController::moveGrab(const carom::Vec3& target) {
  post([worker = worker_, target] { worker->moveGrab(target); });
}
void SimulationController::releaseGrab(const carom::Vec3& velocity) {
  post([worker = worker_, velocity] { worker->releaseGrab(velocity); });
}
void SimulationController::setThrowLimit(double speed) {
  post([worker = worker_, speed] { worker->setThrowLimit(speed); });
}

}  // namespace carom::ui
