#pragma once
// A small tmpfs mounted for a test, to be filled: a real full disk, where writes fail with
// ENOSPC as they do on any full filesystem. Mounting needs root (CI runs as root); where it is
// not allowed, mounted() is false and error() says why, for the test to skip with.

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <sys/mount.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

class SmallFilesystem {
 public:
  // Mounted on `folder` (made if missing), or on a temporary folder of its own.
  explicit SmallFilesystem(qint64 bytes, const QString& folder = QString())
      : path_(folder.isEmpty() ? root_.path() : folder) {
    if (path_.isEmpty() || !QDir().mkpath(path_)) {
      error_ = "no folder to mount on";
      return;
    }
    const QByteArray options = "size=" + QByteArray::number(bytes) + ",mode=0777";
    if (::mount("tmpfs", QFile::encodeName(path_).constData(), "tmpfs", 0, options.constData()) !=
        0) {
      error_ = QString("cannot mount a tmpfs of %1 bytes (root needed): %2")
                   .arg(bytes)
                   .arg(QString::fromLocal8Bit(std::strerror(errno)));
      return;
    }
    mounted_ = true;
  }
  ~SmallFilesystem() {
    if (mounted_) ::umount2(QFile::encodeName(path_).constData(), MNT_DETACH);
  }
  SmallFilesystem(const SmallFilesystem&) = delete;
  SmallFilesystem& operator=(const SmallFilesystem&) = delete;

  bool mounted() const { return mounted_; }
  const QString& error() const { return error_; }
  const QString& path() const { return path_; }
  QString filePath(const QString& name) const { return QDir(path_).filePath(name); }
  QString fillerName() const { return filePath(".filler"); }

  // Bytes a write can still take.
  qint64 freeBytes() const {
    struct statvfs info;
    if (::statvfs(QFile::encodeName(path_).constData(), &info) != 0) return -1;
    return qint64(info.f_bavail) * qint64(info.f_frsize);
  }

  // Fills the filesystem with a filler file, then gives back `leave` bytes of it (in whole
  // pages, tmpfs's unit). True when the filesystem then has about `leave` bytes free.
  bool fill(qint64 leave = 0) {
    QFile filler(fillerName());
    if (!filler.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Unbuffered))
      return false;
    const QByteArray page(4096, 'f');
    while (filler.write(page) == page.size()) {
    }
    // A last partial page, if any room is left.
    while (filler.write("f", 1) == 1) {
    }
    filler.close();
    if (leave > 0 && !filler.resize(std::max<qint64>(0, filler.size() - leave))) return false;
    const qint64 left = freeBytes();
    return left >= leave && left < leave + 8192;
  }
  bool unfill() { return QFile::remove(fillerName()); }

 private:
  QTemporaryDir root_;
  QString path_;
  bool mounted_ = false;
  QString error_;
};
