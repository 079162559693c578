#include "ui/edit_menu.h"

#include "ui/edit_actions.h"

#include <QAction>
#include <QEvent>
#include <QUndoStack>

namespace carom::ui {

EditMenu::EditMenu(QUndoStack* stack, EditActions* editActions, QWidget* window, QWidget* parent)
    : QMenu(parent), stack_(stack) {
  // Not QUndoStack's own actions, whose texts stay in the language they were made in.
  undoAction_ = new QAction(this);
  undoAction_->setShortcut(QKeySequence::Undo);
  undoAction_->setEnabled(stack->canUndo());
  connect(undoAction_, &QAction::triggered, stack, &QUndoStack::undo);
  connect(stack, &QUndoStack::canUndoChanged, undoAction_, &QAction::setEnabled);
  connect(stack, &QUndoStack::undoTextChanged, this, &EditMenu::showUndoTexts);
  redoAction_ = new QAction(this);
  redoAction_->setShortcuts(
      {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  redoAction_->setEnabled(stack->canRedo());
  connect(redoAction_, &QAction::triggered, stack, &QUndoStack::redo);
  connect(stack, &QUndoStack::canRedoChanged, redoAction_, &QAction::setEnabled);
  connect(stack, &QUndoStack::redoTextChanged, this, &EditMenu::showUndoTexts);

  copyAction_ = new QAction(this);
  copyAction_->setShortcut(QKeySequence::Copy);
  connect(copyAction_, &QAction::triggered, editActions, &EditActions::copy);
  pasteAction_ = new QAction(this);
  pasteAction_->setShortcut(QKeySequence::Paste);
  connect(pasteAction_, &QAction::triggered, editActions, &EditActions::paste);
  duplicateAction_ = new QAction(this);
  duplicateAction_->setShortcut(Qt::CTRL | Qt::Key_D);
  connect(duplicateAction_, &QAction::triggered, editActions, &EditActions::duplicate);
  deleteAction_ = new QAction(this);
  deleteAction_->setShortcut(QKeySequence::Delete);
  connect(deleteAction_, &QAction::triggered, editActions, &EditActions::deleteSelection);
  selectAllAction_ = new QAction(this);
  selectAllAction_->setShortcut(QKeySequence::SelectAll);
  connect(selectAllAction_, &QAction::triggered, editActions, &EditActions::selectAll);

  window->addActions({undoAction_, redoAction_, copyAction_, pasteAction_, duplicateAction_,
                      deleteAction_, selectAllAction_});

  addActions({undoAction_, redoAction_});
  addSeparator();
  addActions({copyAction_, pasteAction_, duplicateAction_, deleteAction_});
  addSeparator();
  addActions({selectAllAction_});
  retranslate();
}

void EditMenu::showUndoTexts() {
  undoAction_->setText(stack_->undoText().isEmpty() ? tr("&Undo")
                                                    : tr("&Undo %1").arg(stack_->undoText()));
  redoAction_->setText(stack_->redoText().isEmpty() ? tr("&Redo")
                                                    : tr("&Redo %1").arg(stack_->redoText()));
}

void EditMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void EditMenu::retranslate() {
  setTitle(tr("&Edit"));
  showUndoTexts();
  copyAction_->setText(tr("&Copy"));
  pasteAction_->setText(tr("&Paste"));
  duplicateAction_->setText(tr("&Duplicate"));
  deleteAction_->setText(tr("De&lete"));
  selectAllAction_->setText(tr("Select &All"));
}

}  // namespace carom::ui
