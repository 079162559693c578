#pragma once

// Numbers as the window shows and reads them: the docks, the toolbar, the status line, the
// timeline and the plots all write them in the language's locale through these.

#include <QLocale>
#include <QString>

#include <optional>

namespace carom::editor {

// The user's locale without group separators.
QLocale numberLocale();

// `value` in the user's locale as QLocale::toString() writes it, with a lower-case exponent
// ("-1e+12"): the locales' own capital E reads as a digit at a glance.
QString formatNumber(double value, char format, int precision);

// The shortest text that reads back as the same double.
QString formatNumber(double value);
// Six significant digits, for reading at a glance (the stored value is not rounded).
QString formatShortNumber(double value);

// A number typed in, or why it is not one.
struct ParsedNumber {
  std::optional<double> value;
  QString problem;
};

// Reads the user's locale or the C locale ("0,5" and "0.5" both work in German). "nan" and
// "inf" read as numbers: whoever checks the value says why they are refused.
ParsedNumber parseNumber(const QString& typed);

}  // namespace carom::editor
