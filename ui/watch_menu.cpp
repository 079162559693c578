#include "ui/watch_menu.h"

#include "ui/dialogs/watch_tolerance_dialog.h"

#include <QAction>
#include <QEvent>
#include <QSettings>

namespace carom::ui {
namespace {

QString key(const char* field) {
  return QString("watch/") + field;
}

QString kindName(WatchKind kind) {
  const std::string_view name = watchKindName(kind);
  return QString::fromUtf8(name.data(), name.size());
}

// The remembered settings; the defaults for any that are missing or that a hand-edited file
// made invalid.
WatchSettings loadSettings() {
  QSettings stored;
  WatchSettings settings;
  for (int k = 0; k < kWatchKindCount; ++k) {
    const WatchKind kind = WatchKind(k);
    settings.enabled(kind) =
        stored.value(key("on/") + kindName(kind), settings.enabled(kind)).toBool();
  }
  settings.energyRiseTolerance =
      stored.value(key("energyRise"), settings.energyRiseTolerance).toDouble();
  settings.escapeTolerance = stored.value(key("escape"), settings.escapeTolerance).toDouble();
  settings.penetrationTolerance =
      stored.value(key("penetration"), settings.penetrationTolerance).toDouble();
  if (!validateWatchSettings(settings).empty()) {
    const WatchSettings defaults;
    settings.energyRiseTolerance = defaults.energyRiseTolerance;
    settings.escapeTolerance = defaults.escapeTolerance;
    settings.penetrationTolerance = defaults.penetrationTolerance;
  }
  return settings;
}

void saveSettings(WatchSettings settings) {
  QSettings stored;
  for (int k = 0; k < kWatchKindCount; ++k)
    stored.setValue(key("on/") + kindName(WatchKind(k)), settings.enabled(WatchKind(k)));
  stored.setValue(key("energyRise"), settings.energyRiseTolerance);
  stored.setValue(key("escape"), settings.escapeTolerance);
  stored.setValue(key("penetration"), settings.penetrationTolerance);
}

}  // namespace

WatchMenu::WatchMenu(QWidget* parent) : QMenu(parent), settings_(loadSettings()) {
  setObjectName("watchMenu");
  for (int k = 0; k < kWatchKindCount; ++k) {
    const WatchKind kind = WatchKind(k);
    QAction* action = addAction(QString());
    action->setObjectName("watch:" + kindName(kind));
    action->setCheckable(true);
    connect(action, &QAction::triggered, this, [this, kind](bool on) {
      WatchSettings settings = settings_;
      settings.enabled(kind) = on;
      setSettings(settings);
    });
    checks_[k] = action;
  }
  addSeparator();
  tolerances_ = addAction(QString(), this, &WatchMenu::editTolerances);
  tolerances_->setObjectName("watchTolerances");
  showSettings();
  retranslate();
}

bool WatchMenu::setSettings(const WatchSettings& settings) {
  if (!validateWatchSettings(settings).empty()) {
    showSettings();
    return false;
  }
  settings_ = settings;
  saveSettings(settings_);
  showSettings();
  emit settingsChanged(settings_);
  return true;
}

void WatchMenu::editTolerances() {
  WatchToleranceDialog dialog(settings_, parentWidget());
  if (dialog.exec() == QDialog::Accepted) setSettings(dialog.settings());
}

void WatchMenu::showSettings() {
  WatchSettings settings = settings_;
  for (int k = 0; k < kWatchKindCount; ++k) checks_[k]->setChecked(settings.enabled(WatchKind(k)));
}

void WatchMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void WatchMenu::retranslate() {
  setTitle(tr("&Watch"));
  setToolTipsVisible(true);
  checks_[int(WatchKind::NonFinite)]->setText(tr("Stop on &Non-finite Numbers"));
  checks_[int(WatchKind::EnergyRise)]->setText(tr("Stop on &Energy Rise"));
  checks_[int(WatchKind::EnergyRise)]->setToolTip(
      tr("Only where no restitution exceeds 1, so that energy can only fall"));
  checks_[int(WatchKind::Escape)]->setText(tr("Stop on Escape Through a &Solid"));
  checks_[int(WatchKind::Penetration)]->setText(tr("Stop on Deep &Penetration"));
  tolerances_->setText(tr("&Tolerances…"));
}

}  // namespace carom::ui
