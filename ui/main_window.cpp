#include "ui/main_window.h"

#include "ui/dialogs/accuracy_window.h"
#include "ui/dialogs/help_dialogs.h"
#include "ui/dialogs/image_export.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/docks/energy_plot.h"
#include "ui/edit_actions.h"
#include "ui/editor/cylinder_length_field.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/number_text.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/running_state.h"
#include "ui/grab_control.h"
#include "ui/language.h"
#include "ui/number_box.h"
#include "ui/scene_files.h"

#include "sim/model/validation.h"
#include "ui/dialogs/video_export.h"
#include "ui/editor/scene_document.h"
#include "ui/editor/scene_recovery.h"
#include "ui/render/render_scene.h"
#include "ui/render/scene_view.h"
#include "ui/run/run_session.h"
#include "ui/simulation_sync.h"
#include "ui/sound_thread.h"
#include "ui/status_readout.h"
#include "ui/timeline_bar.h"
#include "ui/watch_alert.h"
#include "ui/watch_menu.h"
#include "ui/world_tool_bar.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>
#include <QUrl>
#include <QVBoxLayout>

namespace carom::ui {

using render::SceneView;

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      simulation_(std::make_unique<RunSession>()),
      document_(new editor::SceneDocument(this)) {
  setAcceptDrops(true);
  view_ = new SceneView;
  timeline_ = new TimelineBar;
  auto* centre = new QWidget;
  auto* centreLayout = new QVBoxLayout(centre);
  centreLayout->setContentsMargins(0, 0, 0, 0);
  centreLayout->setSpacing(0);
  centreLayout->addWidget(view_, 1);
  centreLayout->addWidget(timeline_);
  setCentralWidget(centre);
  connect(timeline_, &TimelineBar::frameRequested, this, [this](std::uint64_t frame) {
    playAction_->setChecked(false);
    simulation_->controls().showFrame(frame);
  });
  connect(timeline_, &TimelineBar::memoryBudgetChanged, &simulation_->controls(),
          &SimulationController::setRecordingBudget);
  sync_ = new SimulationSync(document_, simulation_.get(), this);
  connect(simulation_.get(), &RunSession::restarted, this,
          [this](std::uint64_t, std::shared_ptr<const Scene> start) {
            view_->setScene(
                std::make_shared<const render::RenderScene>(render::makeRenderScene(*start)));
            // Another scene or an edit: the plot, the story and the rates of the run before are
            // not this one's.
            energyPlot_->clear();
            storyDock_->restart();
            status_->restart();
            showSelection();
          });
  connect(sync_, &SimulationSync::message, this, &MainWindow::showMessage);
  energyPlot_ = new EnergyPlot;
  energyDock_ = new QDockWidget(this);
  energyDock_->setObjectName("energyDock");
  energyDock_->setWidget(energyPlot_);
  // Below the view, where the plot's time axis has room.
  addDockWidget(Qt::BottomDockWidgetArea, energyDock_);
  energyPlot_->setMinimumHeight(170);
  storyDock_ = new BallStoryDock(document_, view_, this);
  addDockWidget(Qt::BottomDockWidgetArea, storyDock_);
  tabifyDockWidget(energyDock_, storyDock_);
  energyDock_->raise();
  imageExport_ = new ImageExport(view_, this, this);
  connect(imageExport_, &ImageExport::message, this, &MainWindow::showMessage);
  videoExport_ = new VideoExport(view_, simulation_.get(), this, this);
  connect(videoExport_, &VideoExport::message, this, &MainWindow::showMessage);
  // The frames come from the recording, which a running simulation would go on extending.
  connect(videoExport_, &VideoExport::pauseRequested, this,
          [this] { playAction_->setChecked(false); });
  sound_ = new SoundThread(this);
  status_ = new StatusReadout(sound_);
  // Permanent: passing messages (saves, refusals) show beside the readout, not over it.
  statusBar()->addPermanentWidget(status_);
  tools_ = new editor::EditorTools(document_, view_, this);
  connect(tools_, &editor::EditorTools::refused, this, &MainWindow::showMessage);
  grab_ = new GrabControl(tools_, simulation_.get(), this);
  connect(grab_, &GrabControl::message, this, &MainWindow::showMessage);
  watchAlert_ = new WatchAlert(document_, view_, &simulation_->controls(), this);
  // The worker has paused; the control follows.
  connect(watchAlert_, &WatchAlert::stopped, this, [this] { playAction_->setChecked(false); });
  connect(watchAlert_, &WatchAlert::stopped, this, &MainWindow::watchStopped);
  outlineDock_ = new editor::OutlineDock(document_, this);
  addDockWidget(Qt::RightDockWidgetArea, outlineDock_);
  connect(outlineDock_->model(), &editor::OutlineModel::refused, this, &MainWindow::showMessage);
  propertiesDock_ = new editor::PropertiesDock(document_, this);
  addDockWidget(Qt::RightDockWidgetArea, propertiesDock_);
  connect(propertiesDock_, &editor::PropertiesDock::refused, this, &MainWindow::showMessage);
  recovery_ = new editor::SceneRecovery(document_, this);
  connect(recovery_, &editor::SceneRecovery::autosaveFailed, this, [this](const QString& reason) {
    showMessage(tr("The recovery copy could not be written (%1); the last one is kept. Save "
                   "the scene elsewhere to be safe.")
                    .arg(reason));
  });
  files_ = new SceneFiles(document_, this, this);
  connect(files_, &SceneFiles::message, this, &MainWindow::showMessage);
  connect(files_, &SceneFiles::sceneAboutToOpen, this, [this] { playAction_->setChecked(false); });
  connect(files_, &SceneFiles::sceneOpened, this, [this] { view_->frameScene(); });
  // Pasted and duplicated balls move to the right of the screen, as the camera looks.
  editActions_ = new EditActions(
      document_,
      [this] {
        const QVector3D right =
            QVector3D::crossProduct(view_->camera().eye() - view_->camera().target(),
                                    QVector3D(0, 1, 0))
                .normalized();
        return Vec3(-right.x(), -right.y(), -right.z());
      },
      this);
  connect(editActions_, &EditActions::message, this, &MainWindow::showMessage);
  buildActions();
  buildFileActions();
  buildEditActions();
  buildToolActions();
  buildToolBar();
  simulation_->controls().setSpeed(speed_->value());
  simulation_->controls().setRecordingBudget(TimelineBar::memoryBudget());
  buildMenus();
  connect(document_, &editor::SceneDocument::sceneChanged, this,
          [this](const editor::SceneChange& change) {
            if (change.world) worldBar_->showWorld();
          });
  connect(document_, &editor::SceneDocument::displayNameChanged, this, &MainWindow::updateTitle);
  connect(document_, &editor::SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &editor::SceneDocument::selectionChanged, this, [this] {
    if (followAction_->isChecked()) view_->setFollowedBall(followTarget());
    showSelection();
  });
  connect(simulation_.get(), &RunSession::snapshotReady, this, &MainWindow::showSnapshot);
  connect(view_, &SceneView::frameRendered, status_, &StatusReadout::countFrame);
  retranslate();
  resize(1280, 800);
  // The docks share a column, as wide as the properties' vector rows need in this language.
  resizeDocks({outlineDock_}, {std::max(kDockWidth, propertiesDock_->sizeHint().width())},
              Qt::Horizontal);
}

MainWindow::~MainWindow() {
  // First, so that a start being made from the document is finished while all is whole, and
  // restarts nothing of this window from here on.
  delete sync_;
  // Closing the window moves the focus, which commits a value being typed in a dock: the
  // document takes it, but this half-destroyed window must no longer hear of it. Nor of the
  // undo stack, which announces its texts as it clears itself on the way out.
  document_->disconnect(this);
  document_->undoStack()->disconnect(this);
}

QWidget* MainWindow::view() const {
  return view_;
}

QString MainWindow::statusText() const {
  return status_->text();
}

QMessageBox* MainWindow::watchDialog() const {
  return watchAlert_->dialog();
}

int MainWindow::framesRendered() const {
  return status_->framesRendered();
}

void MainWindow::buildActions() {
  playAction_ = new QAction(this);
  playAction_->setObjectName("run");
  playAction_->setCheckable(true);
  playAction_->setShortcut(Qt::Key_Space);
  connect(playAction_, &QAction::toggled, this, [this](bool on) {
    playAction_->setText(on ? tr("&Pause") : tr("&Run"));
    simulation_->controls().setRunning(on);
  });

  stepAction_ = new QAction(this);
  stepAction_->setShortcut(Qt::Key_S);
  connect(stepAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->controls().stepOnce();
  });

  resetAction_ = new QAction(this);
  resetAction_->setShortcut(Qt::Key_R);
  connect(resetAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->controls().reset();
  });

  fullScreenAction_ = new QAction(this);
  fullScreenAction_->setShortcuts({Qt::Key_F11, Qt::Key_F1});
  fullScreenAction_->setCheckable(true);
  connect(fullScreenAction_, &QAction::toggled, this,
          [this](bool on) { on ? showFullScreen() : showNormal(); });

  // The view's keys are the window's: they work wherever the focus is, except in a text field
  // being edited (which takes its own keys first).
  frameAction_ = new QAction(this);
  frameAction_->setObjectName("frameScene");
  frameAction_->setShortcut(Qt::Key_Home);
  connect(frameAction_, &QAction::triggered, this, [this] { view_->frameScene(); });

  followAction_ = new QAction(this);
  followAction_->setShortcut(Qt::Key_F2);
  followAction_->setCheckable(true);
  connect(followAction_, &QAction::toggled, this,
          [this](bool on) { view_->setFollowedBall(on ? followTarget() : -1); });

  explosionsAction_ = new QAction(this);
  explosionsAction_->setCheckable(true);
  explosionsAction_->setChecked(true);
  connect(explosionsAction_, &QAction::toggled, this,
          [this](bool on) { view_->setExplosionsEnabled(on); });

  // Remembered once chosen; until then the view decides by its renderer.
  antialiasingAction_ = new QAction(this);
  antialiasingAction_->setCheckable(true);
  QSettings settings;
  if (settings.contains(kAntialiasingKey))
    view_->setAntialiasing(settings.value(kAntialiasingKey).toBool());
  antialiasingAction_->setChecked(view_->antialiasing());
  connect(antialiasingAction_, &QAction::triggered, this, [this](bool on) {
    QSettings().setValue(kAntialiasingKey, on);
    view_->setAntialiasing(on);
  });
  connect(view_, &SceneView::antialiasingChanged, antialiasingAction_, &QAction::setChecked);

  muteAction_ = new QAction(this);
  muteAction_->setShortcut(Qt::Key_F3);
  muteAction_->setCheckable(true);
  connect(muteAction_, &QAction::toggled, this, [this](bool on) { sound_->setMuted(on); });

  largerStepAction_ = new QAction(this);
  largerStepAction_->setShortcuts({Qt::Key_Plus, Qt::Key_Equal});
  connect(largerStepAction_, &QAction::triggered, this, [this] { changeTimeStep(1.25); });
  smallerStepAction_ = new QAction(this);
  smallerStepAction_->setShortcut(Qt::Key_Minus);
  connect(smallerStepAction_, &QAction::triggered, this, [this] { changeTimeStep(1.0 / 1.25); });
  addActions({largerStepAction_, smallerStepAction_});
}

void MainWindow::buildToolBar() {
  // Two rows, so that every control stays visible at 1280 pixels in the longer languages: the
  // tools and the run controls, then the world's settings.
  simulationBar_ = addToolBar(QString());
  simulationBar_->setObjectName("simulation");
  simulationBar_->addAction(playAction_);
  simulationBar_->addAction(stepAction_);
  simulationBar_->addAction(resetAction_);
  simulationBar_->addSeparator();

  speedLabel_ = new QLabel;
  simulationBar_->addWidget(speedLabel_);
  speed_ = new NumberBox(QString(), 0.01, 100.0, 0.25);  // named in retranslate()
  speed_->setObjectName("speed");
  speed_->setValue(1.0);
  connect(speed_, &NumberBox::refused, this, &MainWindow::showMessage);
  connect(speed_, &QDoubleSpinBox::valueChanged, this,
          [this](double value) { simulation_->controls().setSpeed(value); });
  simulationBar_->addWidget(speed_);

  addToolBarBreak();
  worldBar_ = new WorldToolBar(document_, this);
  addToolBar(worldBar_);
  connect(worldBar_, &WorldToolBar::message, this, &MainWindow::showMessage);
}

void MainWindow::buildMenus() {
  fileMenu_ = menuBar()->addMenu(QString());
  fileMenu_->addActions({newAction_, openAction_});
  recentMenu_ = fileMenu_->addMenu(QString());
  recentMenu_->setObjectName("recentMenu");
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
  fileMenu_->addActions({saveAction_, saveAsAction_});
  fileMenu_->addSeparator();
  fileMenu_->addActions({exportImageAction_, exportVideoAction_});
  fileMenu_->addSeparator();
  quitAction_ = fileMenu_->addAction(QString(), QKeySequence::Quit, this, &QWidget::close);

  editMenu_ = menuBar()->addMenu(QString());
  editMenu_->addActions({undoAction_, redoAction_});
  editMenu_->addSeparator();
  editMenu_->addActions({copyAction_, pasteAction_, duplicateAction_, deleteAction_});
  editMenu_->addSeparator();
  editMenu_->addActions({selectAllAction_});

  // The same actions as the toolbar's.
  toolsMenu_ = menuBar()->addMenu(QString());
  toolsMenu_->setObjectName("toolsMenu");
  for (QAction* action : toolActions_) toolsMenu_->addAction(action);
  toolsMenu_->addSeparator();
  toolsMenu_->addAction(snapAction_);

  simulationMenu_ = menuBar()->addMenu(QString());
  simulationMenu_->addActions({playAction_, stepAction_, resetAction_});
  simulationMenu_->addSeparator();
  accuracyAction_ = simulationMenu_->addAction(QString(), this, [this] { openAccuracyWindow(); });
  watchMenu_ = new WatchMenu(this);
  simulationMenu_->addMenu(watchMenu_);
  connect(watchMenu_, &WatchMenu::settingsChanged, &simulation_->controls(),
          &SimulationController::setWatchSettings);
  simulation_->controls().setWatchSettings(watchMenu_->settings());
  simulationMenu_->addSeparator();
  simulationMenu_->addActions({useStateAction_, applyToRunningAction_});
  simulationMenu_->addSeparator();
  throwLimitAction_ =
      simulationMenu_->addAction(QString(), this, [this] { grab_->askThrowLimit(this); });
  throwLimitAction_->setObjectName("throwLimit");
  timelineMemoryAction_ =
      simulationMenu_->addAction(QString(), timeline_, &TimelineBar::askMemoryBudget);
  timelineMemoryAction_->setObjectName("timelineMemory");

  examplesMenu_ = menuBar()->addMenu(QString());
  examplesMenu_->setObjectName("examplesMenu");
  for (const QString& file : SceneFiles::exampleFiles()) {
    QAction* action =
        examplesMenu_->addAction(QString(), this, [this, file] { openExample(file, true); });
    action->setObjectName(QString("example:%1").arg(file));
  }

  viewMenu_ = menuBar()->addMenu(QString());
  viewMenu_->addActions({frameAction_, followAction_, fullScreenAction_, explosionsAction_,
                         antialiasingAction_, muteAction_});
  viewMenu_->addSeparator();
  viewMenu_->addAction(energyDock_->toggleViewAction());
  viewMenu_->addAction(storyDock_->toggleViewAction());
  viewMenu_->addAction(outlineDock_->toggleViewAction());
  viewMenu_->addAction(propertiesDock_->toggleViewAction());
  viewMenu_->addAction(historyDock_->toggleViewAction());
  viewMenu_->addSeparator();
  languageMenu_ = viewMenu_->addMenu(QString());
  auto* languages = new QActionGroup(this);
  const QString current = chosenLanguage(QCoreApplication::arguments());
  for (const Language& language : availableLanguages()) {
    QAction* action = languageMenu_->addAction(language.nativeName);
    action->setObjectName("language:" + language.code);
    action->setCheckable(true);
    action->setChecked(language.code == current);
    languages->addAction(action);
    if (language.code.isEmpty()) systemLanguageAction_ = action;
    connect(action, &QAction::triggered, this,
            [this, code = language.code] { chooseLanguage(code); });
  }

  buildHelpMenu();
}

void MainWindow::buildHelpMenu() {
  helpMenu_ = menuBar()->addMenu(QString());
  helpMenu_->setObjectName("helpMenu");
  // One window a page, shown again when asked again.
  const auto show = [this](HelpWindow::Page page) {
    HelpWindow* window = nullptr;
    for (HelpWindow* open : findChildren<HelpWindow*>())
      if (open->page() == page) window = open;
    if (!window) window = new HelpWindow(page, this);
    window->show();
    window->raise();
  };
  keyboardHelpAction_ =
      helpMenu_->addAction(QString(), this, [show] { show(HelpWindow::Page::KeyboardAndMouse); });
  keyboardHelpAction_->setObjectName("keyboardHelp");
  userGuideAction_ =
      helpMenu_->addAction(QString(), this, [show] { show(HelpWindow::Page::UserGuide); });
  userGuideAction_->setObjectName("userGuide");
  helpMenu_->addSeparator();
  aboutAction_ = helpMenu_->addAction(QString(), this, [this] { showAbout(this); });
  aboutAction_->setObjectName("about");
}

void MainWindow::chooseLanguage(const QString& code) {
  saveLanguageChoice(code);
  // Every widget hears of it through a LanguageChange event, and retranslates itself.
  installTranslation(*QCoreApplication::instance(), code);
}

void MainWindow::showUndoTexts() {
  const QUndoStack* stack = document_->undoStack();
  undoAction_->setText(stack->undoText().isEmpty() ? tr("&Undo")
                                                   : tr("&Undo %1").arg(stack->undoText()));
  redoAction_->setText(stack->redoText().isEmpty() ? tr("&Redo")
                                                   : tr("&Redo %1").arg(stack->redoText()));
}

void MainWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
  fileMenu_->setTitle(tr("&File"));
  newAction_->setText(tr("&New"));
  openAction_->setText(tr("&Open…"));
  recentMenu_->setTitle(tr("Open &Recent"));
  saveAction_->setText(tr("&Save"));
  saveAsAction_->setText(tr("Save &As…"));
  exportImageAction_->setText(tr("Export &Image…"));
  exportVideoAction_->setText(tr("Export &Video…"));
  quitAction_->setText(tr("&Quit"));

  editMenu_->setTitle(tr("&Edit"));
  showUndoTexts();
  copyAction_->setText(tr("&Copy"));
  pasteAction_->setText(tr("&Paste"));
  duplicateAction_->setText(tr("&Duplicate"));
  deleteAction_->setText(tr("De&lete"));
  selectAllAction_->setText(tr("Select &All"));
  historyDock_->setWindowTitle(tr("History"));
  // Qt's undo view names its empty state once, when it is made: a new one speaks the language.
  delete historyDock_->widget();
  historyDock_->setWidget(new QUndoView(document_->undoStack()));

  toolsMenu_->setTitle(tr("&Tools"));
  toolsBar_->setWindowTitle(tr("Tools"));
  const QString toolTexts[] = {tr("Select"), tr("Add Ball"), tr("Add Plane"), tr("Add Cylinder"),
                               tr("Add Box")};
  for (int i = 0; i < int(std::size(toolTexts)); ++i) {
    toolActions_[i]->setText(toolTexts[i]);
    toolActions_[i]->setToolTip(tr("%1 (%2)").arg(
        toolTexts[i], toolActions_[i]->shortcut().toString(QKeySequence::NativeText)));
  }
  snapAction_->setText(tr("Snap to &Grid"));
  snapAction_->setToolTip(tr("Moves land on multiples of %1 m")
                              .arg(editor::formatNumber(editor::EditorTools::gridStep())));

  simulationMenu_->setTitle(tr("&Simulation"));
  playAction_->setText(playAction_->isChecked() ? tr("&Pause") : tr("&Run"));
  playAction_->setToolTip(tr("Run or pause the simulation (Space)"));
  stepAction_->setText(tr("&Step"));
  stepAction_->setToolTip(tr("Advance one time step (S)"));
  resetAction_->setText(tr("R&eset"));
  resetAction_->setToolTip(tr("Back to the scene's initial state (R)"));
  largerStepAction_->setText(tr("Larger Time Step"));
  smallerStepAction_->setText(tr("Smaller Time Step"));
  accuracyAction_->setText(tr("Speed vs &Accuracy…"));
  throwLimitAction_->setText(tr("&Throw Speed Limit…"));
  timelineMemoryAction_->setText(tr("Timeline &Memory…"));
  useStateAction_->setText(tr("&Use Current State as Initial"));
  applyToRunningAction_->setText(tr("Edits Apply to the &Running State"));
  applyToRunningAction_->setToolTip(
      tr("Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves "
         "alone keep their running state."));

  simulationBar_->setWindowTitle(tr("Simulation"));
  speedLabel_->setText(tr("Speed"));
  speed_->setName(tr("Speed"));
  speed_->setToolTip(tr("Simulated seconds per real second"));
  {
    const QSignalBlocker blocker(speed_);  // shown in the language's number format
    speed_->setValue(speed_->value());
  }
  worldBar_->retranslate();

  examplesMenu_->setTitle(tr("&Examples"));
  const QList<QAction*> examples = examplesMenu_->actions();
  for (int i = 0; i < int(examples.size()); ++i) examples[i]->setText(SceneFiles::exampleTitle(i));
  files_->retranslate();

  viewMenu_->setTitle(tr("&View"));
  frameAction_->setText(tr("F&rame Scene"));
  followAction_->setText(tr("&Follow Ball"));
  fullScreenAction_->setText(tr("&Full Screen"));
  explosionsAction_->setText(tr("&Explosions"));
  antialiasingAction_->setText(tr("&Antialiasing"));
  muteAction_->setText(tr("&Mute"));
  energyDock_->setWindowTitle(tr("Energy"));
  languageMenu_->setTitle(tr("&Language"));
  systemLanguageAction_->setText(availableLanguages().front().nativeName);

  helpMenu_->setTitle(tr("&Help"));
  keyboardHelpAction_->setText(tr("&Keyboard and Mouse"));
  userGuideAction_->setText(tr("&User Guide"));
  aboutAction_->setText(tr("&About Carom"));

  updateTitle();
}

void MainWindow::openScene(const carom::Scene& scene, const QString& fileName,
                           const QString& title) {
  files_->openScene(scene, fileName, title);
}

void MainWindow::showSelection() {
  std::vector<int> indices[editor::kObjectKindCount];
  for (const editor::ObjectRef& ref : document_->selection())
    indices[int(ref.kind)].push_back(ref.index);
  view_->setHighlighted(
      indices[int(editor::ObjectKind::Ball)], indices[int(editor::ObjectKind::Plane)],
      indices[int(editor::ObjectKind::Cylinder)], indices[int(editor::ObjectKind::Box)]);
  std::vector<std::pair<Vec3, Vec3>> arrows;
  for (const editor::EditorTools::Handle& handle : tools_->handles())
    arrows.emplace_back(handle.base, handle.tip);
  view_->setHandleArrows(std::move(arrows));
}

void MainWindow::showMessage(const QString& message) {
  statusBar()->showMessage(message, kMessageMilliseconds);
}

QString MainWindow::statusMessage() const {
  return statusBar()->currentMessage();
}

void MainWindow::buildToolActions() {
  auto* group = new QActionGroup(this);
  const struct {
    editor::EditorTools::Tool tool;
    const char* name;
    Qt::Key key;
  } tools[] = {{editor::EditorTools::Tool::Select, "toolSelect", Qt::Key_V},
               {editor::EditorTools::Tool::AddBall, "toolAddBall", Qt::Key_B},
               {editor::EditorTools::Tool::AddPlane, "toolAddPlane", Qt::Key_P},
               {editor::EditorTools::Tool::AddCylinder, "toolAddCylinder", Qt::Key_C},
               {editor::EditorTools::Tool::AddBox, "toolAddBox", Qt::Key_K}};
  toolsBar_ = addToolBar(QString());
  toolsBar_->setObjectName("tools");
  for (const auto& entry : tools) {
    QAction* action = group->addAction(QString());
    action->setObjectName(entry.name);
    action->setCheckable(true);
    action->setShortcut(entry.key);
    action->setChecked(entry.tool == tools_->tool());
    connect(action, &QAction::triggered, this,
            [this, tool = entry.tool] { tools_->setTool(tool); });
    toolsBar_->addAction(action);
    toolActions_[int(entry.tool)] = action;
  }
  // Add Cylinder's length, beside the tool while it is chosen.
  auto* cylinderLength = new editor::CylinderLengthField(tools_);
  connect(cylinderLength, &editor::CylinderLengthField::refused, this, &MainWindow::showMessage);
  QAction* cylinderLengthAction =
      toolsBar_->insertWidget(toolActions_[int(editor::EditorTools::Tool::AddBox)], cylinderLength);
  const auto showCylinderLength = [cylinderLengthAction](editor::EditorTools::Tool tool) {
    cylinderLengthAction->setVisible(tool == editor::EditorTools::Tool::AddCylinder);
  };
  showCylinderLength(tools_->tool());
  connect(tools_, &editor::EditorTools::toolChanged, cylinderLengthAction, showCylinderLength);
  snapAction_ = new QAction(this);
  snapAction_->setObjectName("snapToGrid");
  snapAction_->setCheckable(true);
  connect(snapAction_, &QAction::toggled, this, [this](bool on) { tools_->setSnapToGrid(on); });
  toolsBar_->addAction(snapAction_);
  addActions(group->actions());
}

void MainWindow::updateTitle() {
  setWindowTitle(tr("%1[*] — Carom").arg(document_->displayName()));
  setWindowModified(document_->isModified());
}

int MainWindow::followTarget() const {
  for (const editor::ObjectRef& ref : document_->selection())
    if (ref.kind == editor::ObjectKind::Ball) return ref.index;
  return document_->scene().balls.empty() ? -1 : 0;
}

void MainWindow::setRunning(bool running) {
  playAction_->setChecked(running);
}

AccuracyWindow* MainWindow::openAccuracyWindow(double duration) {
  auto* window = new AccuracyWindow(document_->scene(), this);
  window->setAttribute(Qt::WA_DeleteOnClose);
  window->setDuration(duration);
  window->setTolerance(worldBar_->autoTolerance());  // the accuracy auto aims at
  connect(window, &AccuracyWindow::settingsChosen, this, &MainWindow::applySettings);
  window->show();
  window->start();
  return window;
}

void MainWindow::applySettings(carom::Method method, carom::Integrator integrator,
                               double timeStep) {
  worldBar_->editWorld(tr("Apply Settings"), [=](World& world) {
    world.method = method;
    world.integrator = integrator;
    world.timeStep = timeStep;
    world.autoMethod.reset();  // a setting of one's own
  });
}

void MainWindow::changeTimeStep(double factor) {
  worldBar_->changeTimeStep(factor);
}

void MainWindow::showSnapshot(std::shared_ptr<const SimulationSnapshot> snapshot) {
  view_->setBallPositions(snapshot->positions);
  view_->addExplosions(snapshot->collisions);
  energyPlot_->add(*snapshot);
  // Looking back along the timeline shows the story then; the run going on from there records
  // again (and an earlier time truncates the story, as Reset does).
  if (snapshot->frame < snapshot->frameCount)
    storyDock_->showTime(snapshot->time);
  else
    storyDock_->add(snapshot);
  sound_->play(snapshot->collisions);
  timeline_->showSnapshot(*snapshot);
  grab_->showSnapshot(*snapshot);
  status_->showSnapshot(snapshot);
  watchAlert_->showSnapshot(*snapshot, followAction_->isChecked());
}

// ---- Files ---------------------------------------------------------------------------------

void MainWindow::buildFileActions() {
  newAction_ = new QAction(this);
  newAction_->setShortcut(QKeySequence::New);
  connect(newAction_, &QAction::triggered, files_, &SceneFiles::newScene);
  openAction_ = new QAction(this);
  openAction_->setShortcut(QKeySequence::Open);
  connect(openAction_, &QAction::triggered, files_, &SceneFiles::open);
  saveAction_ = new QAction(this);
  saveAction_->setShortcut(QKeySequence::Save);
  connect(saveAction_, &QAction::triggered, this, &MainWindow::save);
  saveAsAction_ = new QAction(this);
  // Spelled out: the standard key is empty on X11 outside GNOME and KDE.
  saveAsAction_->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
  connect(saveAsAction_, &QAction::triggered, this, &MainWindow::saveAs);
  exportImageAction_ = new QAction(this);
  exportImageAction_->setObjectName("exportImage");
  connect(exportImageAction_, &QAction::triggered, imageExport_, &ImageExport::exportImage);
  exportVideoAction_ = new QAction(this);
  exportVideoAction_->setObjectName("exportVideo");
  connect(exportVideoAction_, &QAction::triggered, videoExport_, &VideoExport::exportVideo);
}

bool MainWindow::openFile(const QString& fileName, bool askToSave) {
  return files_->openFile(fileName, askToSave);
}

bool MainWindow::openExample(const QString& file, bool askToSave) {
  return files_->openExample(file, askToSave);
}

bool MainWindow::offerRecovery() {
  return files_->offerRecovery();
}

bool MainWindow::save() {
  return files_->save();
}

bool MainWindow::saveAs() {
  return files_->saveAs();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (files_->maybeSave())
    event->accept();
  else
    event->ignore();
}

void MainWindow::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = SceneFiles::recentFiles();
  for (const QString& file : recent) {
    recentMenu_->addAction(QDir::toNativeSeparators(file), this,
                           [this, file] { openFile(file, true); });
  }
  if (recent.isEmpty()) recentMenu_->addAction(tr("(none)"))->setEnabled(false);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.first().isLocalFile()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() != 1 || !urls.first().isLocalFile()) return;
  event->acceptProposedAction();
  // After the drop has finished: a modal question inside a drop would hold the drag source.
  const QString file = urls.first().toLocalFile();
  QMetaObject::invokeMethod(
      this, [this, file] { openFile(file, true); }, Qt::QueuedConnection);
}

// ---- Editing -------------------------------------------------------------------------------

void MainWindow::buildEditActions() {
  // Not QUndoStack's own actions, whose texts stay in the language they were made in.
  QUndoStack* stack = document_->undoStack();
  undoAction_ = new QAction(this);
  undoAction_->setShortcut(QKeySequence::Undo);
  undoAction_->setEnabled(stack->canUndo());
  connect(undoAction_, &QAction::triggered, stack, &QUndoStack::undo);
  connect(stack, &QUndoStack::canUndoChanged, undoAction_, &QAction::setEnabled);
  connect(stack, &QUndoStack::undoTextChanged, this, &MainWindow::showUndoTexts);
  redoAction_ = new QAction(this);
  redoAction_->setShortcuts(
      {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  redoAction_->setEnabled(stack->canRedo());
  connect(redoAction_, &QAction::triggered, stack, &QUndoStack::redo);
  connect(stack, &QUndoStack::canRedoChanged, redoAction_, &QAction::setEnabled);
  connect(stack, &QUndoStack::redoTextChanged, this, &MainWindow::showUndoTexts);

  copyAction_ = new QAction(this);
  copyAction_->setShortcut(QKeySequence::Copy);
  connect(copyAction_, &QAction::triggered, editActions_, &EditActions::copy);
  pasteAction_ = new QAction(this);
  pasteAction_->setShortcut(QKeySequence::Paste);
  connect(pasteAction_, &QAction::triggered, editActions_, &EditActions::paste);
  duplicateAction_ = new QAction(this);
  duplicateAction_->setShortcut(Qt::CTRL | Qt::Key_D);
  connect(duplicateAction_, &QAction::triggered, editActions_, &EditActions::duplicate);
  deleteAction_ = new QAction(this);
  deleteAction_->setShortcut(QKeySequence::Delete);
  connect(deleteAction_, &QAction::triggered, editActions_, &EditActions::deleteSelection);
  selectAllAction_ = new QAction(this);
  selectAllAction_->setShortcut(QKeySequence::SelectAll);
  connect(selectAllAction_, &QAction::triggered, editActions_, &EditActions::selectAll);

  useStateAction_ = new QAction(this);
  useStateAction_->setObjectName("useCurrentState");
  connect(useStateAction_, &QAction::triggered, this, &MainWindow::useCurrentState);
  applyToRunningAction_ = new QAction(this);
  applyToRunningAction_->setObjectName("applyToRunningState");
  applyToRunningAction_->setCheckable(true);
  applyToRunningAction_->setChecked(QSettings().value(kApplyToRunningKey, false).toBool());
  sync_->setApplyToRunningState(applyToRunningAction_->isChecked());
  connect(applyToRunningAction_, &QAction::toggled, this, [this](bool on) {
    sync_->setApplyToRunningState(on);
    QSettings().setValue(kApplyToRunningKey, on);
  });

  addActions({undoAction_, redoAction_, copyAction_, pasteAction_, duplicateAction_, deleteAction_,
              selectAllAction_});

  historyDock_ = new QDockWidget(this);
  historyDock_->setObjectName("historyDock");
  tabifyDockWidget(outlineDock_, historyDock_);
  outlineDock_->raise();
  historyDock_->hide();
}

void MainWindow::useCurrentState() {
  // Of the current start only: a snapshot of the run before an edit is not this scene's state.
  const std::shared_ptr<const SimulationSnapshot> snapshot = simulation_->latest();
  const Scene& scene = document_->scene();
  if (!snapshot || snapshot->positions.size() != scene.balls.size()) return;
  editor::Selection balls;
  Scene values;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    balls.push_back({editor::ObjectKind::Ball, static_cast<int>(i)});
    values.balls.push_back(scene.balls[i]);
    values.balls.back().position = snapshot->positions[i];
    values.balls.back().velocity = snapshot->velocities[i];
  }
  const QString error = document_->editObjects(balls, values, tr("Use Current State as Initial"));
  if (!error.isEmpty()) showMessage(error);
}

}  // namespace carom::ui
