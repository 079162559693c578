#include "ui/file_menu.h"

#include "ui/dialogs/image_export.h"
#include "ui/dialogs/video_export.h"
#include "ui/scene_files.h"

#include <QAction>
#include <QDir>
#include <QEvent>

namespace carom::ui {

FileMenu::FileMenu(SceneFiles* files, ImageExport* imageExport, VideoExport* videoExport,
                   QWidget* window, QWidget* parent)
    : QMenu(parent), files_(files) {
  newAction_ = new QAction(this);
  newAction_->setShortcut(QKeySequence::New);
  connect(newAction_, &QAction::triggered, files_, &SceneFiles::newScene);
  openAction_ = new QAction(this);
  openAction_->setShortcut(QKeySequence::Open);
  connect(openAction_, &QAction::triggered, files_, &SceneFiles::open);
  saveAction_ = new QAction(this);
  saveAction_->setShortcut(QKeySequence::Save);
  connect(saveAction_, &QAction::triggered, files_, &SceneFiles::save);
  saveAsAction_ = new QAction(this);
  // Spelled out: the standard key is empty on X11 outside GNOME and KDE.
  saveAsAction_->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
  connect(saveAsAction_, &QAction::triggered, files_, &SceneFiles::saveAs);
  exportImageAction_ = new QAction(this);
  exportImageAction_->setObjectName("exportImage");
  connect(exportImageAction_, &QAction::triggered, imageExport, &ImageExport::exportImage);
  exportVideoAction_ = new QAction(this);
  exportVideoAction_->setObjectName("exportVideo");
  connect(exportVideoAction_, &QAction::triggered, videoExport, &VideoExport::exportVideo);

  addActions({newAction_, openAction_});
  recentMenu_ = addMenu(QString());
  recentMenu_->setObjectName("recentMenu");
  connect(recentMenu_, &QMenu::aboutToShow, this, &FileMenu::fillRecentMenu);
  addActions({saveAction_, saveAsAction_});
  addSeparator();
  addActions({exportImageAction_, exportVideoAction_});
  addSeparator();
  quitAction_ = addAction(QString(), QKeySequence::Quit, window, &QWidget::close);
  retranslate();
}

void FileMenu::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = SceneFiles::recentFiles();
  for (const QString& file : recent) {
    recentMenu_->addAction(QDir::toNativeSeparators(file), this,
                           [this, file] { files_->openFile(file, true); });
  }
  if (recent.isEmpty()) recentMenu_->addAction(tr("(none)"))->setEnabled(false);
}

void FileMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void FileMenu::retranslate() {
  setTitle(tr("&File"));
  newAction_->setText(tr("&New"));
  openAction_->setText(tr("&Open…"));
  recentMenu_->setTitle(tr("Open &Recent"));
  saveAction_->setText(tr("&Save"));
  saveAsAction_->setText(tr("Save &As…"));
  exportImageAction_->setText(tr("Export &Image…"));
  exportVideoAction_->setText(tr("Export &Video…"));
  quitAction_->setText(tr("&Quit"));
}

}  // namespace carom::ui
