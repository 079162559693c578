#include "sim/io/json_scan.h"

#include "sim/io/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include <algorithm>
#include <vector>

namespace carom::io {

std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset) {
  offset = std::clamp<qsizetype>(offset, 0, text.size());
  int line = 1;
  int column = 1;
  for (qsizetype i = 0; i < offset; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      ++line;
      column = 1;
    } else if ((byte & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
      ++column;
    }
  }
  return {line, column};
}

DocumentCounts countDocument(const QByteArray& json) {
  DocumentCounts counts;
  std::size_t* list = nullptr;  // the top-level list being counted
  int depth = 0;
  bool expectingElement = false;
  QString key;  // the last string at depth 1: the key of the value that follows it
  bool versionOne = false;
  char previous = 0;  // the last character outside strings and white space
  for (qsizetype i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (depth == 2 && list && expectingElement && c != ']') {
      ++*list;
      expectingElement = false;
    }
    if (c == '"') {
      const qsizetype start = i;
      for (++i; i < json.size() && json[i] != '"'; ++i)
        if (json[i] == '\\') ++i;
      previous = '"';
      if (depth != 1) continue;
      const QByteArray token = json.mid(start, i - start + 1);
      key = token.contains('\\')
                ? QJsonDocument::fromJson('[' + token + ']').array().at(0).toString()
                : QString::fromUtf8(token.mid(1, token.size() - 2));
    } else if (c == ',') {
      ++counts.values;
      if (depth == 2) expectingElement = true;
    } else if (c == '{' || c == '[') {
      ++depth;
      if (depth == 2 && c == '[') {
        list = key == "balls"       ? &counts.lists.balls
               : key == "planes"    ? &counts.lists.planes
               : key == "cylinders" ? &counts.lists.cylinders
               : key == "boxes"     ? &counts.lists.boxes
                                    : nullptr;
        expectingElement = true;
      }
    } else if (c == '}' || c == ']') {
      if (depth == 2) list = nullptr;
      --depth;
    } else if (depth == 1 && key == "version" && previous == ':' && c == '1' &&
               (i + 1 == json.size() || !std::isdigit(static_cast<unsigned char>(json[i + 1])))) {
      versionOne = true;
    }
    previous = c;
  }
  // Version 1 had no boxes: there "boxes" is a key it does not know, kept as it is.
  if (versionOne) counts.lists.boxes = 0;
  return counts;
}

// `json` is valid JSON here, so the scan only follows containers, commas, colons and strings.
std::optional<QString> duplicateKeyPath(const QByteArray& json) {
  struct Container {
    bool object = false;
    QSet<QString> keys;  // objects: keys seen so far
    QString key;         // objects: the key whose value comes next
    bool expectingKey = true;
    qsizetype index = 0;  // arrays: the element that comes next
  };
  std::vector<Container> open;
  // Paths are spelled only for the answer: a large scene has a container per ball and vector.
  const auto pathTo = [&open](std::size_t depth) {
    QString path;
    for (std::size_t d = 0; d < depth; ++d)
      path = open[d].object ? memberPath(path, shortenedText(open[d].key))
                            : elementPath(path, open[d].index);
    return path;
  };
  for (qsizetype i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '{' || c == '[') {
      Container container;
      container.object = c == '{';
      open.push_back(std::move(container));
    } else if (c == '}' || c == ']') {
      open.pop_back();
    } else if (c == ',' && !open.empty()) {
      if (open.back().object)
        open.back().expectingKey = true;
      else
        ++open.back().index;
    } else if (c == ':' && !open.empty()) {
      open.back().expectingKey = false;
    } else if (c == '"') {
      const qsizetype start = i;
      bool escapes = false;
      for (++i; json[i] != '"'; ++i) {
        if (json[i] == '\\') {
          escapes = true;
          ++i;
        }
      }
      if (open.empty() || !open.back().object || !open.back().expectingKey) continue;
      const QByteArray token = json.mid(start, i - start + 1);
      // Escapes (\u0061 is "a") are decoded by the JSON parser itself, one string at a time.
      const QString key = escapes
                              ? QJsonDocument::fromJson('[' + token + ']').array().at(0).toString()
                              : QString::fromUtf8(token.mid(1, token.size() - 2));
      Container& object = open.back();
      if (object.keys.contains(key)) return memberPath(pathTo(open.size() - 1), shortenedText(key));
      object.keys.insert(key);
      object.key = key;
    }
  }
  return std::nullopt;
}

}  // namespace carom::io
