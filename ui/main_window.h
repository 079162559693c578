#pragma once
// The sandbox window: the 3D view in the centre, the simulation controls on a toolbar, the
// numbers in the status bar. It observes the simulation through snapshots and never waits on it.

#include "scene.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>

#include <memory>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace carom::ui {

class AccuracyWindow;
struct SimulationSnapshot;
class EnergyPlot;
class SimulationController;
}  // namespace carom::ui
namespace carom {
class SoundBoard;
}
namespace carom::render {
class SceneView;
}
namespace carom::ui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Shows `scene` (valid) from its start, paused; `title` names it in the window title.
  void openScene(const carom::Scene& scene, const QString& title);

  SimulationController& simulation() { return *simulation_; }
  // As the Run/Pause control does.
  void setRunning(bool running);
  QWidget* view() const;
  EnergyPlot* energyPlot() const { return energyPlot_; }
  SoundBoard& sound() { return *sound_; }
  QString statusText() const;
  // Opens the Speed vs accuracy window on the current scene and settings, and starts it.
  AccuracyWindow* openAccuracyWindow(double duration = 5.0);
  // Frames drawn and snapshots shown so far (for the status line and tests).
  int framesRendered() const { return framesRendered_; }

 private:
  void buildActions();
  void buildToolBar();
  void buildMenus();
  void showSnapshot();
  void showStatus();
  void changeTimeStep(double factor);
  void applyGravity();
  void applySettings(carom::Method method, carom::Integrator integrator, double timeStep);

  std::unique_ptr<SimulationController> simulation_;
  render::SceneView* view_ = nullptr;
  EnergyPlot* energyPlot_ = nullptr;
  SoundBoard* sound_ = nullptr;
  QAction* muteAction_ = nullptr;
  QAction* explosionsAction_ = nullptr;
  QAction* antialiasingAction_ = nullptr;
  static constexpr const char* kAntialiasingKey = "view/antialiasing";
  carom::Scene scene_;
  QAction* playAction_ = nullptr;
  QAction* stepAction_ = nullptr;
  QAction* resetAction_ = nullptr;
  QAction* fullScreenAction_ = nullptr;
  QAction* followAction_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QDoubleSpinBox* gravity_[3] = {};
  QDoubleSpinBox* timeStep_ = nullptr;
  QComboBox* method_ = nullptr;
  QComboBox* integrator_ = nullptr;
  QLabel* status_ = nullptr;
  static constexpr int kStatusRefreshMilliseconds = 200;
  QTimer statusTimer_;
  std::shared_ptr<const SimulationSnapshot> latestSnapshot_;
  int framesRendered_ = 0;
  int framesAtLastSample_ = 0;
  QElapsedTimer fpsClock_;
  double framesPerSecond_ = 0.0;
  double lastCollisionTime_ = 0.0;
  std::uint64_t lastCollisionCount_ = 0;
  double collisionsPerSecond_ = 0.0;
};

}  // namespace carom::ui
