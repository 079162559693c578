#include "main_window.h"

#include "accuracy_window.h"
#include "energy_plot.h"
#include "language.h"

#include "render_scene.h"
#include "scene_file.h"
#include "scene_view.h"
#include "simulation_controller.h"
#include "sound_board.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

namespace carom::ui {

using render::SceneView;

namespace {

QString text(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<int>(s.size()));
}

QDoubleSpinBox* numberBox(double low, double high, int decimals, double step, const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setRange(low, high);
  box->setDecimals(decimals);
  box->setSingleStep(step);
  box->setToolTip(tip);
  box->setKeyboardTracking(false);  // apply a typed value when it is complete, not per digit
  return box;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), simulation_(std::make_unique<SimulationController>()) {
  view_ = new SceneView;
  setCentralWidget(view_);
  energyPlot_ = new EnergyPlot;
  auto* energyDock = new QDockWidget(tr("Energy"), this);
  energyDock->setObjectName("energyDock");
  energyDock->setWidget(energyPlot_);
  // Below the view, where the plot's time axis has room.
  addDockWidget(Qt::BottomDockWidgetArea, energyDock);
  energyPlot_->setMinimumHeight(190);
  status_ = new QLabel;
  statusBar()->addWidget(status_, 1);
  sound_ = new SoundBoard(this);
  buildActions();
  buildToolBar();
  buildMenus();
  connect(simulation_.get(), &SimulationController::snapshotPublished, this,
          &MainWindow::showSnapshot);
  connect(view_, &SceneView::frameRendered, this, [this](double) {
    ++framesRendered_;
    const double seconds = fpsClock_.nsecsElapsed() * 1e-9;
    if (seconds >= 1.0) {
      framesPerSecond_ = (framesRendered_ - framesAtLastSample_) / seconds;
      framesAtLastSample_ = framesRendered_;
      fpsClock_.restart();
    }
  });
  fpsClock_.start();
  statusTimer_.setSingleShot(true);
  statusTimer_.setInterval(kStatusRefreshMilliseconds);
  connect(&statusTimer_, &QTimer::timeout, this, &MainWindow::showStatus);
  resize(1280, 800);
}

MainWindow::~MainWindow() = default;

QWidget* MainWindow::view() const {
  return view_;
}

QString MainWindow::statusText() const {
  return status_->text();
}

void MainWindow::buildActions() {
  playAction_ = new QAction(tr("&Run"), this);
  playAction_->setCheckable(true);
  playAction_->setShortcut(Qt::Key_Space);
  playAction_->setToolTip(tr("Run or pause the simulation (Space)"));
  connect(playAction_, &QAction::toggled, this, [this](bool on) {
    playAction_->setText(on ? tr("&Pause") : tr("&Run"));
    simulation_->setRunning(on);
  });

  stepAction_ = new QAction(tr("&Step"), this);
  stepAction_->setShortcut(Qt::Key_S);
  stepAction_->setToolTip(tr("Advance one time step (S)"));
  connect(stepAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->stepOnce();
  });

  resetAction_ = new QAction(tr("R&eset"), this);
  resetAction_->setShortcut(Qt::Key_R);
  resetAction_->setToolTip(tr("Back to the scene's initial state (R)"));
  connect(resetAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->reset();
  });

  fullScreenAction_ = new QAction(tr("&Full Screen"), this);
  fullScreenAction_->setShortcuts({Qt::Key_F11, Qt::Key_F1});
  fullScreenAction_->setCheckable(true);
  connect(fullScreenAction_, &QAction::toggled, this,
          [this](bool on) { on ? showFullScreen() : showNormal(); });

  followAction_ = new QAction(tr("&Follow Ball"), this);
  followAction_->setShortcut(Qt::Key_F2);
  followAction_->setCheckable(true);
  connect(followAction_, &QAction::toggled, this,
          [this](bool on) { view_->setFollowedBall(on && !scene_.balls.empty() ? 0 : -1); });

  explosionsAction_ = new QAction(tr("&Explosions"), this);
  explosionsAction_->setCheckable(true);
  explosionsAction_->setChecked(true);
  connect(explosionsAction_, &QAction::toggled, this,
          [this](bool on) { view_->setExplosionsEnabled(on); });

  // Remembered once chosen; until then the view decides by its renderer.
  antialiasingAction_ = new QAction(tr("&Antialiasing"), this);
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

  muteAction_ = new QAction(tr("&Mute"), this);
  muteAction_->setShortcut(Qt::Key_F3);
  muteAction_->setCheckable(true);
  connect(muteAction_, &QAction::toggled, this, [this](bool on) { sound_->setMuted(on); });

  auto* faster = new QAction(tr("Larger Time Step"), this);
  faster->setShortcuts({Qt::Key_Plus, Qt::Key_Equal});
  connect(faster, &QAction::triggered, this, [this] { changeTimeStep(1.25); });
  auto* slower = new QAction(tr("Smaller Time Step"), this);
  slower->setShortcut(Qt::Key_Minus);
  connect(slower, &QAction::triggered, this, [this] { changeTimeStep(1.0 / 1.25); });
  addActions({faster, slower});
}

void MainWindow::buildToolBar() {
  QToolBar* bar = addToolBar(tr("Simulation"));
  bar->setObjectName("simulation");
  bar->addAction(playAction_);
  bar->addAction(stepAction_);
  bar->addAction(resetAction_);
  bar->addSeparator();

  bar->addWidget(new QLabel(tr("Speed")));
  speed_ = numberBox(0.01, 100.0, 2, 0.25, tr("Simulated seconds per real second"));
  speed_->setObjectName("speed");
  speed_->setValue(1.0);
  connect(speed_, &QDoubleSpinBox::valueChanged, this,
          [this](double value) { simulation_->setSpeed(value); });
  bar->addWidget(speed_);

  bar->addWidget(new QLabel(tr("Gravity")));
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    gravity_[a] = numberBox(-1000.0, 1000.0, 3, 0.5, tr("Gravity %1 (m/s²)").arg(axes[a]));
    gravity_[a]->setObjectName(QString("gravity") + QChar(axes[a][0]).toUpper());
    connect(gravity_[a], &QDoubleSpinBox::valueChanged, this, &MainWindow::applyGravity);
    bar->addWidget(gravity_[a]);
  }

  bar->addWidget(new QLabel(tr("Step")));
  timeStep_ = numberBox(1e-6, 10.0, 6, 0.001, tr("Time step in seconds (+ and - keys)"));
  timeStep_->setObjectName("timeStep");
  connect(timeStep_, &QDoubleSpinBox::valueChanged, this,
          [this](double value) { simulation_->setTimeStep(value); });
  bar->addWidget(timeStep_);

  method_ = new QComboBox;
  for (std::string_view name : methodNames()) method_->addItem(text(name));
  method_->setToolTip(tr("Exact (event-driven), swept, or discrete steps"));
  connect(method_, &QComboBox::currentIndexChanged, this,
          [this](int index) { simulation_->setMethod(Method(index)); });
  bar->addWidget(method_);

  integrator_ = new QComboBox;
  for (std::string_view name : integratorNames()) integrator_->addItem(text(name));
  integrator_->setToolTip(tr("Integrator of the swept and discrete methods"));
  connect(integrator_, &QComboBox::currentIndexChanged, this,
          [this](int index) { simulation_->setIntegrator(Integrator(index)); });
  bar->addWidget(integrator_);
}

void MainWindow::buildMenus() {
  QMenu* simulationMenu = menuBar()->addMenu(tr("&Simulation"));
  simulationMenu->addActions({playAction_, stepAction_, resetAction_});
  simulationMenu->addSeparator();
  simulationMenu->addAction(tr("Speed vs &Accuracy…"), this, [this] { openAccuracyWindow(); });
  simulationMenu->addSeparator();
  simulationMenu->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::quit);

  QMenu* examples = menuBar()->addMenu(tr("&Examples"));
  const QStringList files = QDir(":/scenes").entryList({"*.json"}, QDir::Files, QDir::Name);
  for (const QString& file : files) {
    QString title = file;
    title.chop(5);
    examples->addAction(title, this, [this, file, title] {
      const SceneLoadResult loaded = loadSceneFile(":/scenes/" + file);
      if (loaded.scene) openScene(*loaded.scene, title);
    });
  }

  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  viewMenu->addActions(
      {followAction_, fullScreenAction_, explosionsAction_, antialiasingAction_, muteAction_});
  viewMenu->addSeparator();
  viewMenu->addAction(findChild<QDockWidget*>("energyDock")->toggleViewAction());
  viewMenu->addSeparator();
  QMenu* languageMenu = viewMenu->addMenu(tr("&Language"));
  auto* languages = new QActionGroup(this);
  const QString current = chosenLanguage({});
  for (const Language& language : availableLanguages()) {
    QAction* action = languageMenu->addAction(language.nativeName);
    action->setCheckable(true);
    action->setChecked(language.code == current);
    languages->addAction(action);
    connect(action, &QAction::triggered, this, [this, code = language.code] {
      saveLanguageChoice(code);
      statusBar()->showMessage(tr("The language changes when Carom is next started."), 8000);
    });
  }
}

void MainWindow::openScene(const carom::Scene& scene, const QString& title) {
  scene_ = scene;
  playAction_->setChecked(false);
  setWindowTitle(tr("%1 — Carom").arg(title));
  view_->setScene(std::make_shared<const render::RenderScene>(render::makeRenderScene(scene)));
  // Show the scene's world settings without echoing them back to the worker.
  const QSignalBlocker blockers[] = {QSignalBlocker(gravity_[0]), QSignalBlocker(gravity_[1]),
                                     QSignalBlocker(gravity_[2]), QSignalBlocker(timeStep_),
                                     QSignalBlocker(method_),     QSignalBlocker(integrator_)};
  for (int a = 0; a < 3; ++a) gravity_[a]->setValue(scene.world.gravity[a]);
  timeStep_->setValue(scene.world.timeStep);
  method_->setCurrentIndex(int(scene.world.method));
  integrator_->setCurrentIndex(int(scene.world.integrator));
  energyPlot_->clear();
  simulation_->loadScene(scene);
  simulation_->setSpeed(speed_->value());
  lastCollisionCount_ = 0;
  lastCollisionTime_ = 0.0;
  collisionsPerSecond_ = 0.0;
}

void MainWindow::setRunning(bool running) {
  playAction_->setChecked(running);
}

AccuracyWindow* MainWindow::openAccuracyWindow(double duration) {
  carom::Scene scene = scene_;
  // The study runs what the sandbox runs now: the scene with the current world settings.
  if (const auto snapshot = simulation_->latest()) scene.world = snapshot->world;
  auto* window = new AccuracyWindow(scene, this);
  window->setAttribute(Qt::WA_DeleteOnClose);
  window->setDuration(duration);
  connect(window, &AccuracyWindow::settingsChosen, this, &MainWindow::applySettings);
  window->show();
  window->start();
  return window;
}

void MainWindow::applySettings(carom::Method method, carom::Integrator integrator,
                               double timeStep) {
  method_->setCurrentIndex(int(method));
  integrator_->setCurrentIndex(int(integrator));
  timeStep_->setValue(timeStep);
}

void MainWindow::applyGravity() {
  simulation_->setGravity(Vec3(gravity_[0]->value(), gravity_[1]->value(), gravity_[2]->value()));
}

void MainWindow::changeTimeStep(double factor) {
  timeStep_->setValue(timeStep_->value() * factor);
}

void MainWindow::showSnapshot() {
  const std::shared_ptr<const SimulationSnapshot> snapshot = simulation_->take();
  if (!snapshot) return;
  view_->setBallPositions(snapshot->positions);
  view_->addExplosions(snapshot->collisions);
  energyPlot_->add(*snapshot);
  sound_->play(snapshot->collisions);
  latestSnapshot_ = snapshot;
  // Numbers changing sixty times a second cannot be read, and relaying out the status bar each
  // frame costs the GUI thread; the line shows the latest snapshot a few times a second.
  if (!statusTimer_.isActive()) statusTimer_.start();
}

void MainWindow::showStatus() {
  const std::shared_ptr<const SimulationSnapshot> snapshot = latestSnapshot_;
  if (!snapshot) return;
  const std::uint64_t collisions = snapshot->stats.collisions.total();
  if (snapshot->time < lastCollisionTime_ || collisions < lastCollisionCount_) {
    lastCollisionTime_ = snapshot->time;  // after a reset
    lastCollisionCount_ = collisions;
  } else if (snapshot->time - lastCollisionTime_ >= 0.5) {
    collisionsPerSecond_ =
        double(collisions - lastCollisionCount_) / (snapshot->time - lastCollisionTime_);
    lastCollisionTime_ = snapshot->time;
    lastCollisionCount_ = collisions;
  }
  const double energy = snapshot->kineticEnergy + snapshot->potentialEnergy;
  const double drift = snapshot->initialEnergy != 0.0
                           ? (energy - snapshot->initialEnergy) / std::abs(snapshot->initialEnergy)
                           : 0.0;
  QString line = tr("t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   "
                    "E = %6 J (drift %7)")
                     .arg(snapshot->time, 0, 'f', 3)
                     .arg(snapshot->realTimeFactor, 0, 'f', 2)
                     .arg(framesPerSecond_, 0, 'f', 0)
                     .arg(collisionsPerSecond_, 0, 'f', 0)
                     .arg(snapshot->positions.size())
                     .arg(energy, 0, 'g', 6)
                     .arg(drift, 0, 'e', 1);
  if (!sound_->available())
    line += tr("   sound unavailable");
  else if (sound_->muted())
    line += tr("   muted");
  if (snapshot->fallingBehind) line += tr("   — the physics cannot keep up; running slower");
  status_->setText(line);
}

}  // namespace carom::ui
