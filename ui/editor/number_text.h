#pragma once

// Numbers as the editor shows and reads them, shared by the properties dock and the toolbar.

#include <QLocale>
#include <QString>

#include <optional>

namespace carom::editor {

// The user's locale without group separators.
QLocale numberLocale();

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
