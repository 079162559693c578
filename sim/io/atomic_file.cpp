#include "sim/io/atomic_file.h"

#include "sim/io/file_names.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <random>

namespace carom::io {
namespace {

// Writes smaller than this are gathered: a trajectory writes a row block a tick.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
// Links followed before giving up, as the kernel's own limit for a path.
constexpr int kMaxLinks = 40;

QByteArray folderOf(const QByteArray& path) {
  const qsizetype slash = path.lastIndexOf('/');
  if (slash < 0) return ".";
  return slash == 0 ? QByteArray("/") : path.left(slash);
}

// The file a name ends at, symbolic links followed (a dangling one ends at what it names).
QByteArray followLinks(QByteArray path) {
  for (int i = 0; i < kMaxLinks; ++i) {
    struct stat info;
    if (::lstat(path.constData(), &info) != 0 || !S_ISLNK(info.st_mode)) return path;
    QByteArray target(info.st_size > 0 ? info.st_size + 1 : 4096, '\0');
    const ssize_t length = ::readlink(path.constData(), target.data(), target.size());
    if (length <= 0) return path;
    target.truncate(length);
    path = target.startsWith('/') ? target : folderOf(path) + '/' + target;
  }
  return path;  // a loop: opening it says so
}

QString randomSuffix() {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937 generator{std::random_device{}()};
  std::uniform_int_distribution<int> pick(0, sizeof(kLetters) - 2);
  QString suffix;
  for (int i = 0; i < 6; ++i) suffix += QChar(kLetters[pick(generator)]);
  return suffix;
}

}  // namespace

AtomicFile::AtomicFile(QString fileName) : fileName_(std::move(fileName)) {}

AtomicFile::~AtomicFile() {
  if (isOpen()) closeAndRemove();
}

bool AtomicFile::fail(int error) {
  failed_ = true;
  error_ = qt_error_string(error);
  return false;
}

bool AtomicFile::open() {
  failed_ = false;
  error_.clear();
  if (fileName_.isEmpty()) return fail(ENOENT);
  target_ = followLinks(encodeFileName(fileName_));
  struct stat existing;
  const bool exists = ::stat(target_.constData(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) {
    failed_ = true;
    error_ = QStringLiteral("Filename refers to a directory");  // as Qt says it
    return false;
  }
  if (exists && !S_ISREG(existing.st_mode)) {
    descriptor_ = ::open(target_.constData(), O_WRONLY | O_CLOEXEC);
    if (descriptor_ < 0) return fail(errno);
    temporary_.clear();
    return true;
  }
  const QByteArray folder = folderOf(target_);
  const QByteArray base = target_.mid(target_.lastIndexOf('/') + 1);
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary_ = folder + '/' + base + ".new-" + randomSuffix().toLatin1();
    // 0666 as any new file: the umask then applies.
    descriptor_ = ::open(temporary_.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (descriptor_ >= 0) break;
    if (errno != EEXIST) {
      const int error = errno;
      temporary_.clear();
      return fail(error);
    }
  }
  if (descriptor_ < 0) return fail(EEXIST);
  // The new file keeps the old one's permissions.
  if (exists) (void)::fchmod(descriptor_, existing.st_mode & 07777);
  return true;
}

bool AtomicFile::writeOut(const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(descriptor_, data, size);
    if (written < 0 && errno == EINTR) continue;
    // A write that takes nothing and says no error can only be a full device.
    if (written <= 0) return fail(written < 0 ? errno : ENOSPC);
    data += written;
    size -= std::size_t(written);
  }
  return true;
}

bool AtomicFile::write(const char* data, std::size_t size) {
  if (failed_) return false;
  if (!isOpen()) return fail(EBADF);
  if (std::size_t(buffer_.size()) + size <= kBufferBytes) {
    buffer_.append(data, qsizetype(size));
    return true;
  }
  if (!writeOut(buffer_.constData(), std::size_t(buffer_.size()))) return false;
  buffer_.clear();
  if (size >= kBufferBytes) return writeOut(data, size);
  buffer_.append(data, qsizetype(size));
  return true;
}

bool AtomicFile::commit() {
  if (!isOpen()) return failed_ ? false : fail(EBADF);
  const bool written = !failed_ && writeOut(buffer_.constData(), std::size_t(buffer_.size()));
  buffer_.clear();
  if (!written) {
    closeAndRemove();
    return false;
  }
  if (temporary_.isEmpty()) {
    const int closed = ::close(descriptor_);
    descriptor_ = -1;
    return closed == 0 || errno == EINTR || fail(errno);
  }
  // Filesystems that allocate late report a full disk only here, or at close.
  if (::fsync(descriptor_) != 0 && errno != EINVAL) {
    const int error = errno;
    closeAndRemove();
    return fail(error);
  }
  const int closed = ::close(descriptor_);
  descriptor_ = -1;
  if (closed != 0 && errno != EINTR) {
    const int error = errno;
    ::unlink(temporary_.constData());
    return fail(error);
  }
  if (::rename(temporary_.constData(), target_.constData()) != 0) {
    const int error = errno;
    ::unlink(temporary_.constData());
    return fail(error);
  }
  temporary_.clear();
  return true;
}

void AtomicFile::cancel() {
  if (isOpen()) closeAndRemove();
}

void AtomicFile::closeAndRemove() {
  ::close(descriptor_);
  descriptor_ = -1;
  if (!temporary_.isEmpty()) ::unlink(temporary_.constData());
  temporary_.clear();
  buffer_.clear();
}

bool writeFileAtomically(const QString& fileName, const QByteArray& contents, QString* error) {
  AtomicFile file(fileName);
  const bool done = file.open() && file.write(contents) && file.commit();
  if (error) *error = done ? QString() : file.errorString();
  return done;
}

}  // namespace carom::io
