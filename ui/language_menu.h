#pragma once
// View > Language: the system's language and each one the program speaks, named in itself. A
// choice is saved for the next start and spoken at once.

#include <QMenu>

class QAction;

namespace carom::ui {

class LanguageMenu : public QMenu {
  Q_OBJECT
 public:
  explicit LanguageMenu(QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  static void chooseLanguage(const QString& code);

  QAction* systemLanguageAction_ = nullptr;
};

}  // namespace carom::ui
