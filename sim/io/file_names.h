#pragma once
// File names as the bytes the system gave. Qt reads every name as UTF-8 and turns bytes that are
// not UTF-8 into U+FFFD, so a file named in Latin-1 ("lat\xe9.json") could not be opened by the
// name Qt makes of it, and a file written by that name would get another. These keep each such
// byte as a lone surrogate U+DC80..U+DCFF (as Python's surrogateescape does), so a name from the
// command line reaches the system unchanged; valid UTF-8 gives exactly the QString Qt gives.

#include <QByteArray>
#include <QString>

namespace carom::io {

QString decodeFileName(const QByteArray& bytes);
QByteArray encodeFileName(const QString& name);
// Whether both names reach one existing file (through symbolic links and hard links alike).
bool isSameFile(const QString& a, const QString& b);

}  // namespace carom::io
