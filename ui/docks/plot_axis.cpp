#include "ui/docks/plot_axis.h"

#include "ui/editor/number_text.h"

#include <QChart>
#include <QGraphicsLayout>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <cmath>

namespace carom::ui {

void fitToDock(QChart* chart) {
  constexpr int kMargin = 4;
  chart->setMargins(QMargins(kMargin, kMargin, kMargin, 0));
  chart->layout()->setContentsMargins(0, 0, 0, 0);
  chart->setBackgroundRoundness(0);
}

void localizeNumbers(QChart* chart) {
  chart->setLocale(editor::numberLocale());
  chart->setLocalizeNumbers(true);
}

void setRoundRange(QValueAxis* axis, double low, double high, int maxTicks) {
  const double span = high - low;
  if (!(span > 0.0) || !std::isfinite(span)) {
    axis->setRange(low, high);
    return;
  }
  const double least = span / std::max(1, maxTicks - 1);
  const int exponent = int(std::floor(std::log10(least)));
  const double power = std::pow(10.0, exponent);
  // The first round step with no more ticks than allowed.
  constexpr std::array<double, 5> kMantissas = {1.0, 2.0, 2.5, 5.0, 10.0};
  double mantissa = kMantissas.back();
  for (double candidate : kMantissas) {
    if (candidate * power >= least * (1.0 - 1e-9)) {
      mantissa = candidate;
      break;
    }
  }
  const double step = mantissa * power;
  // 2.5 x 10^k needs one decimal more than 10^k, below ten.
  const int decimals = std::max(0, -exponent - (mantissa == 10.0 ? 1 : 0)) +
                       (mantissa == 2.5 && exponent < 1 ? 1 : 0);
  // The chart lays its ticks out as each setting changes: between the old range and step and
  // the new ones, it never goes through more ticks than either has (a small step over a long
  // range would be millions), nor through a step of 0 (Qt's default, for ever).
  const bool finer = axis->tickType() == QValueAxis::TicksDynamic && step < axis->tickInterval();
  if (finer) axis->setRange(low, high);
  axis->setTickAnchor(0.0);
  axis->setTickInterval(step);
  axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
  axis->setTickType(QValueAxis::TicksDynamic);
  if (!finer) axis->setRange(low, high);
}

}  // namespace carom::ui
