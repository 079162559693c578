#include "ui/examples_menu.h"

#include "ui/scene_files.h"

#include <QAction>
#include <QEvent>

namespace carom::ui {

ExamplesMenu::ExamplesMenu(SceneFiles* files, QWidget* parent) : QMenu(parent) {
  setObjectName("examplesMenu");
  for (const QString& file : SceneFiles::exampleFiles()) {
    QAction* action =
        addAction(QString(), files, [files, file] { files->openExample(file, true); });
    action->setObjectName(QString("example:%1").arg(file));
  }
  retranslate();
}

void ExamplesMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void ExamplesMenu::retranslate() {
  setTitle(tr("&Examples"));
  const QList<QAction*> examples = actions();
  for (int i = 0; i < int(examples.size()); ++i) examples[i]->setText(SceneFiles::exampleTitle(i));
}

}  // namespace carom::ui
