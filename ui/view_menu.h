#pragma once
// The View menu: framing and following, full screen, the view's explosions and antialiasing, the
// sound's mute, the docks shown, and the language.

#include <QList>
#include <QMenu>

class QAction;
class QDockWidget;

namespace carom::render {
class SceneView;
}
namespace carom::ui {

class SoundThread;

class ViewMenu : public QMenu {
  Q_OBJECT
 public:
  // `followAction` is the window's, which knows the ball to follow; Full Screen is `window`'s.
  ViewMenu(render::SceneView* view, SoundThread* sound, QAction* followAction,
           const QList<QDockWidget*>& docks, QWidget* window, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  static constexpr const char* kAntialiasingKey = "view/antialiasing";
  QAction* frameAction_ = nullptr;
  QAction* fullScreenAction_ = nullptr;
  QAction* explosionsAction_ = nullptr;
  QAction* antialiasingAction_ = nullptr;
  QAction* muteAction_ = nullptr;
};

}  // namespace carom::ui
