#pragma once
// Method "auto" in the window: the pilot of sim/method_choice.h, run off the GUI thread on the
// document's scene whenever the world asks for auto anew (chosen, its tolerance changed, or a
// scene opened that was saved under auto). The cheapest setting that meets the tolerance
// becomes the world's method, integrator and step (one undo step that names it), and what was
// chosen and why is reported; when none meets it, the settings stay as they are.

#include "sim/measure/method_choice.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <atomic>
#include <memory>
#include <optional>

namespace carom::editor {
class SceneDocument;
}

namespace carom::ui {

class CallQueue;

class AutoMethod : public QObject {
  Q_OBJECT
 public:
  // A sandbox run has no end: the pilot plans for a run of this many simulated seconds.
  static constexpr double kPlannedRunSeconds = 60.0;

  AutoMethod(editor::SceneDocument* document, QObject* parent = nullptr);
  // Stops a pilot under way and waits for it.
  ~AutoMethod() override;

  // The tolerance the world asks for under auto, or the one it asked for last (what choosing
  // auto again asks for).
  const AccuracyTolerance& tolerance() const { return tolerance_; }
  bool choosing() const { return running_ != nullptr; }

 signals:
  void choosingStarted();
  // `summary` for the status line ("Auto chose swept (...)"), `explanation` the whole of what
  // was chosen and why, or why nothing was.
  void finished(const QString& summary, const QString& explanation);

 private:
  struct Pilot;
  void worldChanged(bool newScene);
  void pilot();
  void apply(const std::shared_ptr<Pilot>& pilot);

  editor::SceneDocument* document_;
  std::optional<AccuracyTolerance> asked_;  // what the world asked for when last seen
  AccuracyTolerance tolerance_;
  std::shared_ptr<Pilot> running_;  // the pilot whose result counts
  CallQueue* calls_;                // a child: the pilot's report, run on this object's thread
  QThreadPool pool_;
};

}  // namespace carom::ui
