#pragma once
// The world's settings on a toolbar: gravity, the time step, the method (auto with its
// accuracy) and the integrator. It mirrors the document's world; each change is one edit of it.

#include "sim/measure/method_choice.h"
#include "sim/model/scene.h"

#include <QList>
#include <QString>
#include <QToolBar>

#include <functional>

class QAction;
class QComboBox;
class QLabel;

namespace carom::editor {
class SceneDocument;
}
namespace carom::ui {

class AutoMethod;
class NumberBox;

class WorldToolBar : public QToolBar {
  Q_OBJECT
 public:
  explicit WorldToolBar(editor::SceneDocument* document, QWidget* parent = nullptr);

  // Shows the document's world, without echoing it back as edits.
  void showWorld();
  // `change` made to the document's world, as one command named `text`; a refusal is said and
  // the bar shows the world as it stays.
  void editWorld(const QString& text, const std::function<void(World&)>& change);
  // The time step box's value times `factor`, which edits the world as typing does.
  void changeTimeStep(double factor);
  // The accuracy auto aims at.
  const AccuracyTolerance& autoTolerance() const;
  // Larger and Smaller Time Step (+ and -), for the window, whose keys they are.
  QList<QAction*> timeStepActions() const { return {largerStepAction_, smallerStepAction_}; }

 signals:
  // For the status bar: a refusal, or what auto is doing or chose.
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void addGravity();
  void addMethod();
  void addTimeStepActions();
  void retranslate();
  void retranslateMethodTip();

  editor::SceneDocument* document_;
  QLabel* gravityLabel_ = nullptr;
  NumberBox* gravity_[3] = {};
  QLabel* timeStepLabel_ = nullptr;
  NumberBox* timeStep_ = nullptr;
  QComboBox* method_ = nullptr;  // the methods, then "auto"
  AutoMethod* autoMethod_ = nullptr;
  QString autoExplanation_;  // what auto chose last and why, in the method box's tooltip
  QLabel* accuracyLabel_ = nullptr;
  NumberBox* accuracy_ = nullptr;  // auto's energy error per simulated second
  QAction* accuracyLabelAction_ = nullptr;
  QAction* accuracyBoxAction_ = nullptr;
  QComboBox* integrator_ = nullptr;
  QAction* largerStepAction_ = nullptr;
  QAction* smallerStepAction_ = nullptr;
};

}  // namespace carom::ui
