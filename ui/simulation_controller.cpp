#include "simulation_controller.h"

#include "simulation_worker.h"

namespace carom::ui {

SimulationController::SimulationController(QObject* parent)
    : QObject(parent), worker_(new SimulationWorker(exchange_)) {
  thread_.setObjectName("physics");
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &SimulationWorker::snapshotPublished, this,
          &SimulationController::snapshotPublished, Qt::QueuedConnection);
  thread_.start();
}

SimulationController::~SimulationController() {
  thread_.quit();
  thread_.wait();
}

template <typename Call>
void SimulationController::post(Call&& call) {
  QMetaObject::invokeMethod(worker_, std::forward<Call>(call), Qt::QueuedConnection);
}

void SimulationController::loadScene(const carom::Scene& scene) {
  post([worker = worker_, scene] { worker->loadScene(scene); });
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
void SimulationController::setGravity(const carom::Vec3& gravity) {
  post([worker = worker_, gravity] { worker->setGravity(gravity); });
}
void SimulationController::setTimeStep(double seconds) {
  post([worker = worker_, seconds] { worker->setTimeStep(seconds); });
}
void SimulationController::setMethod(carom::Method method) {
  post([worker = worker_, method] { worker->setMethod(method); });
}
void SimulationController::setIntegrator(carom::Integrator integrator) {
  post([worker = worker_, integrator] { worker->setIntegrator(integrator); });
}
void SimulationController::stallNextBatch(double seconds) {
  post([worker = worker_, seconds] { worker->stallNextBatch(seconds); });
}

}  // namespace carom::ui
