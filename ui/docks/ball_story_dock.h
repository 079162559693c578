#pragma once
// The Ball story dock: for the selected balls (the first kMaxBalls of them), a plot of height,
// speed or energy against simulated time, and their trails and velocity arrows in the view. Fed
// from the snapshots the window shows; the samples live in a BallStory, not in the widgets.
//
// The shown time is the newest snapshot's until showTime() pins an earlier moment (the
// timeline's scrubbing): the plot then marks that moment and the trails end there. The next
// snapshot of a later or an earlier time (the run going on, or resumed from a rewound moment,
// which discards the story after it) follows the newest again.

#include "sim/model/scene.h"
#include "ui/docks/ball_story.h"

#include <QDockWidget>
#include <QList>
#include <QPointF>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QChart;
class QComboBox;
class QLabel;
class QLineSeries;
class QValueAxis;

namespace carom::editor {
class SceneDocument;
}
namespace carom::render {
class SceneView;
}
namespace carom::ui {

struct SimulationSnapshot;

class BallStoryDock : public QDockWidget {
  Q_OBJECT
 public:
  // More selected balls than this are left out of the story (the dock says so): a plot of more
  // lines reads as noise and each costs the GUI thread a little on every snapshot.
  static constexpr int kMaxBalls = 8;
  // How far back the trails in the view reach, in simulated seconds.
  static constexpr double kTrailSeconds = 3.0;
  // A velocity arrow is as long as the ball travels in this time at that velocity.
  static constexpr double kArrowSeconds = 0.25;

  enum class Quantity { Height, Speed, Energy };

  BallStoryDock(editor::SceneDocument* document, render::SceneView* view,
                QWidget* parent = nullptr);
  ~BallStoryDock() override;

  // Records the watched balls' states from a snapshot of the current start (RunSession: the
  // window calls restart() when a new one begins); one of an earlier time (Reset) truncates the
  // story there.
  void add(std::shared_ptr<const SimulationSnapshot> snapshot);
  // The timeline: shows the story at `time` (the plot's cursor, the trails up to it, the arrows
  // at the state then). Kept until a snapshot of another time arrives, or showLatest().
  void showTime(double time);
  void showLatest();
  double shownTime() const;
  // The timeline resumed from `time`: what was recorded after it is discarded.
  void truncateAfter(double time);
  // Forgets every sample and the last snapshot (the watched balls stay watched): the
  // simulation starts again, from a new or edited scene.
  void restart();

  const BallStory& story() const { return story_; }
  Quantity quantity() const;
  void setQuantity(Quantity quantity);
  // The plot as drawn: one series per watched ball, in the story's order, and the cursor's time.
  int seriesCount() const;
  QList<QPointF> seriesPoints(int index) const;
  double cursorTime() const;
  QString note() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void watchSelection();
  void showNote();
  // The trails and velocity arrows of the shown time, to the view.
  void updateView();
  // Rebuilds the plot's series from the story (at most every kRedrawMilliseconds).
  void schedulePlot();
  void plot();
  double value(int ball, const BallStory::Sample& sample) const;

  editor::SceneDocument* document_;
  render::SceneView* view_;
  BallStory story_;
  std::optional<double> pinnedTime_;
  std::shared_ptr<const SimulationSnapshot> latest_;
  Vec3 gravity_ = Vec3::Zero();
  int selectedBalls_ = 0;

  QComboBox* quantity_;
  QLabel* note_;
  QChart* chart_;
  QValueAxis* timeAxis_;
  QValueAxis* valueAxis_;
  QLineSeries* cursor_;
  std::vector<QLineSeries*> series_;  // one per watched ball
  QTimer redrawTimer_;
};

}  // namespace carom::ui
