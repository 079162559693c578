#pragma once
// Method "auto" in the window: the pilot of sim/method_choice.h, run off the GUI thread on the
// document's scene whenever auto is chosen or its accuracy changes. The cheapest setting that
// meets the accuracy becomes the world's method, integrator and step (one undo step), and the
// status line says what was chosen and why; when none meets it, the settings stay as they are.

#include "sim/method_choice.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <atomic>
#include <memory>

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

  bool active() const { return active_; }
  // On: pilots the scene now; off: forgets a pilot under way.
  void setActive(bool on);
  const AccuracyTolerance& tolerance() const { return tolerance_; }
  // Valid (validateTolerance); pilots again when active.
  void setTolerance(const AccuracyTolerance& tolerance);
  bool choosing() const { return running_ != nullptr; }

 signals:
  void choosingStarted();
  // What was chosen and why, or why nothing was, for the status line.
  void finished(const QString& status);

 private:
  struct Pilot;
  void pilot();
  void apply(const std::shared_ptr<Pilot>& pilot);

  editor::SceneDocument* document_;
  bool active_ = false;
  AccuracyTolerance tolerance_;
  std::shared_ptr<Pilot> running_;  // the pilot whose result counts
  CallQueue* calls_;                // a child: the pilot's report, run on this object's thread
  QThreadPool pool_;
};

}  // namespace carom::ui
