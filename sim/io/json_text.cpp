#include "sim/io/json_text.h"

#include "sim/validation/validation.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>

namespace carom::io {

QStringList keyList(std::span<const std::string_view> keys) {
  QStringList list;
  for (std::string_view key : keys) list << QString::fromLatin1(key.data(), qsizetype(key.size()));
  return list;
}

const KnownKeys& knownKeys(int version) {
  const auto of = [](int v) {
    const format::VersionKeys keys = format::versionKeys(v);
    return KnownKeys{keyList(keys.top),      keyList(keys.world), keyList(keys.plane),
                     keyList(keys.cylinder), keyList(keys.box),   keyList(keys.ball)};
  };
  // One per version, from 1.
  static const KnownKeys kVersions[] = {of(1), of(2), of(3)};
  static_assert(std::size(kVersions) == format::kVersion);
  return kVersions[std::clamp(version, 1, format::kVersion) - 1];
}

void appendNumber(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  if (value == 0.0) {
    out += '0';
    return;
  }
  char text[32];
  const char* end =
      std::to_chars(text, text + sizeof text, value, std::chars_format::scientific).ptr;
  const char* mantissa = text[0] == '-' ? text + 1 : text;
  char digits[24];
  int count = 0;
  const char* e = mantissa;
  for (; *e != 'e'; ++e)
    if (*e != '.') digits[count++] = *e;
  int exponent = 0;
  std::from_chars(e[1] == '+' ? e + 2 : e + 1, end, exponent);
  const auto scientificLength = end - mantissa;
  const int fixedLength = exponent < 0            ? 1 - exponent + count
                          : exponent + 1 >= count ? exponent + 1
                                                  : count + 1;
  if (mantissa != text) out += '-';
  if (fixedLength > scientificLength) {
    out.append(mantissa, end);
  } else if (exponent < 0) {
    out += "0.";
    out.append(static_cast<std::size_t>(-exponent - 1), '0');
    out.append(digits, static_cast<std::size_t>(count));
  } else if (exponent + 1 >= count) {
    out.append(digits, static_cast<std::size_t>(count));
    out.append(static_cast<std::size_t>(exponent + 1 - count), '0');
  } else {
    out.append(digits, static_cast<std::size_t>(exponent + 1));
    out += '.';
    out.append(digits + exponent + 1, static_cast<std::size_t>(count - exponent - 1));
  }
}

QByteArray numberText(double value) {
  std::string text;
  appendNumber(text, value);
  return QByteArray::fromStdString(text);
}

QString shortenedText(const QString& text) {
  return QString::fromStdString(excerpt(text.toStdString()));
}

QString memberPath(const QString& path, const QString& key) {
  return path.isEmpty() ? key : path + '.' + key;
}

QString elementPath(const QString& path, qsizetype index) {
  return path + '[' + QString::number(index) + ']';
}

}  // namespace carom::io
