#pragma once
// The Examples menu: the bundled scenes, titled in the program's language.

#include <QMenu>

namespace carom::ui {

class SceneFiles;

class ExamplesMenu : public QMenu {
  Q_OBJECT
 public:
  explicit ExamplesMenu(SceneFiles* files, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
};

}  // namespace carom::ui
