#pragma once
// What the window does when the run watch (sim/run_watch.h) has paused the run on an event:
// says it in the status bar and a dialog that offers the moment before, selects the ball and
// frames it in the view.

#include "sim/measure/run_watch.h"

#include <QObject>
#include <QPointer>

class QMainWindow;
class QMessageBox;

namespace carom::editor {
class SceneDocument;
}
namespace carom::render {
class SceneView;
}
namespace carom::ui {

class SimulationController;
struct SimulationSnapshot;

class WatchAlert : public QObject {
  Q_OBJECT
 public:
  WatchAlert(editor::SceneDocument* document, render::SceneView* view,
             SimulationController* simulation, QMainWindow* window);

  // Each snapshot the window shows: a new event is shown once. `following`: the view follows
  // the selected ball, so it is not framed as well.
  void showSnapshot(const SimulationSnapshot& snapshot, bool following);
  // The dialog of the last event while it is open.
  QMessageBox* dialog() const;

 signals:
  // The event is shown; `event.lastGoodTime` is the last step the watch passed.
  void stopped(const carom::WatchEvent& event);

 private:
  void show(const SimulationSnapshot& snapshot, bool following);

  editor::SceneDocument* document_;
  render::SceneView* view_;
  SimulationController* simulation_;
  QMainWindow* window_;
  std::uint64_t eventsShown_ = 0;  // the worker's count of events as of the last shown
  QPointer<QMessageBox> dialog_;
  // The view frames a ball the watch stopped on with this many radii around it.
  static constexpr double kFrameRadii = 8.0;
};

}  // namespace carom::ui
