// The scene file's JSON as both its reader and its writer spell it: the keys of each object
// (scene_format.h's, as Qt strings), numbers in their shortest exact form, and the paths by
// which messages name a field.
#pragma once

#include "sim/io/scene_format.h"

#include <QByteArray>
#include <QStringList>

#include <span>
#include <string>
#include <string_view>

namespace carom::io {

QStringList keyList(std::span<const std::string_view> keys);

// The keys of each object a file of `version` knows (format::versionKeys), as Qt strings.
struct KnownKeys {
  QStringList top, world, plane, cylinder, box, ball;
};
const KnownKeys& knownKeys(int version);

// The shortest text that reads back as the same double, as QByteArray::number(value, 'g',
// QLocale::FloatingPointShortest) spells it (fixed unless scientific is shorter, and a nought
// without a sign), without its allocations: a million balls hold seven million numbers.
// JSON has no infinities or NaN, so a scene holding one is written with null there (and refused
// when read back).
void appendNumber(std::string& out, double value);
QByteArray numberText(double value);

// The paths that messages name a field by, such as "balls[2].radius".
QString memberPath(const QString& path, const QString& key);
QString elementPath(const QString& path, qsizetype index);
// Text of the file as a message shows it: its start only when it is long (validation.h).
QString shortenedText(const QString& text);

}  // namespace carom::io
