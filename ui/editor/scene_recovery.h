#pragma once
// Keeps a copy of the open scene on disk while it has unsaved changes, so that a crash loses at
// most one autosave interval of work, and finds the copies that crashed sessions left behind.
//
// Each session owns three files in the recovery folder, named by a session id: a lock held
// while it runs (QLockFile, which tells a dead owner from a live one), the scene, and a note of
// the file the scene came from (or the title of one that has no file). A clean exit removes
// them.

#include <QDateTime>
#include <QList>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace carom::editor {

class SceneDocument;

class SceneRecovery : public QObject {
  Q_OBJECT
 public:
  static constexpr int kDefaultIntervalMilliseconds = 60 * 1000;

  explicit SceneRecovery(SceneDocument* document, QObject* parent = nullptr);
  // A clean end: this session's copy goes.
  ~SceneRecovery() override;

  void setInterval(int milliseconds) { timer_.setInterval(milliseconds); }
  // Writes the copy now if the scene changed since the last one and is unsaved; false when
  // writing failed (the next interval tries again).
  bool autosave();
  // This session's copy; it exists only while there are unsaved changes.
  QString copyFile() const;

  // What a session that did not end cleanly left.
  struct Orphan {
    QString id;
    QString sceneFile;     // the autosaved scene
    QString originalFile;  // where the user's scene lives; empty if it was never saved
    QDateTime saved;
    QString title;  // what a scene without a file was called (an example's title)
  };
  // Newest first.
  static QList<Orphan> orphans();
  // Removes an orphan's files, once recovered or declined.
  static void discard(const Orphan& orphan);
  static QString folder();

 signals:
  void autosaved(const QString& file);
  // The copy could not be written (a full disk); the last one written, if any, is kept whole.
  void autosaveFailed(const QString& reason);

 private:
  void removeCopy();

  SceneDocument* document_;
  QString id_;
  std::unique_ptr<QLockFile> lock_;
  QTimer timer_;
  bool changedSinceCopy_ = false;
};

}  // namespace carom::editor
