#include "ui/editor/number_text.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace carom::editor {

QLocale numberLocale() {
  QLocale locale;
  locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
  return locale;
}

QString formatNumber(double value, char format, int precision) {
  const QLocale locale = numberLocale();
  QString text = locale.toString(value, format, precision);
  const QString exponent = locale.exponential();
  return text.replace(exponent, exponent.toLower());
}

QString formatNumber(double value) {
  return formatNumber(value, 'g', QLocale::FloatingPointShortest);
}

QString formatShortNumber(double value) {
  constexpr int kShownDigits = 6;
  return formatNumber(value, 'g', kShownDigits);
}

ParsedNumber parseNumber(const QString& typed) {
  const QString text = typed.trimmed();
  bool ok = false;
  const double value = numberLocale().toDouble(text, &ok);
  if (ok) return {value, {}};
  QLocale c = QLocale::c();
  c.setNumberOptions(QLocale::RejectGroupSeparator);
  const double inC = c.toDouble(text, &ok);
  if (ok) return {inC, {}};
  // Written as a number, but beyond what a double holds (1e400, 1e-400).
  static const QRegularExpression numeral(R"(^[+-]?(\d+([.,]\d*)?|[.,]\d+)[eE][+-]?\d+$)");
  if (numeral.match(text).hasMatch())
    return {std::nullopt,
            QCoreApplication::translate("NumberText", "“%1” is out of range").arg(text)};
  return {std::nullopt,
          QCoreApplication::translate("NumberText", "“%1” is not a number").arg(text)};
}

}  // namespace carom::editor
