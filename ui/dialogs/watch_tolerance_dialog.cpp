#include "ui/dialogs/watch_tolerance_dialog.h"

#include "ui/number_box.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace carom::ui {

WatchToleranceDialog::WatchToleranceDialog(const WatchSettings& settings, QWidget* parent)
    : QDialog(parent), settings_(settings) {
  setWindowTitle(tr("Watch Tolerances"));
  const auto box = [this](const QString& name, const char* objectName, double value) {
    auto* number = new NumberBox(name, 0.0, kMaxWatchTolerance, 0.01);
    number->setObjectName(objectName);
    number->setValue(value);
    connect(number, &NumberBox::refused, this, [this](const QString& message) {
      problem_->setText(message);
      problem_->show();
    });
    connect(number, &QDoubleSpinBox::valueChanged, this, [this] { problem_->hide(); });
    return number;
  };
  energyRise_ = box(tr("Energy rise"), "watchEnergyRise", settings.energyRiseTolerance);
  energyRise_->setToolTip(
      tr("How far the total energy may rise above its value at the start, "
         "as a fraction of the scene's energy scale (kinetic energy plus "
         "the balls' weight times the scene's height)"));
  escape_ = box(tr("Escape depth"), "watchEscape", settings.escapeTolerance);
  escape_->setToolTip(
      tr("How far a ball's centre may be past a solid's surface, as a fraction of its radius"));
  penetration_ = box(tr("Penetration"), "watchPenetration", settings.penetrationTolerance);
  penetration_->setToolTip(tr("How deep an overlap may be, as a fraction of the smaller radius"));

  auto* form = new QFormLayout;
  form->addRow(tr("Energy rise:"), energyRise_);
  form->addRow(tr("Escape depth:"), escape_);
  form->addRow(tr("Penetration:"), penetration_);
  problem_ = new QLabel;
  problem_->setObjectName("watchProblem");
  problem_->setWordWrap(true);
  problem_->hide();
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                       QDialogButtonBox::RestoreDefaults);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
          &WatchToleranceDialog::restoreDefaults);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons);
}

WatchSettings WatchToleranceDialog::settings() const {
  WatchSettings settings = settings_;
  settings.energyRiseTolerance = energyRise_->value();
  settings.escapeTolerance = escape_->value();
  settings.penetrationTolerance = penetration_->value();
  return settings;
}

QString WatchToleranceDialog::problem() const {
  return problem_->isHidden() ? QString() : problem_->text();
}

void WatchToleranceDialog::restoreDefaults() {
  const WatchSettings defaults;
  energyRise_->setValue(defaults.energyRiseTolerance);
  escape_->setValue(defaults.escapeTolerance);
  penetration_->setValue(defaults.penetrationTolerance);
}

}  // namespace carom::ui
