#include "ui/help_menu.h"

#include "ui/dialogs/help_dialogs.h"

#include <QAction>
#include <QEvent>

namespace carom::ui {

HelpMenu::HelpMenu(QWidget* window, QWidget* parent) : QMenu(parent) {
  setObjectName("helpMenu");
  // One window a page, shown again when asked again.
  const auto show = [window](HelpWindow::Page page) {
    HelpWindow* shown = nullptr;
    for (HelpWindow* open : window->findChildren<HelpWindow*>())
      if (open->page() == page) shown = open;
    if (!shown) shown = new HelpWindow(page, window);
    shown->show();
    shown->raise();
  };
  keyboardHelpAction_ =
      addAction(QString(), this, [show] { show(HelpWindow::Page::KeyboardAndMouse); });
  keyboardHelpAction_->setObjectName("keyboardHelp");
  userGuideAction_ = addAction(QString(), this, [show] { show(HelpWindow::Page::UserGuide); });
  userGuideAction_->setObjectName("userGuide");
  addSeparator();
  aboutAction_ = addAction(QString(), this, [window] { showAbout(window); });
  aboutAction_->setObjectName("about");
  retranslate();
}

void HelpMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void HelpMenu::retranslate() {
  setTitle(tr("&Help"));
  keyboardHelpAction_->setText(tr("&Keyboard and Mouse"));
  userGuideAction_->setText(tr("&User Guide"));
  aboutAction_->setText(tr("&About Carom"));
}

}  // namespace carom::ui
