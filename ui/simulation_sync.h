#pragma once
// Keeps the simulation in step with the document, as the document reports its changes: new
// world settings go to the running simulation as they are; a change of the objects restarts it
// from the edited scene or, when edits apply to the running state, with every ball the edit
// left alone where the run has it.

#include "sim/scene.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>

namespace carom::editor {
class SceneDocument;
struct SceneChange;
}  // namespace carom::editor
namespace carom::ui {

class SimulationController;

class SimulationSync : public QObject {
  Q_OBJECT
 public:
  SimulationSync(editor::SceneDocument* document, SimulationController* simulation,
                 QObject* parent = nullptr);

  void setApplyToRunningState(bool on) { applyToRunningState_ = on; }

 signals:
  // The simulation restarted from `start` (the view draws its objects).
  void restarted(std::shared_ptr<const carom::Scene> start);
  void message(const QString& text);

 private:
  void documentChanged(const editor::SceneChange& change);
  Scene withRunningState(const editor::SceneChange& change);

  editor::SceneDocument* document_;
  SimulationController* simulation_;
  bool applyToRunningState_ = false;
  std::shared_ptr<const Scene> start_;  // the scene the simulation last started from
  std::uint64_t startNumber_ = 0;       // the controller's number for start_
};

}  // namespace carom::ui
