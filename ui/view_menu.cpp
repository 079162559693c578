#include "ui/view_menu.h"

#include "ui/language_menu.h"
#include "ui/render/scene_view.h"
#include "ui/sound_thread.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QSettings>

namespace carom::ui {

using render::SceneView;

ViewMenu::ViewMenu(SceneView* view, SoundThread* sound, QAction* followAction,
                   const QList<QDockWidget*>& docks, QWidget* window, QWidget* parent)
    : QMenu(parent) {
  fullScreenAction_ = new QAction(this);
  fullScreenAction_->setShortcuts({Qt::Key_F11, Qt::Key_F1});
  fullScreenAction_->setCheckable(true);
  connect(fullScreenAction_, &QAction::toggled, this,
          [window](bool on) { on ? window->showFullScreen() : window->showNormal(); });

  // The view's keys are the window's: they work wherever the focus is, except in a text field
  // being edited (which takes its own keys first).
  frameAction_ = new QAction(this);
  frameAction_->setObjectName("frameScene");
  frameAction_->setShortcut(Qt::Key_Home);
  connect(frameAction_, &QAction::triggered, view, &SceneView::frameScene);

  explosionsAction_ = new QAction(this);
  explosionsAction_->setCheckable(true);
  explosionsAction_->setChecked(true);
  connect(explosionsAction_, &QAction::toggled, view, &SceneView::setExplosionsEnabled);

  // Remembered once chosen; until then the view decides by its renderer.
  antialiasingAction_ = new QAction(this);
  antialiasingAction_->setCheckable(true);
  QSettings settings;
  if (settings.contains(kAntialiasingKey))
    view->setAntialiasing(settings.value(kAntialiasingKey).toBool());
  antialiasingAction_->setChecked(view->antialiasing());
  connect(antialiasingAction_, &QAction::triggered, view, [view](bool on) {
    QSettings().setValue(kAntialiasingKey, on);
    view->setAntialiasing(on);
  });
  connect(view, &SceneView::antialiasingChanged, antialiasingAction_, &QAction::setChecked);

  muteAction_ = new QAction(this);
  muteAction_->setShortcut(Qt::Key_F3);
  muteAction_->setCheckable(true);
  connect(muteAction_, &QAction::toggled, sound, &SoundThread::setMuted);

  addActions({frameAction_, followAction, fullScreenAction_, explosionsAction_, antialiasingAction_,
              muteAction_});
  addSeparator();
  for (QDockWidget* dock : docks) addAction(dock->toggleViewAction());
  addSeparator();
  addMenu(new LanguageMenu(this));
  retranslate();
}

void ViewMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void ViewMenu::retranslate() {
  setTitle(tr("&View"));
  frameAction_->setText(tr("F&rame Scene"));
  fullScreenAction_->setText(tr("&Full Screen"));
  explosionsAction_->setText(tr("&Explosions"));
  antialiasingAction_->setText(tr("&Antialiasing"));
  muteAction_->setText(tr("&Mute"));
}

}  // namespace carom::ui
