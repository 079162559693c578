#pragma once
// The Edit menu: Undo and Redo named after the commands they would undo and redo, then the
// clipboard, duplicate, delete and select all of EditActions.

#include <QMenu>

class QAction;
class QUndoStack;

namespace carom::ui {

class EditActions;

class EditMenu : public QMenu {
  Q_OBJECT
 public:
  // The actions' keys work all over `window`.
  EditMenu(QUndoStack* stack, EditActions* editActions, QWidget* window, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void showUndoTexts();

  // The document's: it announces its texts as it clears itself on the way out, when only it is
  // still whole.
  QUndoStack* stack_;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* copyAction_ = nullptr;
  QAction* pasteAction_ = nullptr;
  QAction* duplicateAction_ = nullptr;
  QAction* deleteAction_ = nullptr;
  QAction* selectAllAction_ = nullptr;
};

}  // namespace carom::ui
