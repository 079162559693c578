#pragma once
// The Help menu: the keyboard and mouse reference and the user guide, each in one window shown
// again when asked again, and the About box.

#include <QMenu>

class QAction;

namespace carom::ui {

class HelpMenu : public QMenu {
  Q_OBJECT
 public:
  // The windows and the About box open over `window`.
  explicit HelpMenu(QWidget* window, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QAction* keyboardHelpAction_ = nullptr;
  QAction* userGuideAction_ = nullptr;
  QAction* aboutAction_ = nullptr;
};

}  // namespace carom::ui
