#pragma once
// Keeps the simulation in step with the document, as the document reports its changes: new
// world settings go to the running simulation as they are; a change of the objects restarts it
// from the edited scene or, when edits apply to the running state, with every ball the edit
// left alone where the run has it.

#include "sim/model/scene.h"
#include "sim/validation/validation.h"

#include <QObject>
#include <QString>

#include <cstddef>
#include <future>
#include <memory>
#include <optional>

namespace carom::editor {
class SceneDocument;
struct SceneChange;
}  // namespace carom::editor
namespace carom::ui {

class CallQueue;
class RunSession;
struct SimulationSnapshot;

class SimulationSync : public QObject {
  Q_OBJECT
 public:
  // From this many balls on, the scene a restart starts from is made on a thread of its own, and
  // the restart follows when it is made: copying a million balls took the GUI thread 0.9-1.5 s
  // at every edit. The document waits for it before it changes again.
  static constexpr std::size_t kBackgroundBalls = 50'000;

  // Restarts `run` (its restarted() says so) with each change of the document's objects.
  SimulationSync(editor::SceneDocument* document, RunSession* run, QObject* parent = nullptr);
  ~SimulationSync() override;

  void setApplyToRunningState(bool on) { applyToRunningState_ = on; }

 signals:
  void message(const QString& text);

 private:
  // A scene to start from, and why it is the edited scene as it is when the running state did
  // not fit (worded on the GUI thread, naming the objects of `scene`).
  struct Start {
    std::shared_ptr<const Scene> scene;
    std::optional<ValidationError> unfitRunningState;
  };
  static Start makeStart(const Scene& edited, const editor::SceneChange& change,
                         const std::shared_ptr<const Scene>& runningFrom,
                         const std::shared_ptr<const SimulationSnapshot>& snapshot);

  void documentChanged(const editor::SceneChange& change);
  // Waits for the start being made, if any, and restarts from it.
  void finishStart();
  // The start being made, once it is made; nothing when it is not.
  void startMade();
  void restart(Start start);

  editor::SceneDocument* document_;
  RunSession* run_;
  bool applyToRunningState_ = false;
  std::shared_ptr<const Scene> start_;  // the scene the simulation last started from
  std::future<Start> pendingStart_;     // being made from the document, on its own thread
  CallQueue* calls_;                    // a child: the thread's notice that its start is made
};

}  // namespace carom::ui
