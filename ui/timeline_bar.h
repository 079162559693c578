#pragma once
// The timeline under the view: a slider over every frame the run has recorded
// (sim/run_recording.h) and a line saying which moment is shown and what the recording holds.
// Dragging it, or its keys, asks for an earlier frame; the run pauses there. It keeps the
// recording's memory budget (a setting, Simulation > Timeline Memory).

#include <QString>
#include <QWidget>

#include <cstddef>
#include <cstdint>

class QLabel;
class QSlider;

namespace carom::ui {

struct SimulationSnapshot;

class TimelineBar : public QWidget {
  Q_OBJECT
 public:
  explicit TimelineBar(QWidget* parent = nullptr);

  void showSnapshot(const SimulationSnapshot& snapshot);

  // The recording's memory budget in bytes, as stored (the default when unset or out of range).
  static std::size_t memoryBudget();
  static constexpr int kMinMemoryMebibytes = 16;
  static constexpr int kMaxMemoryMebibytes = 65536;
  // Simulation > Timeline Memory: asks for the budget over the window, stores it and says so.
  void askMemoryBudget();

 signals:
  void frameRequested(std::uint64_t frame);
  void memoryBudgetChanged(std::size_t bytes);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  // The line beside the slider for these numbers.
  static QString line(double time, std::uint64_t frame, std::uint64_t frameCount,
                      std::uint64_t keyframes, std::size_t bytes, double scrubMilliseconds);

  QSlider* slider_;
  QLabel* label_;
  // Frames per slider step: a slider counts in ints, a long run at a small step may not.
  std::uint64_t framesPerStep_ = 1;
  std::uint64_t frame_ = 0, frameCount_ = 0, keyframes_ = 0;
  double time_ = 0.0, scrubMilliseconds_ = 0.0;
  std::size_t bytes_ = 0;
};

}  // namespace carom::ui
