#pragma once
// The sandbox window: the 3D view in the centre, the simulation controls on a toolbar, the
// numbers in the status bar. It observes the simulation through snapshots and never waits on it.

#include "sim/measure/run_watch.h"
#include "sim/model/scene.h"
#include "ui/editor/object_ref.h"

#include <QMainWindow>
#include <QString>

#include <memory>

class QAction;
class QDockWidget;

namespace carom::editor {
class SceneDocument;
class EditorTools;
class OutlineDock;
class PropertiesDock;
}  // namespace carom::editor
namespace carom::ui {

class AccuracyWindow;
class BallStoryDock;
class EditActions;
class ImageExport;
class SceneFiles;
class RunControls;
class VideoExport;
class StatusReadout;
class TimelineBar;
class GrabControl;
class WatchAlert;
class WorldToolBar;
class SoundThread;
struct SimulationSnapshot;
class EnergyPlot;
class RunSession;
class SimulationSync;
}  // namespace carom::ui
namespace carom::render {
class SceneView;
}
namespace carom::ui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Shows `scene` (valid) from its start, paused, as the document read from `fileName` (empty
  // for a new scene; `title` then names it in the title bar and in Save As). Discards unsaved
  // changes.
  void openScene(const carom::Scene& scene, const QString& fileName, const QString& title = {});
  // Open, asking first about unsaved changes when `askToSave`; a broken file gets a dialog with
  // the loader's message and leaves the open scene as it was.
  bool openFile(const QString& fileName, bool askToSave);
  // A bundled example by its file's base name ("magic-room"), titled in the program's language
  // ("Magic room"); false when there is none or the user cancels the question about saving.
  bool openExample(const QString& file, bool askToSave);
  bool save();
  bool saveAs();
  editor::SceneDocument* document() const { return document_; }
  // At start: offers the scenes that sessions which did not end cleanly left unsaved, newest
  // first, to recover, discard or keep for later; the first one recovered opens as an unsaved
  // scene. Returns whether one did.
  bool offerRecovery();
  editor::OutlineDock* outlineDock() const { return outlineDock_; }
  editor::PropertiesDock* propertiesDock() const { return propertiesDock_; }
  void showMessage(const QString& message);

  RunSession& simulation() { return *simulation_; }
  // As the Run/Pause control does.
  void setRunning(bool running);
  QWidget* view() const;
  SoundThread& sound() { return *sound_; }
  // Opens the Speed vs accuracy window on the current scene and settings, and starts it.
  AccuracyWindow* openAccuracyWindow(double duration = 5.0);

 signals:
  // The run watch paused the run on `event`, which the window has shown. `event.lastGoodTime`
  // is the last step the watch passed: the moment a timeline should offer to go back to.
  void watchStopped(const carom::WatchEvent& event);

 protected:
  void changeEvent(QEvent* event) override;
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  // The window's own texts: its title, the Follow action and the energy dock's title. Its menus,
  // toolbars and docks retranslate themselves.
  void retranslate();
  void buildBars(ImageExport* imageExport, VideoExport* videoExport, EditActions* editActions,
                 QDockWidget* historyDock);
  void showSelection();
  void updateTitle();
  int followTarget() const;
  void useCurrentState();
  void showSnapshot(std::shared_ptr<const SimulationSnapshot> snapshot);
  void applySettings(carom::Method method, carom::Integrator integrator, double timeStep);

  std::unique_ptr<RunSession> simulation_;  // the live run: its starts, snapshots and controls
  render::SceneView* view_ = nullptr;
  EnergyPlot* energyPlot_ = nullptr;
  BallStoryDock* storyDock_ = nullptr;  // the selected balls' plot, trails and arrows
  SoundThread* sound_ = nullptr;
  editor::SceneDocument* document_ = nullptr;
  SceneFiles* files_ = nullptr;  // New, Open, Save, the recent files, the examples
  editor::EditorTools* tools_ = nullptr;
  SimulationSync* sync_ = nullptr;  // keeps the simulation in step with the document
  QDockWidget* energyDock_ = nullptr;
  editor::OutlineDock* outlineDock_ = nullptr;
  editor::PropertiesDock* propertiesDock_ = nullptr;
  static constexpr int kMessageMilliseconds = 8000;
  static constexpr int kDockWidth = 330;
  RunControls* runControls_ = nullptr;  // Run/Pause, Step, Reset, the speed
  QAction* followAction_ = nullptr;
  WorldToolBar* worldBar_ = nullptr;  // gravity, time step, method (auto), integrator
  StatusReadout* status_ = nullptr;
  TimelineBar* timeline_ = nullptr;
  GrabControl* grab_ = nullptr;
  WatchAlert* watchAlert_ = nullptr;
};

}  // namespace carom::ui
