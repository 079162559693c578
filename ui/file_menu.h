#pragma once
// The File menu: New, Open, the recent files, Save, Save As, the exports and Quit. The work is
// SceneFiles', ImageExport's and VideoExport's; the menu offers it.

#include <QMenu>

class QAction;

namespace carom::ui {

class ImageExport;
class SceneFiles;
class VideoExport;

class FileMenu : public QMenu {
  Q_OBJECT
 public:
  // Quit closes `window`.
  FileMenu(SceneFiles* files, ImageExport* imageExport, VideoExport* videoExport, QWidget* window,
           QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void fillRecentMenu();

  SceneFiles* files_;
  QAction* newAction_ = nullptr;
  QAction* openAction_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QAction* saveAction_ = nullptr;
  QAction* saveAsAction_ = nullptr;
  QAction* exportImageAction_ = nullptr;
  QAction* exportVideoAction_ = nullptr;
  QAction* quitAction_ = nullptr;
};

}  // namespace carom::ui
