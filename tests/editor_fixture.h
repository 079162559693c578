#pragma once
// What the editor's GUI tests share: a small scene, a window showing it, clicks at world
// points, and the answerers for modal dialogs of tests/dialog_answerer.h.

#include "tests/dialog_answerer.h"
#include "tests/scene_edits.h"
#include "tests/window_parts.h"
#include "ui/editor/scene_document.h"
#include "ui/main_window.h"
#include "ui/render/scene_view.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QAction>
#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <functional>
#include <memory>

namespace carom::testing {

// A floor at y = 0 and one ball resting on it, between two walls at x = -4 and 4 that keep the
// view's bounds (and so the camera) the same whatever a test adds.
inline Scene floorScene() {
  Scene scene;
  Plane floor;
  floor.normal = Vec3::UnitY();
  floor.name = "floor";
  scene.planes.push_back(floor);
  Ball ball;
  ball.position = Vec3(0, 0.5, 0);
  ball.radius = 0.5;
  ball.name = "first";
  ball.color = "#ff0000";
  scene.balls.push_back(ball);
  for (double x : {-4.0, 4.0}) {
    Plane wall;
    wall.point = Vec3(x, 0, 0);
    wall.normal = Vec3(x < 0 ? 1 : -1, 0, 0);
    scene.planes.push_back(wall);
  }
  return scene;
}

// Opens a window on floorScene() for each test and drives its view.
class EditorFixture : public QObject {
 public:
  static void initMain() {
    render::SceneView::setDefaultFormat();
    // Settings go to a test folder, not the user's.
    QStandardPaths::setTestModeEnabled(true);
  }

 protected:
  void openWindow() {
    QSettings().clear();  // recent files and choices start afresh for every test
    window_ = std::make_unique<ui::MainWindow>();
    window_->openScene(floorScene(), {}, "floor");
    window_->resize(1200, 800);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QApplication::setActiveWindow(window_.get());
    QTRY_VERIFY(framesRendered(*window_) > 0);
  }
  editor::SceneDocument& document() { return *window_->document(); }
  // The newest snapshot of the run's current start. RunSession::latest() is null from a
  // restart until the worker has answered it; this waits for the answer (up to ten seconds).
  std::shared_ptr<const ui::SimulationSnapshot> currentSnapshot() {
    if (!QTest::qWaitFor([this] { return window_->simulation().latest() != nullptr; }, 10000))
      qFatal("No snapshot of the run's current start within ten seconds");
    return window_->simulation().latest();
  }
  render::SceneView& view() { return *qobject_cast<render::SceneView*>(window_->view()); }
  QPoint at(const Vec3& world) { return view().project(world).toPoint(); }
  void click(const Vec3& world, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QTest::mouseClick(&view(), Qt::LeftButton, modifiers, at(world));
  }
  void chooseTool(const char* name) {
    QAction* action = window_->findChild<QAction*>(name);
    QVERIFY2(action, name);
    action->trigger();
  }
  // A press, moves in `steps` and a release, from `from` to `to` in view pixels; moves reach
  // the window asynchronously on xcb, so `arrived` is awaited before the release.
  void drag(QPoint from, QPoint to, const std::function<bool()>& arrived, int steps = 10) {
    QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= steps; ++i) QTest::mouseMove(&view(), from + (to - from) * i / steps);
    QTRY_VERIFY(arrived());
    QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to);
  }

  std::unique_ptr<ui::MainWindow> window_;
};

}  // namespace carom::testing
