#include "ui/language_menu.h"

#include "ui/language.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QEvent>

namespace carom::ui {

LanguageMenu::LanguageMenu(QWidget* parent) : QMenu(parent) {
  auto* languages = new QActionGroup(this);
  const QString current = chosenLanguage(QCoreApplication::arguments());
  for (const Language& language : availableLanguages()) {
    QAction* action = addAction(language.nativeName);
    action->setObjectName("language:" + language.code);
    action->setCheckable(true);
    action->setChecked(language.code == current);
    languages->addAction(action);
    if (language.code.isEmpty()) systemLanguageAction_ = action;
    connect(action, &QAction::triggered, this, [code = language.code] { chooseLanguage(code); });
  }
  retranslate();
}

void LanguageMenu::chooseLanguage(const QString& code) {
  saveLanguageChoice(code);
  // Every widget hears of it through a LanguageChange event, and retranslates itself.
  installTranslation(*QCoreApplication::instance(), code);
}

void LanguageMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void LanguageMenu::retranslate() {
  setTitle(tr("&Language"));
  systemLanguageAction_->setText(availableLanguages().front().nativeName);
}

}  // namespace carom::ui
