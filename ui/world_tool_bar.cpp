#include "ui/world_tool_bar.h"

#include "sim/core/tolerances.h"
#include "ui/auto_method.h"
#include "ui/editor/scene_document.h"
#include "ui/number_box.h"

#include <QAction>
#include <QComboBox>
#include <QEvent>
#include <QLabel>
#include <QSignalBlocker>

#include <string_view>

namespace carom::ui {

WorldToolBar::WorldToolBar(editor::SceneDocument* document, QWidget* parent)
    : QToolBar(parent), document_(document) {
  setObjectName("world");
  addGravity();
  timeStepLabel_ = new QLabel;
  addWidget(timeStepLabel_);
  timeStep_ = new NumberBox(QString(), tolerance::kMinTimeStep, tolerance::kMaxTimeStep, 0.001);
  timeStep_->setObjectName("timeStep");
  connect(timeStep_, &NumberBox::refused, this, &WorldToolBar::message);
  connect(timeStep_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
    editWorld(tr("Change Time Step"), [value](World& world) { world.timeStep = value; });
  });
  addWidget(timeStep_);
  addMethod();
  integrator_ = new QComboBox;
  for (std::string_view name : integratorNames()) integrator_->addItem(QString::fromUtf8(name));
  connect(integrator_, &QComboBox::currentIndexChanged, this, [this](int index) {
    editWorld(tr("Change Integrator"),
              [index](World& world) { world.integrator = Integrator(index); });
  });
  addWidget(integrator_);
  addTimeStepActions();
  retranslate();
}

void WorldToolBar::addTimeStepActions() {
  largerStepAction_ = new QAction(this);
  largerStepAction_->setShortcuts({Qt::Key_Plus, Qt::Key_Equal});
  connect(largerStepAction_, &QAction::triggered, this, [this] { changeTimeStep(1.25); });
  smallerStepAction_ = new QAction(this);
  smallerStepAction_->setShortcut(Qt::Key_Minus);
  connect(smallerStepAction_, &QAction::triggered, this, [this] { changeTimeStep(1.0 / 1.25); });
}

void WorldToolBar::addGravity() {
  gravityLabel_ = new QLabel;
  addWidget(gravityLabel_);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    gravity_[a] =
        new NumberBox(QString(), -tolerance::kMaxMagnitude, tolerance::kMaxMagnitude, 0.5);
    gravity_[a]->setObjectName(QString("gravity") + QChar(axes[a][0]).toUpper());
    connect(gravity_[a], &NumberBox::refused, this, &WorldToolBar::message);
    connect(gravity_[a], &QDoubleSpinBox::valueChanged, this, [this, a](double value) {
      editWorld(tr("Change Gravity"), [a, value](World& world) { world.gravity[a] = value; });
    });
    addWidget(gravity_[a]);
  }
}

// The methods, then auto, whose accuracy shows beside it only while it is chosen.
void WorldToolBar::addMethod() {
  method_ = new QComboBox;
  method_->setObjectName("worldMethod");
  for (std::string_view name : methodNames()) method_->addItem(QString::fromUtf8(name));
  method_->addItem(QStringLiteral("auto"));  // a key like the methods' names, not translated
  autoMethod_ = new AutoMethod(document_, this);
  connect(autoMethod_, &AutoMethod::choosingStarted, this,
          [this] { emit message(tr("Auto: piloting the scene under 13 settings…")); });
  connect(autoMethod_, &AutoMethod::finished, this,
          [this](const QString& summary, const QString& explanation) {
            autoExplanation_ = explanation;
            retranslateMethodTip();
            emit message(summary);
          });
  connect(method_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index == int(methodNames().size())) {
      editWorld(tr("Change Method"), [tolerance = autoMethod_->tolerance()](World& world) {
        world.autoMethod = tolerance;
      });
    } else {
      editWorld(tr("Change Method"), [index](World& world) {
        world.method = Method(index);
        world.autoMethod.reset();
      });
    }
  });
  addWidget(method_);
  accuracyLabel_ = new QLabel;
  accuracyLabelAction_ = addWidget(accuracyLabel_);
  accuracy_ = new NumberBox(QString(), 1e-30, 10.0, 1e-3);
  accuracy_->setObjectName("accuracy");
  accuracy_->setValue(autoMethod_->tolerance().energyPerSecond);
  connect(accuracy_, &NumberBox::refused, this, &WorldToolBar::message);
  connect(accuracy_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
    editWorld(tr("Change Accuracy"), [value](World& world) {
      if (world.autoMethod) world.autoMethod->energyPerSecond = value;
    });
  });
  accuracyBoxAction_ = addWidget(accuracy_);
  accuracyLabelAction_->setVisible(false);
  accuracyBoxAction_->setVisible(false);
}

const AccuracyTolerance& WorldToolBar::autoTolerance() const {
  return autoMethod_->tolerance();
}

void WorldToolBar::showWorld() {
  const World& world = document_->scene().world;
  const QSignalBlocker blockers[] = {QSignalBlocker(gravity_[0]), QSignalBlocker(gravity_[1]),
                                     QSignalBlocker(gravity_[2]), QSignalBlocker(timeStep_),
                                     QSignalBlocker(method_),     QSignalBlocker(integrator_),
                                     QSignalBlocker(accuracy_)};
  for (int a = 0; a < 3; ++a) gravity_[a]->setValue(world.gravity[a]);
  timeStep_->setValue(world.timeStep);
  // Under auto the world holds what auto chose; the box says auto, and what that is.
  const int automatic = int(methodNames().size());
  const std::string_view name = methodName(world.method);
  method_->setItemText(automatic,
                       QString("auto (%1)").arg(QString::fromUtf8(name.data(), name.size())));
  method_->setCurrentIndex(world.autoMethod ? automatic : int(world.method));
  accuracyLabelAction_->setVisible(world.autoMethod.has_value());
  accuracyBoxAction_->setVisible(world.autoMethod.has_value());
  accuracy_->setValue(autoMethod_->tolerance().energyPerSecond);
  integrator_->setCurrentIndex(int(world.integrator));
}

void WorldToolBar::editWorld(const QString& text, const std::function<void(World&)>& change) {
  World world = document_->scene().world;
  change(world);
  const QString error = document_->editWorld(world, text);
  if (!error.isEmpty()) {
    emit message(error);
    showWorld();  // puts the bar back
  }
}

void WorldToolBar::changeTimeStep(double factor) {
  timeStep_->setValue(timeStep_->value() * factor);
}

// What the methods are, and what auto last chose and why: the status line shows that only for
// a while, and cut to its width.
void WorldToolBar::retranslateMethodTip() {
  QString tip =
      tr("Exact (event-driven), swept, or discrete steps; auto: the cheapest that "
         "meets the accuracy, found by a short pilot");
  if (!autoExplanation_.isEmpty()) tip += "\n\n" + autoExplanation_;
  method_->setToolTip(tip);
}

void WorldToolBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QToolBar::changeEvent(event);
}

void WorldToolBar::retranslate() {
  setWindowTitle(tr("World"));
  gravityLabel_->setText(tr("Gravity"));
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    gravity_[a]->setName(tr("Gravity %1").arg(axes[a]));
    gravity_[a]->setToolTip(tr("Gravity %1 (m/s²)").arg(axes[a]));
  }
  timeStepLabel_->setText(tr("Step"));
  timeStep_->setName(tr("Time step"));
  timeStep_->setToolTip(tr("Time step in seconds (+ and - keys)"));
  retranslateMethodTip();
  accuracyLabel_->setText(tr("Accuracy"));
  accuracy_->setName(tr("Accuracy"));
  accuracy_->setToolTip(
      tr("Auto's tolerance: the relative energy error per simulated second (and a penetration of "
         "at most 5% of the radius)"));
  integrator_->setToolTip(tr("Integrator of the swept and discrete methods"));
  largerStepAction_->setText(tr("Larger Time Step"));
  smallerStepAction_->setText(tr("Smaller Time Step"));
  // The boxes show their values in the language's number format.
  for (NumberBox* box : {gravity_[0], gravity_[1], gravity_[2], timeStep_, accuracy_}) {
    const QSignalBlocker blocker(box);
    box->setValue(box->value());
  }
}

}  // namespace carom::ui
