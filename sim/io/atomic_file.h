#pragma once
// Writes a file whole or not at all. The bytes go to a new file beside it, which is written to
// the disk and then renamed over the old one; a failure anywhere (a full disk, a folder that
// went away, an interrupted write) removes the new file, leaves the old one as it was and says
// why. Every write is checked: QSaveFile in Qt 6.4 does not report a failed final flush, and
// so renamed an empty file over a scene on a full disk and reported success.
//
// A name that is a symbolic link writes its target, so the link stays a link. A name that is
// not a regular file (a FIFO, /dev/stdout) is written in place, as nothing can be renamed over
// it. Names go to the system as decodeFileName's bytes (file_names.h).

#include <QByteArray>
#include <QString>

#include <cstddef>

namespace carom::io {

class AtomicFile {
 public:
  explicit AtomicFile(QString fileName);
  ~AtomicFile();  // an uncommitted new file is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Creates the new file. False, with errorString(), when it cannot.
  bool open();
  // Each returns false once anything failed; the first failure's reason stays.
  bool write(const char* data, std::size_t size);
  bool write(const QByteArray& data) { return write(data.constData(), std::size_t(data.size())); }
  // Writes what is buffered, syncs it to the disk and renames it over the old file.
  bool commit();
  // Removes the new file; the old one stays as it was.
  void cancel();

  const QString& fileName() const { return fileName_; }
  bool isOpen() const { return descriptor_ >= 0; }
  // Why the last call failed, as the system says it: "No space left on device".
  const QString& errorString() const { return error_; }

 private:
  bool fail(int error);
  bool writeOut(const char* data, std::size_t size);
  void closeAndRemove();

  QString fileName_;
  QByteArray target_;     // where the file ends up, symbolic links followed
  QByteArray temporary_;  // the new file beside it; empty when written in place
  int descriptor_ = -1;
  QByteArray buffer_;
  bool failed_ = false;
  QString error_;
};

// The whole of `contents` as `fileName` through an AtomicFile; false with `*error` (when given)
// saying why.
bool writeFileAtomically(const QString& fileName, const QByteArray& contents, QString* error);

}  // namespace carom::io
