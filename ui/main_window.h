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
class QLabel;
class QMenu;
class QMessageBox;
class QToolBar;

namespace carom::editor {
class SceneDocument;
class EditorTools;
class OutlineDock;
class PropertiesDock;
class SceneRecovery;
}  // namespace carom::editor
namespace carom::ui {

class AccuracyWindow;
class BallStoryDock;
class ImageExport;
class VideoExport;
class EditActions;
class SceneFiles;
class NumberBox;
class StatusReadout;
class TimelineBar;
class GrabControl;
class WatchAlert;
class WatchMenu;
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
  editor::SceneRecovery* recovery() const { return recovery_; }
  // At start: offers the scenes that sessions which did not end cleanly left unsaved, newest
  // first, to recover, discard or keep for later; the first one recovered opens as an unsaved
  // scene. Returns whether one did.
  bool offerRecovery();
  editor::EditorTools* tools() const { return tools_; }
  editor::OutlineDock* outlineDock() const { return outlineDock_; }
  editor::PropertiesDock* propertiesDock() const { return propertiesDock_; }
  // The status bar's passing message (refusals, saves), as opposed to the status line.
  QString statusMessage() const;
  void showMessage(const QString& message);

  RunSession& simulation() { return *simulation_; }
  // As the Run/Pause control does.
  void setRunning(bool running);
  QWidget* view() const;
  EnergyPlot* energyPlot() const { return energyPlot_; }
  BallStoryDock* ballStoryDock() const { return storyDock_; }
  ImageExport* imageExport() const { return imageExport_; }
  VideoExport* videoExport() const { return videoExport_; }
  SoundThread& sound() { return *sound_; }
  QString statusText() const;
  // Opens the Speed vs accuracy window on the current scene and settings, and starts it.
  AccuracyWindow* openAccuracyWindow(double duration = 5.0);
  // Frames drawn and snapshots shown so far (for the status line and tests).
  int framesRendered() const;
  // Simulation > Watch, and the dialog of the last event the watch stopped the run on while it
  // is open.
  WatchMenu* watchMenu() const { return watchMenu_; }
  QMessageBox* watchDialog() const;

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
  // Every text of the window, its menus, actions and toolbars in the current language.
  void retranslate();
  void showUndoTexts();
  void chooseLanguage(const QString& code);
  void buildActions();
  void buildFileActions();
  void buildEditActions();
  void buildToolActions();
  void showSelection();
  void fillRecentMenu();
  void updateTitle();
  int followTarget() const;
  void useCurrentState();
  void buildToolBar();
  void buildMenus();
  void buildHelpMenu();
  void showSnapshot(std::shared_ptr<const SimulationSnapshot> snapshot);
  void changeTimeStep(double factor);
  void applySettings(carom::Method method, carom::Integrator integrator, double timeStep);

  std::unique_ptr<RunSession> simulation_;  // the live run: its starts, snapshots and controls
  render::SceneView* view_ = nullptr;
  EnergyPlot* energyPlot_ = nullptr;
  BallStoryDock* storyDock_ = nullptr;  // the selected balls' plot, trails and arrows
  ImageExport* imageExport_ = nullptr;  // File > Export Image
  VideoExport* videoExport_ = nullptr;  // File > Export Video
  QAction* exportImageAction_ = nullptr;
  QAction* exportVideoAction_ = nullptr;
  SoundThread* sound_ = nullptr;
  QAction* muteAction_ = nullptr;
  QAction* explosionsAction_ = nullptr;
  QAction* antialiasingAction_ = nullptr;
  QAction* largerStepAction_ = nullptr;
  QAction* smallerStepAction_ = nullptr;
  static constexpr const char* kAntialiasingKey = "view/antialiasing";
  editor::SceneDocument* document_ = nullptr;
  SceneFiles* files_ = nullptr;         // New, Open, Save, the recent files, the examples
  EditActions* editActions_ = nullptr;  // copy, paste, duplicate, delete, select all
  editor::EditorTools* tools_ = nullptr;
  QAction* toolActions_[5] = {};  // in EditorTools::Tool order
  QAction* snapAction_ = nullptr;
  SimulationSync* sync_ = nullptr;  // keeps the simulation in step with the document
  QAction* newAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QAction* saveAction_ = nullptr;
  QAction* saveAsAction_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QAction* quitAction_ = nullptr;
  QMenu* fileMenu_ = nullptr;
  QMenu* editMenu_ = nullptr;
  QMenu* simulationMenu_ = nullptr;
  QAction* accuracyAction_ = nullptr;
  QMenu* examplesMenu_ = nullptr;
  QMenu* toolsMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* languageMenu_ = nullptr;
  QAction* systemLanguageAction_ = nullptr;
  QMenu* helpMenu_ = nullptr;
  QAction* keyboardHelpAction_ = nullptr;
  QAction* userGuideAction_ = nullptr;
  QAction* aboutAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* copyAction_ = nullptr;
  QAction* pasteAction_ = nullptr;
  QAction* duplicateAction_ = nullptr;
  QAction* deleteAction_ = nullptr;
  QAction* selectAllAction_ = nullptr;
  QAction* useStateAction_ = nullptr;
  QAction* applyToRunningAction_ = nullptr;
  QDockWidget* historyDock_ = nullptr;
  QDockWidget* energyDock_ = nullptr;
  editor::OutlineDock* outlineDock_ = nullptr;
  editor::PropertiesDock* propertiesDock_ = nullptr;
  editor::SceneRecovery* recovery_ = nullptr;
  static constexpr int kMessageMilliseconds = 8000;
  static constexpr int kDockWidth = 330;
  static constexpr const char* kApplyToRunningKey = "editing/applyToRunningState";
  QAction* playAction_ = nullptr;
  QAction* stepAction_ = nullptr;
  QAction* resetAction_ = nullptr;
  QAction* fullScreenAction_ = nullptr;
  QAction* frameAction_ = nullptr;
  QAction* followAction_ = nullptr;
  QToolBar* toolsBar_ = nullptr;
  QToolBar* simulationBar_ = nullptr;
  WorldToolBar* worldBar_ = nullptr;  // gravity, time step, method (auto), integrator
  QLabel* speedLabel_ = nullptr;
  NumberBox* speed_ = nullptr;
  StatusReadout* status_ = nullptr;
  TimelineBar* timeline_ = nullptr;
  GrabControl* grab_ = nullptr;
  QAction* throwLimitAction_ = nullptr;
  QAction* timelineMemoryAction_ = nullptr;
  WatchMenu* watchMenu_ = nullptr;
  WatchAlert* watchAlert_ = nullptr;
};

}  // namespace carom::ui
