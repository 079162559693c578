#include "ui/number_box.h"

#include "ui/editor/number_text.h"

#include <QFontMetrics>
#include <QLineEdit>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace carom::ui {

NumberBox::NumberBox(const QString& name, double low, double high, double step, QWidget* parent)
    : QDoubleSpinBox(parent), name_(name) {
  // Qt's largest precision: values are never rounded, and textFromValue() decides the digits.
  setDecimals(std::numeric_limits<double>::max_exponent10 + std::numeric_limits<double>::digits10);
  setRange(low, high);
  setSingleStep(step);
  setKeyboardTracking(false);  // apply a typed value when it is complete, not per digit
  connect(this, &QAbstractSpinBox::editingFinished, this, &NumberBox::reportRefusal);
  // A refusal that was not reported before the value changed some other way is moot.
  connect(this, &QDoubleSpinBox::valueChanged, this, [this] { refusedText_ = QString(); });
}

QString NumberBox::problem(const QString& text) const {
  const editor::ParsedNumber parsed = editor::parseNumber(text);
  if (!parsed.value) return parsed.problem;
  const double value = *parsed.value;
  if (!std::isfinite(value)) return tr("must be finite (got %1)").arg(text.trimmed());
  if (value < minimum() || value > maximum())
    return tr("must be between %1 and %2 (got %3)")
        .arg(editor::formatNumber(minimum()), editor::formatNumber(maximum()),
             editor::formatNumber(value));
  return {};
}

QValidator::State NumberBox::validate(QString& text, int&) const {
  // Anything may be typed; what cannot be taken is refused when editing finishes, with a reason.
  return problem(text).isEmpty() ? QValidator::Acceptable : QValidator::Intermediate;
}

void NumberBox::fixup(QString& text) const {
  refusedText_ = text;
}

double NumberBox::valueFromText(const QString& text) const {
  // The value is shown to six digits; its own text stands for the exact value, so that leaving
  // the box untouched does not round it.
  if (text == textFromValue(value())) return value();
  return editor::parseNumber(text).value.value_or(value());
}

QString NumberBox::textFromValue(double value) const {
  return editor::formatShortNumber(value);
}

QSize NumberBox::sizeHint() const {
  // Qt sizes the box for the range's ends; size it for a typical value instead.
  QSize size = QDoubleSpinBox::sizeHint();
  const QFontMetrics metrics = fontMetrics();
  const int ends = std::max(metrics.horizontalAdvance(textFromValue(minimum()) + ' '),
                            metrics.horizontalAdvance(textFromValue(maximum()) + ' '));
  size.rwidth() += metrics.horizontalAdvance(QStringLiteral("-0.0166667 ")) - ends;
  return size;
}

void NumberBox::focusOutEvent(QFocusEvent* event) {
  QDoubleSpinBox::focusOutEvent(event);
  // The box keeps the cursor where typing left it, at the end, and a text wider than the box
  // would then hide its sign and leading digits; new values keep the cursor at the start.
  lineEdit()->setCursorPosition(0);
}

void NumberBox::reportRefusal() {
  if (refusedText_.isNull()) return;
  const QString text = std::exchange(refusedText_, QString());
  const QString why = problem(text);
  if (!why.isEmpty()) emit refused(tr("%1: %2").arg(name_, why));
}

}  // namespace carom::ui
