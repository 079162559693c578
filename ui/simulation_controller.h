#pragma once
// The GUI's handle on the simulation: owns the worker thread and forwards every request to the
// worker as a queued call, so nothing here ever waits on the physics.

#include "scene.h"
#include "simulation_snapshot.h"

#include <QObject>
#include <QThread>

namespace carom::ui {

class SimulationWorker;

class SimulationController : public QObject {
  Q_OBJECT
 public:
  explicit SimulationController(QObject* parent = nullptr);
  ~SimulationController() override;

  void loadScene(const carom::Scene& scene);
  void setRunning(bool running);
  void stepOnce();
  void reset();
  void setSpeed(double factor);
  void setGravity(const carom::Vec3& gravity);
  void setTimeStep(double seconds);
  void setMethod(carom::Method method);
  void setIntegrator(carom::Integrator integrator);
  void stallNextBatch(double seconds);  // test hook

  // The most recent snapshot, or null before the first; never blocks.
  std::shared_ptr<const SimulationSnapshot> latest() const { return exchange_.latest(); }
  // The same, marking it shown: the worker announces the next one.
  std::shared_ptr<const SimulationSnapshot> take() { return exchange_.take(); }

 signals:
  void snapshotPublished();

 private:
  template <typename Call>
  void post(Call&& call);

  SnapshotExchange exchange_;
  QThread thread_;
  SimulationWorker* worker_;
};

}  // namespace carom::ui
