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

inline const QStringList kTopKeys = keyList(format::kTopKeys);
inline const QStringList kTopKeysVersion1 = keyList(format::kTopKeysVersion1);
inline const QStringList kWorldKeys = keyList(format::kWorldKeys);
inline const QStringList kPlaneKeys = keyList(format::kPlaneKeys);
inline const QStringList kCylinderKeys = keyList(format::kCylinderKeys);
inline const QStringList kCylinderKeysVersion1 = keyList(format::kCylinderKeysVersion1);
inline const QStringList kBoxKeys = keyList(format::kBoxKeys);
inline const QStringList kBallKeys = keyList(format::kBallKeys);

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
