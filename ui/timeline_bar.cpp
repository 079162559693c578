#include "ui/timeline_bar.h"

#include "sim/measure/run_recording.h"
#include "ui/editor/number_text.h"
#include "ui/run/simulation_snapshot.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QSettings>
#include <QSlider>

#include <limits>

namespace carom::ui {
namespace {

constexpr char kMemoryKey[] = "simulation/timelineMemoryMiB";
constexpr int kDefaultMebibytes = int(RunRecording::kDefaultBudgetBytes >> 20);

}  // namespace

TimelineBar::TimelineBar(QWidget* parent)
    : QWidget(parent), slider_(new QSlider(Qt::Horizontal)), label_(new QLabel) {
  setObjectName("timeline");
  slider_->setObjectName("timelineSlider");
  label_->setObjectName("timelineLabel");
  slider_->setRange(0, 0);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 0, 6, 0);
  layout->addWidget(slider_, 1);
  layout->addWidget(label_);
  // Only the user's moves ask for a frame: showSnapshot() sets the slider with signals blocked.
  connect(slider_, &QSlider::valueChanged, this, [this](int value) {
    emit frameRequested(
        std::min<std::uint64_t>(std::uint64_t(value) * framesPerStep_, frameCount_));
  });
  retranslate();
}

void TimelineBar::showSnapshot(const SimulationSnapshot& snapshot) {
  frame_ = snapshot.frame;
  frameCount_ = snapshot.frameCount;
  keyframes_ = snapshot.keyframes;
  time_ = snapshot.time;
  bytes_ = snapshot.recordingBytes;
  scrubMilliseconds_ = snapshot.frame < snapshot.frameCount ? snapshot.scrubMilliseconds : 0.0;
  const std::uint64_t maxSteps = std::numeric_limits<int>::max();
  framesPerStep_ = frameCount_ / maxSteps + 1;
  const QSignalBlocker block(slider_);
  slider_->setRange(0, int(frameCount_ / framesPerStep_));
  slider_->setPageStep(std::max(1, slider_->maximum() / 20));
  // While the user holds the slider, it stays where the hand is.
  if (!slider_->isSliderDown()) slider_->setValue(int(frame_ / framesPerStep_));
  retranslate();
}

std::size_t TimelineBar::memoryBudget() {
  bool ok = false;
  const int stored = QSettings().value(kMemoryKey, kDefaultMebibytes).toInt(&ok);
  const int mebibytes = ok && stored >= kMinMemoryMebibytes && stored <= kMaxMemoryMebibytes
                            ? stored
                            : kDefaultMebibytes;
  return std::size_t(mebibytes) << 20;
}

void TimelineBar::askMemoryBudget() {
  bool ok = false;
  const int mebibytes = QInputDialog::getInt(
      window(), tr("Timeline Memory"), tr("Memory for the recorded run (MiB):"),
      int(memoryBudget() >> 20), kMinMemoryMebibytes, kMaxMemoryMebibytes, 16, &ok);
  if (!ok) return;
  QSettings().setValue(kMemoryKey, mebibytes);
  emit memoryBudgetChanged(memoryBudget());
}

void TimelineBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void TimelineBar::retranslate() {
  slider_->setToolTip(
      tr("The recorded run: drag back to see an earlier moment; Run goes on "
         "from the moment shown and forgets what came after it."));
  // Room for the line of a long run being scrubbed, so that the slider does not shrink as the
  // numbers grow (and grow back as the replay's time comes and goes).
  label_->setMinimumWidth(label_->fontMetrics().horizontalAdvance(
      line(1000.0, 100000, 100000, 1000, std::size_t(1000) << 20, 100.0)));
  label_->setText(line(time_, frame_, frameCount_, keyframes_, bytes_, scrubMilliseconds_));
}

QString TimelineBar::line(double time, std::uint64_t frame, std::uint64_t frameCount,
                          std::uint64_t keyframes, std::size_t bytes, double scrubMilliseconds) {
  const QLocale locale;
  QString text = tr("t = %1 s · frame %2 of %3 · %4 MiB in %n keyframes", nullptr, int(keyframes))
                     .arg(editor::formatNumber(time, 'f', 3), locale.toString(qulonglong(frame)),
                          locale.toString(qulonglong(frameCount)),
                          editor::formatNumber(double(bytes) / (1 << 20), 'f', 1));
  if (scrubMilliseconds > 0.0)
    text += " · " + tr("replayed in %1 ms").arg(editor::formatNumber(scrubMilliseconds, 'f', 1));
  return text;
}

}  // namespace carom::ui
