#include "ui/main_window.h"

#include "ui/dialogs/accuracy_window.h"
#include "ui/dialogs/image_export.h"
#include "ui/dialogs/video_export.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/docks/energy_plot.h"
#include "ui/docks/history_dock.h"
#include "ui/edit_actions.h"
#include "ui/edit_menu.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/scene_document.h"
#include "ui/editor/scene_recovery.h"
#include "ui/editor_tool_bar.h"
#include "ui/examples_menu.h"
#include "ui/file_menu.h"
#include "ui/grab_control.h"
#include "ui/help_menu.h"
#include "ui/render/render_scene.h"
#include "ui/render/scene_view.h"
#include "ui/run/run_session.h"
#include "ui/run_controls.h"
#include "ui/scene_files.h"
#include "ui/simulation_menu.h"
#include "ui/simulation_sync.h"
#include "ui/sound_thread.h"
#include "ui/status_readout.h"
#include "ui/timeline_bar.h"
#include "ui/view_menu.h"
#include "ui/watch_alert.h"
#include "ui/world_tool_bar.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMenuBar>
#include <QMimeData>
#include <QStatusBar>
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
    runControls_->setRunning(false);
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
  energyPlot_->setObjectName("energyPlot");
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
  auto* imageExport = new ImageExport(view_, this, this);
  imageExport->setObjectName("imageExport");
  connect(imageExport, &ImageExport::message, this, &MainWindow::showMessage);
  auto* videoExport = new VideoExport(view_, simulation_.get(), this, this);
  videoExport->setObjectName("videoExport");
  connect(videoExport, &VideoExport::message, this, &MainWindow::showMessage);
  // The frames come from the recording, which a running simulation would go on extending.
  connect(videoExport, &VideoExport::pauseRequested, this,
          [this] { runControls_->setRunning(false); });
  sound_ = new SoundThread(this);
  status_ = new StatusReadout(sound_);
  status_->setObjectName("statusReadout");
  // Permanent: passing messages (saves, refusals) show beside the readout, not over it.
  statusBar()->addPermanentWidget(status_);
  tools_ = new editor::EditorTools(document_, view_, this);
  tools_->setObjectName("editorTools");
  connect(tools_, &editor::EditorTools::refused, this, &MainWindow::showMessage);
  grab_ = new GrabControl(tools_, simulation_.get(), this);
  connect(grab_, &GrabControl::message, this, &MainWindow::showMessage);
  watchAlert_ = new WatchAlert(document_, view_, &simulation_->controls(), this);
  watchAlert_->setObjectName("watchAlert");
  // The worker has paused; the control follows.
  connect(watchAlert_, &WatchAlert::stopped, this, [this] { runControls_->setRunning(false); });
  connect(watchAlert_, &WatchAlert::stopped, this, &MainWindow::watchStopped);
  outlineDock_ = new editor::OutlineDock(document_, this);
  addDockWidget(Qt::RightDockWidgetArea, outlineDock_);
  connect(outlineDock_->model(), &editor::OutlineModel::refused, this, &MainWindow::showMessage);
  propertiesDock_ = new editor::PropertiesDock(document_, this);
  addDockWidget(Qt::RightDockWidgetArea, propertiesDock_);
  connect(propertiesDock_, &editor::PropertiesDock::refused, this, &MainWindow::showMessage);
  auto* recovery = new editor::SceneRecovery(document_, this);
  recovery->setObjectName("sceneRecovery");
  connect(recovery, &editor::SceneRecovery::autosaveFailed, this, [this](const QString& reason) {
    showMessage(tr("The recovery copy could not be written (%1); the last one is kept. Save "
                   "the scene elsewhere to be safe.")
                    .arg(reason));
  });
  files_ = new SceneFiles(document_, this, this);
  connect(files_, &SceneFiles::message, this, &MainWindow::showMessage);
  connect(files_, &SceneFiles::sceneAboutToOpen, this, [this] { runControls_->setRunning(false); });
  connect(files_, &SceneFiles::sceneOpened, this, [this] { view_->frameScene(); });
  // Pasted and duplicated balls move to the right of the screen, as the camera looks.
  auto* editActions = new EditActions(
      document_,
      [this] {
        const QVector3D right =
            QVector3D::crossProduct(view_->camera().eye() - view_->camera().target(),
                                    QVector3D(0, 1, 0))
                .normalized();
        return Vec3(-right.x(), -right.y(), -right.z());
      },
      this);
  connect(editActions, &EditActions::message, this, &MainWindow::showMessage);
  followAction_ = new QAction(this);
  followAction_->setShortcut(Qt::Key_F2);
  followAction_->setCheckable(true);
  connect(followAction_, &QAction::toggled, this,
          [this](bool on) { view_->setFollowedBall(on ? followTarget() : -1); });
  auto* historyDock = new HistoryDock(document_->undoStack(), this);
  tabifyDockWidget(outlineDock_, historyDock);
  outlineDock_->raise();
  historyDock->hide();
  buildBars(imageExport, videoExport, editActions, historyDock);
  simulation_->controls().setRecordingBudget(TimelineBar::memoryBudget());
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
  // document takes it, but this half-destroyed window must no longer hear of it.
  document_->disconnect(this);
}

QWidget* MainWindow::view() const {
  return view_;
}

// The toolbars and the menus, which offer many of the same actions.
void MainWindow::buildBars(ImageExport* imageExport, VideoExport* videoExport,
                           EditActions* editActions, QDockWidget* historyDock) {
  auto* toolsBar = new EditorToolBar(tools_, this, this);
  connect(toolsBar, &EditorToolBar::message, this, &MainWindow::showMessage);
  addToolBar(toolsBar);
  // Two rows, so that every control stays visible at 1280 pixels in the longer languages: the
  // tools and the run controls, then the world's settings.
  runControls_ = new RunControls(&simulation_->controls(), this);
  connect(runControls_, &RunControls::message, this, &MainWindow::showMessage);
  addToolBar(runControls_);
  addToolBarBreak();
  worldBar_ = new WorldToolBar(document_, this);
  addToolBar(worldBar_);
  connect(worldBar_, &WorldToolBar::message, this, &MainWindow::showMessage);
  addActions(worldBar_->timeStepActions());

  QMenuBar* bar = menuBar();
  bar->addMenu(new FileMenu(files_, imageExport, videoExport, this, bar));
  bar->addMenu(new EditMenu(document_->undoStack(), editActions, this, bar));
  toolsBar->addMenuTo(bar);
  auto* simulationMenu = new SimulationMenu(runControls_, &simulation_->controls(), sync_, grab_,
                                            timeline_, this, bar);
  connect(simulationMenu, &SimulationMenu::accuracyWindowRequested, this,
          [this] { openAccuracyWindow(); });
  connect(simulationMenu, &SimulationMenu::useCurrentStateRequested, this,
          &MainWindow::useCurrentState);
  bar->addMenu(simulationMenu);
  bar->addMenu(new ExamplesMenu(files_, bar));
  bar->addMenu(new ViewMenu(view_, sound_, followAction_,
                            {energyDock_, storyDock_, outlineDock_, propertiesDock_, historyDock},
                            this, bar));
  bar->addMenu(new HelpMenu(this, bar));
}

void MainWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
  followAction_->setText(tr("&Follow Ball"));
  energyDock_->setWindowTitle(tr("Energy"));
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
  runControls_->setRunning(running);
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
    values.balls.back().angularVelocity = snapshot->angularVelocities[i];
  }
  const QString error = document_->editObjects(balls, values, tr("Use Current State as Initial"));
  if (!error.isEmpty()) showMessage(error);
}

}  // namespace carom::ui
