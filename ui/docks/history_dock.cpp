#include "ui/docks/history_dock.h"

#include <QEvent>
#include <QUndoView>

namespace carom::ui {

HistoryDock::HistoryDock(QUndoStack* stack, QWidget* parent) : QDockWidget(parent), stack_(stack) {
  setObjectName("historyDock");
  retranslate();
}

void HistoryDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void HistoryDock::retranslate() {
  setWindowTitle(tr("History"));
  // Qt's undo view names its empty state once, when it is made: a new one speaks the language.
  delete widget();
  setWidget(new QUndoView(stack_));
}

}  // namespace carom::ui
