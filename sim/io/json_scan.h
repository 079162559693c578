#pragma once
// Scans of a scene file's raw JSON text, beside Qt's parser: where a byte offset is for a
// message, how much a document holds before its tree is built, and a key said twice in one
// object, which Qt's parser would take silently.

#include "sim/validation/validation.h"

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <optional>
#include <utility>

namespace carom::io {

// 1-based line and column (in characters) of a byte offset into UTF-8 text.
std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset);

// What a document holds, counted before it is parsed: an upper bound on its values (one more
// than its commas outside strings) and the elements of each list at the top, so that a document
// beyond the limits is refused before its tree, tens of bytes a value, is built.
struct DocumentCounts {
  qint64 values = 1;
  SceneCounts lists;
};
DocumentCounts countDocument(const QByteArray& json);

// The path of the first key that appears twice in one object, such as "balls[2].radius".
// QJsonDocument keeps the last of repeated keys without a word; a scene that says two things
// about one field is refused instead. `json` must be valid JSON.
std::optional<QString> duplicateKeyPath(const QByteArray& json);

}  // namespace carom::io
