#pragma once
// The run's controls on a toolbar: Run/Pause, Step, Reset and the speed. The Simulation menu
// shows the same actions.

#include <QList>
#include <QToolBar>

class QAction;
class QLabel;

namespace carom::ui {

class NumberBox;
class SimulationController;

class RunControls : public QToolBar {
  Q_OBJECT
 public:
  explicit RunControls(SimulationController* simulation, QWidget* parent = nullptr);

  // Run/Pause, Step and Reset, for the Simulation menu.
  QList<QAction*> runActions() const;
  // As the Run/Pause control does.
  void setRunning(bool running);

 signals:
  // A typed speed was not taken.
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  SimulationController* simulation_;
  QAction* playAction_ = nullptr;
  QAction* stepAction_ = nullptr;
  QAction* resetAction_ = nullptr;
  QLabel* speedLabel_ = nullptr;
  NumberBox* speed_ = nullptr;
};

}  // namespace carom::ui
