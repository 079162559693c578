#pragma once
// Simulation > Watch > Tolerances: the run watch's three tolerances in number boxes. A value
// the boxes cannot take is refused with its reason and changes nothing.

#include "sim/measure/run_watch.h"

#include <QDialog>

class QLabel;

namespace carom::ui {

class NumberBox;

class WatchToleranceDialog : public QDialog {
  Q_OBJECT
 public:
  WatchToleranceDialog(const carom::WatchSettings& settings, QWidget* parent = nullptr);
  // The settings given, with the tolerances shown.
  carom::WatchSettings settings() const;
  NumberBox* energyRiseBox() const { return energyRise_; }
  NumberBox* escapeBox() const { return escape_; }
  NumberBox* penetrationBox() const { return penetration_; }
  QString problem() const;  // the last refusal shown, empty when none

 private:
  void restoreDefaults();

  carom::WatchSettings settings_;
  NumberBox* energyRise_;
  NumberBox* escape_;
  NumberBox* penetration_;
  QLabel* problem_;
};

}  // namespace carom::ui
