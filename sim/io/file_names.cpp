#include "sim/io/file_names.h"

#include <sys/stat.h>

namespace carom::io {
namespace {

constexpr char16_t kEscapeBase = 0xDC00;  // + the byte, 0x80..0xFF

// The length of the valid UTF-8 sequence at `at`, or 0 (overlong forms, surrogates and code
// points beyond U+10FFFF are not valid).
int validSequenceLength(const unsigned char* at, qsizetype left) {
  const unsigned char lead = at[0];
  if (lead < 0x80) return 1;
  int length = 0;
  char32_t lowest = 0;
  char32_t code = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2, lowest = 0x80, code = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, lowest = 0x800, code = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, lowest = 0x10000, code = lead & 0x07;
  } else {
    return 0;
  }
  if (left < length) return 0;
  for (int i = 1; i < length; ++i) {
    if ((at[i] & 0xC0) != 0x80) return 0;
    code = (code << 6) | (at[i] & 0x3F);
  }
  if (code < lowest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

}  // namespace

QString decodeFileName(const QByteArray& bytes) {
  QString name;
  name.reserve(bytes.size());
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.constData());
  qsizetype run = 0;  // start of the valid UTF-8 not yet decoded
  qsizetype i = 0;
  while (i < bytes.size()) {
    const int length = validSequenceLength(data + i, bytes.size() - i);
    if (length > 0) {
      i += length;
      continue;
    }
    name += QString::fromUtf8(bytes.constData() + run, i - run);
    name += QChar(char16_t(kEscapeBase + data[i]));
    run = ++i;
  }
  name += QString::fromUtf8(bytes.constData() + run, bytes.size() - run);
  return name;
}

QByteArray encodeFileName(const QString& name) {
  QByteArray bytes;
  bytes.reserve(name.size());
  qsizetype run = 0;  // start of the text not yet encoded
  for (qsizetype i = 0; i < name.size(); ++i) {
    const char16_t unit = name[i].unicode();
    const bool escaped = unit >= kEscapeBase + 0x80 && unit <= kEscapeBase + 0xFF;
    // A lone low surrogate: one that does not end a pair.
    if (!escaped || (i > 0 && name[i - 1].isHighSurrogate())) continue;
    bytes += QStringView(name).mid(run, i - run).toUtf8();
    bytes += char(unit - kEscapeBase);
    run = i + 1;
  }
  bytes += QStringView(name).mid(run).toUtf8();
  return bytes;
}

bool isSameFile(const QString& a, const QString& b) {
  struct stat first, second;
  return ::stat(encodeFileName(a).constData(), &first) == 0 &&
         ::stat(encodeFileName(b).constData(), &second) == 0 && first.st_dev == second.st_dev &&
         first.st_ino == second.st_ino;
}

}  // namespace carom::io
