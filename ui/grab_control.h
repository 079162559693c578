#pragma once
// Grabbing balls in the running world (sim/grab.h): hands the Select tool's grabs to the
// simulation, keeps the throw limit (a setting), and says when a grab stopped or a throw was
// cut to the limit.

#include "sim/model/scene.h"

#include <QObject>
#include <QString>

class QWidget;

#include <optional>

namespace carom::editor {
class EditorTools;
}
namespace carom::ui {

class RunSession;
struct SimulationSnapshot;

class GrabControl : public QObject {
  Q_OBJECT
 public:
  GrabControl(editor::EditorTools* tools, RunSession* run, QObject* parent = nullptr);

  // Simulated m/s; a throw faster than this is cut to it.
  double throwLimit() const { return throwLimit_; }
  void setThrowLimit(double speed);
  // Simulation > Throw Speed Limit: asks for the limit over `parent`.
  void askThrowLimit(QWidget* parent);
  static constexpr double kMinThrowLimit = 1e-6;
  static constexpr double kMaxThrowLimit = 1e9;

  // Each snapshot the window shows: a run in progress lets the Select tool grab its balls.
  void showSnapshot(const SimulationSnapshot& snapshot);

 signals:
  void message(const QString& text);

 private:
  // Escape during a grab. Paused, the grab is undone: the ball goes back to where it was taken
  // and keeps the velocity it had. Running, it is let go where it is, at rest: the run is not
  // taken back in time (the timeline does that).
  void cancelGrab();

  editor::EditorTools* tools_;
  RunSession* run_;
  double throwLimit_;
  std::optional<double> lastStopTime_;  // the stop last said, so it is said once
  bool throwCapped_ = false;
  // The held ball as it was when taken in a paused run.
  struct Held {
    Vec3 position;
    Vec3 velocity;
  };
  std::optional<Held> heldFrom_;
};

}  // namespace carom::ui
