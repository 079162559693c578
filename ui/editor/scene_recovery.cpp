#include "ui/editor/scene_recovery.h"

#include "sim/io/atomic_file.h"
#include "sim/io/scene_file.h"
#include "ui/editor/scene_document.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <algorithm>

namespace carom::editor {
namespace {

QString pathOf(const QString& id, const char* suffix) {
  return QDir(SceneRecovery::folder()).filePath(id + suffix);
}

constexpr const char* kLockSuffix = ".lock";
constexpr const char* kSceneSuffix = ".carom";
constexpr const char* kNoteSuffix = ".note.json";

// Whether the session `id` still runs: its lock is held by a live process.
bool alive(const QString& id) {
  QLockFile probe(pathOf(id, kLockSuffix));
  probe.setStaleLockTime(0);  // stale only when its owner is gone, however old
  if (probe.tryLock(0)) {
    probe.unlock();
    return false;
  }
  return probe.error() == QLockFile::LockFailedError;
}

}  // namespace

QString SceneRecovery::folder() {
  return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
      .filePath("recovery");
}

SceneRecovery::SceneRecovery(SceneDocument* document, QObject* parent)
    : QObject(parent),
      document_(document),
      id_(QString("%1-%2")
              .arg(QDateTime::currentMSecsSinceEpoch())
              .arg(QCoreApplication::applicationPid())) {
  QDir().mkpath(folder());
  lock_ = std::make_unique<QLockFile>(pathOf(id_, kLockSuffix));
  lock_->setStaleLockTime(0);
  lock_->tryLock(0);
  connect(document_, &SceneDocument::sceneChanged, this, [this] { changedSinceCopy_ = true; });
  connect(document_, &SceneDocument::displayNameChanged, this,
          [this] { changedSinceCopy_ = true; });
  connect(document_, &SceneDocument::modifiedChanged, this, [this](bool modified) {
    changedSinceCopy_ = modified;
    if (!modified) removeCopy();  // saved, or back at the saved state: nothing to recover
  });
  timer_.setInterval(kDefaultIntervalMilliseconds);
  connect(&timer_, &QTimer::timeout, this, &SceneRecovery::autosave);
  timer_.start();
}

SceneRecovery::~SceneRecovery() {
  removeCopy();
  lock_->unlock();
}

QString SceneRecovery::copyFile() const {
  return pathOf(id_, kSceneSuffix);
}

bool SceneRecovery::autosave() {
  if (!document_->isModified() || !changedSinceCopy_) return true;
  // Each file is replaced whole or not at all: on a full disk the last copy stays recoverable.
  QString error;
  const bool written =
      io::saveSceneFile(document_->scene(), copyFile(), &error) &&
      io::writeFileAtomically(pathOf(id_, kNoteSuffix),
                              QJsonDocument(QJsonObject{{"original", document_->fileName()},
                                                        {"title", document_->title()}})
                                  .toJson(),
                              &error);
  if (!written) {
    // The system's reason alone, the part after the file's name: the copy's path means nothing
    // to the user.
    emit autosaveFailed(error.mid(error.lastIndexOf(": ") + 2));
    return false;
  }
  changedSinceCopy_ = false;
  emit autosaved(copyFile());
  return true;
}

void SceneRecovery::removeCopy() {
  QFile::remove(pathOf(id_, kSceneSuffix));
  QFile::remove(pathOf(id_, kNoteSuffix));
}

QList<SceneRecovery::Orphan> SceneRecovery::orphans() {
  QList<Orphan> found;
  const QStringList scenes =
      QDir(folder()).entryList({QString("*") + kSceneSuffix}, QDir::Files, QDir::Time);
  for (const QString& scene : scenes) {
    const QString id = scene.chopped(int(qstrlen(kSceneSuffix)));
    if (alive(id)) continue;
    Orphan orphan;
    orphan.id = id;
    orphan.sceneFile = pathOf(id, kSceneSuffix);
    orphan.saved = QFileInfo(orphan.sceneFile).lastModified();
    QFile note(pathOf(id, kNoteSuffix));
    if (note.open(QIODevice::ReadOnly)) {
      const QJsonObject said = QJsonDocument::fromJson(note.readAll()).object();
      orphan.originalFile = said["original"].toString();
      orphan.title = said["title"].toString();
    }
    found.push_back(orphan);
  }
  return found;
}

void SceneRecovery::discard(const Orphan& orphan) {
  for (const char* suffix : {kSceneSuffix, kNoteSuffix, kLockSuffix})
    QFile::remove(pathOf(orphan.id, suffix));
}

}  // namespace carom::editor
