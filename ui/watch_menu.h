#pragma once
// Simulation > Watch: each check of the run watch on or off, and its tolerances, remembered
// with QSettings across sessions.

#include "sim/measure/run_watch.h"

#include <QMenu>

class QAction;

namespace carom::ui {

class WatchMenu : public QMenu {
  Q_OBJECT
 public:
  explicit WatchMenu(QWidget* parent = nullptr);

  const carom::WatchSettings& settings() const { return settings_; }
  // Valid settings, remembered and announced; invalid ones are refused (false).
  bool setSettings(const carom::WatchSettings& settings);
  // Opens the tolerances dialog and takes what it gives.
  void editTolerances();
  QAction* checkAction(carom::WatchKind kind) const { return checks_[int(kind)]; }

 signals:
  void settingsChanged(const carom::WatchSettings& settings);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void showSettings();

  carom::WatchSettings settings_;
  QAction* checks_[carom::kWatchKindCount] = {};
  QAction* tolerances_ = nullptr;
};

}  // namespace carom::ui
