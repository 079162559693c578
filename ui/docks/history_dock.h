#pragma once
// The undo stack's commands as a list, as Qt's QUndoView shows them; clicking one goes back or
// forward to it.

#include <QDockWidget>

class QUndoStack;

namespace carom::ui {

class HistoryDock : public QDockWidget {
  Q_OBJECT
 public:
  explicit HistoryDock(QUndoStack* stack, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QUndoStack* stack_;
};

}  // namespace carom::ui
