#include "ui/docks/ball_story_dock.h"

#include "sim/dynamics/energy.h"
#include "ui/docks/plot_axis.h"
#include "ui/editor/object_ref.h"
#include "ui/editor/scene_document.h"
#include "ui/render/scene_view.h"
#include "ui/run/simulation_snapshot.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::ui {
namespace {

// Redrawing the chart for every snapshot would cost the GUI thread several milliseconds a
// frame; the plot catches up at this pace instead.
constexpr int kRedrawMilliseconds = 150;
// At most about this many points a line: the story may hold thousands of samples a ball.
constexpr int kPlotPoints = 600;
// At most this many ticks an axis: their labels stay whole at the dock's opening size.
constexpr int kTimeTicks = 6;
constexpr int kValueTicks = 5;

QColor ballColor(const Scene& scene, int ball) {
  const QColor color(QString::fromStdString(scene.balls[ball].color));
  return color.isValid() ? color : QColor(Qt::gray);
}

// Halfway to white from the ball's colour, so that a dark ball's trail shows against the dark
// background and the velocity arrows (white) stand apart from it.
QColor trailColor(const QColor& ball) {
  return QColor((ball.red() + 255) / 2, (ball.green() + 255) / 2, (ball.blue() + 255) / 2);
}

}  // namespace

BallStoryDock::BallStoryDock(editor::SceneDocument* document, render::SceneView* view,
                             QWidget* parent)
    : QDockWidget(parent),
      document_(document),
      view_(view),
      quantity_(new QComboBox),
      note_(new QLabel),
      chart_(new QChart),
      timeAxis_(new QValueAxis),
      valueAxis_(new QValueAxis),
      cursor_(new QLineSeries) {
  setObjectName("ballStoryDock");
  quantity_->setObjectName("storyQuantity");
  quantity_->addItems({QString(), QString(), QString()});  // named by retranslate()
  note_->setWordWrap(true);
  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(valueAxis_, Qt::AlignLeft);
  chart_->legend()->setAlignment(Qt::AlignRight);
  fitToDock(chart_);
  chart_->addSeries(cursor_);
  cursor_->attachAxis(timeAxis_);
  cursor_->attachAxis(valueAxis_);
  cursor_->setPen(QPen(QColor(120, 120, 120), 1.5, Qt::DashLine));
  chart_->legend()->markers(cursor_).constFirst()->setVisible(false);
  auto* chartView = new QChartView(chart_);
  chartView->setRenderHint(QPainter::Antialiasing);
  auto* content = new QWidget;
  auto* top = new QHBoxLayout;
  top->addWidget(quantity_);
  top->addWidget(note_, 1);
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(4, 4, 4, 0);
  layout->addLayout(top);
  layout->addWidget(chartView, 1);
  setWidget(content);
  redrawTimer_.setSingleShot(true);
  redrawTimer_.setInterval(kRedrawMilliseconds);
  connect(&redrawTimer_, &QTimer::timeout, this, &BallStoryDock::plot);
  connect(quantity_, &QComboBox::currentIndexChanged, this, &BallStoryDock::plot);
  connect(document_, &editor::SceneDocument::selectionChanged, this,
          &BallStoryDock::watchSelection);
  retranslate();
  watchSelection();
}

BallStoryDock::~BallStoryDock() = default;

void BallStoryDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void BallStoryDock::retranslate() {
  setWindowTitle(tr("Ball Story"));
  localizeNumbers(chart_);
  quantity_->setItemText(int(Quantity::Height), tr("Height (m)"));
  quantity_->setItemText(int(Quantity::Speed), tr("Speed (m/s)"));
  quantity_->setItemText(int(Quantity::Energy), tr("Energy (J)"));
  quantity_->setToolTip(
      tr("Height is measured against gravity (along y when there is none); energy is the ball's "
         "kinetic energy plus its potential energy relative to the origin."));
  // The value axis has no title: the chooser above names the quantity and its unit, and a dock
  // as low as the Energy one leaves a vertical title no room.
  timeAxis_->setTitleText(tr("Simulated time (s)"));
  showNote();
  plot();  // the series' names
}

void BallStoryDock::showNote() {
  if (selectedBalls_ == 0) {
    note_->setText(tr("Select balls to follow them: their story starts when they are selected."));
  } else if (selectedBalls_ > kMaxBalls) {
    note_->setText(tr("Showing the first %1 of %2 selected balls; each story starts when the "
                      "ball is selected.")
                       .arg(kMaxBalls)
                       .arg(selectedBalls_));
  } else {
    note_->setText(tr("Each ball's story starts when it is selected."));
  }
}

QString BallStoryDock::note() const {
  return note_->text();
}

void BallStoryDock::watchSelection() {
  std::vector<int> balls;
  selectedBalls_ = 0;
  for (const editor::ObjectRef& ref : document_->selection()) {
    if (ref.kind != editor::ObjectKind::Ball) continue;
    ++selectedBalls_;
    if (static_cast<int>(balls.size()) < kMaxBalls) balls.push_back(ref.index);
  }
  story_.watch(balls);
  // Balls new to the story start from the state the view shows now.
  if (latest_) story_.record(latest_->time, latest_->positions, latest_->velocities);
  showNote();
  updateView();
  plot();
}

void BallStoryDock::add(std::shared_ptr<const SimulationSnapshot> snapshot) {
  if (!snapshot) return;
  if (story_.lastTime() != snapshot->time) pinnedTime_.reset();
  gravity_ = snapshot->world.gravity;
  story_.record(snapshot->time, snapshot->positions, snapshot->velocities);
  latest_ = std::move(snapshot);
  updateView();
  schedulePlot();
}

void BallStoryDock::showTime(double time) {
  pinnedTime_ = time;
  updateView();
  plot();
}

void BallStoryDock::showLatest() {
  pinnedTime_.reset();
  updateView();
  plot();
}

double BallStoryDock::shownTime() const {
  return pinnedTime_.value_or(story_.lastTime().value_or(0.0));
}

void BallStoryDock::truncateAfter(double time) {
  story_.truncateAfter(time);
  updateView();
  plot();
}

void BallStoryDock::restart() {
  story_.clear();
  pinnedTime_.reset();
  // Its positions belong to the start before: balls selected now wait for the new start's.
  latest_.reset();
  updateView();
  plot();
}

void BallStoryDock::updateView() {
  const Scene& scene = document_->scene();
  const double t = shownTime();
  std::vector<render::SceneView::Trail> trails;
  std::vector<render::SceneView::Arrow> arrows;
  for (int ball : story_.watched()) {
    if (ball >= static_cast<int>(scene.balls.size())) continue;
    std::vector<Vec3> path = story_.path(ball, t - kTrailSeconds, t);
    if (path.size() >= 2) trails.push_back({std::move(path), trailColor(ballColor(scene, ball))});
    // At the start the editor's handle already shows the initial velocity.
    const std::optional<BallStory::Sample> state = story_.stateAt(ball, t);
    if (state && state->time > 0.0)
      arrows.emplace_back(state->position, state->position + kArrowSeconds * state->velocity);
  }
  view_->setTrails(std::move(trails));
  view_->setVelocityArrows(std::move(arrows));
}

BallStoryDock::Quantity BallStoryDock::quantity() const {
  return static_cast<Quantity>(quantity_->currentIndex());
}

void BallStoryDock::setQuantity(Quantity quantity) {
  quantity_->setCurrentIndex(int(quantity));
}

double BallStoryDock::value(int ball, const BallStory::Sample& sample) const {
  switch (quantity()) {
    case Quantity::Height: {
      // Up is against gravity; without gravity, the editor's up (y).
      const double g = gravity_.norm();
      return g > 0.0 ? -gravity_.dot(sample.position) / g : sample.position.y();
    }
    case Quantity::Speed:
      return sample.velocity.norm();
    case Quantity::Energy: {
      const double mass = document_->scene().balls[ball].mass;
      return ballKineticEnergy(mass, sample.velocity) +
             ballPotentialEnergy(mass, gravity_, sample.position);
    }
  }
  return 0.0;
}

void BallStoryDock::schedulePlot() {
  if (!redrawTimer_.isActive()) redrawTimer_.start();
}

void BallStoryDock::plot() {
  redrawTimer_.stop();
  const Scene& scene = document_->scene();
  const std::vector<int>& balls = story_.watched();
  while (series_.size() > balls.size()) {
    chart_->removeSeries(series_.back());
    delete series_.back();
    series_.pop_back();
  }
  while (series_.size() < balls.size()) {
    auto* series = new QLineSeries;
    chart_->addSeries(series);
    series->attachAxis(timeAxis_);
    series->attachAxis(valueAxis_);
    series_.push_back(series);
  }
  double first = std::numeric_limits<double>::infinity();
  double last = -first, low = first, high = -first;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const int ball = balls[k];
    QLineSeries* series = series_[k];
    if (ball >= static_cast<int>(scene.balls.size())) {
      series->clear();
      continue;
    }
    // Elided here: the legend's own shortening of a long name costs memory as its square.
    series->setName(editor::elidedName(editor::objectLabel(scene, {editor::ObjectKind::Ball, ball}),
                                       chart_->legend()->font()));
    series->setColor(ballColor(scene, ball));
    const std::deque<BallStory::Sample>& samples = story_.samples(ball);
    QList<QPointF> points;
    if (!samples.empty()) {
      // Thinned evenly in time; the newest sample always ends the line.
      const double spacing = (samples.back().time - samples.front().time) / kPlotPoints;
      double next = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const BallStory::Sample& sample = samples[i];
        if (sample.time < next && i + 1 < samples.size()) continue;
        next = sample.time + spacing;
        const double y = value(ball, sample);
        points.append(QPointF(sample.time, y));
        low = std::min(low, y);
        high = std::max(high, y);
      }
      first = std::min(first, samples.front().time);
      last = std::max(last, samples.back().time);
    }
    series->replace(points);
  }
  if (!std::isfinite(first)) first = last = 0.0;
  if (!std::isfinite(low)) low = high = 0.0;
  const double t = shownTime();
  setRoundRange(timeAxis_, first, std::max({first + 1.0, last, t}), kTimeTicks);
  const double margin = 0.05 * std::max(high - low, 1e-9);
  setRoundRange(valueAxis_, low - margin, high + margin, kValueTicks);
  cursor_->replace({QPointF(t, low - margin), QPointF(t, high + margin)});
}

int BallStoryDock::seriesCount() const {
  return static_cast<int>(series_.size());
}

QList<QPointF> BallStoryDock::seriesPoints(int index) const {
  return series_.at(index)->points();
}

double BallStoryDock::cursorTime() const {
  return cursor_->count() > 0 ? cursor_->at(0).x() : 0.0;
}

}  // namespace carom::ui
