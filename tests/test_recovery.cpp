// No lost work: the editor keeps a copy of unsaved changes, and after the process is killed the
// next start offers it back. The test runs itself as a child editor and kills it.

#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "ui/editor/scene_recovery.h"

#include <QDir>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cstdio>

using carom::Vec3;
using carom::editor::SceneRecovery;
using carom::testing::DialogAnswerer;
using carom::ui::MainWindow;

namespace {

constexpr int kChildIntervalMilliseconds = 200;

// The child: opens `file`, moves its ball, says "autosaved" once the copy is written, and
// waits to be killed.
// `file` is a scene file, or "example:" and an example's name.
int runChild(const QString& file) {
  MainWindow window;
  const bool opened = file.startsWith("example:") ? window.openExample(file.mid(8), false)
                                                  : window.openFile(file, false);
  if (!opened) return 3;
  sceneRecovery(window)->setInterval(kChildIntervalMilliseconds);
  QObject::connect(sceneRecovery(window), &SceneRecovery::autosaved, [] {
    std::printf("autosaved\n");
    std::fflush(stdout);
  });
  carom::Scene edited = window.document()->scene();
  edited.balls[0].position = Vec3(1, 2, 3);
  edited.balls[0].name = "unsaved work";
  if (!carom::testing::applyEdit(*window.document(), edited, "edit").isEmpty()) return 4;
  window.show();
  return QApplication::exec();
}

}  // namespace

class TestRecovery : public carom::testing::EditorFixture {
  Q_OBJECT
 private slots:
  void init();
  void cleanup() { window_.reset(); }
  void killedEditorsWorkIsOfferedBack();
  void declinedRecoveryIsGone();
  void notNowKeepsTheCopy();
  void aCleanEndLeavesNothing();
  void copiesFollowTheUnsavedState();
  void aRecoveredExampleKeepsItsTitle();

 private:
  // Starts the child on `file` and kills it once it has autosaved.
  void crashAChild(const QString& file);
  QTemporaryDir folder_;
};

void TestRecovery::init() {
  QDir(SceneRecovery::folder()).removeRecursively();
  openWindow();
}

void TestRecovery::crashAChild(const QString& file) {
  if (!file.startsWith("example:"))
    QVERIFY(carom::io::saveSceneFile(carom::testing::floorScene(), file, nullptr));
  QProcess child;
  child.start(QCoreApplication::applicationFilePath(), {"--child", file});
  QVERIFY(child.waitForStarted());
  QByteArray said;
  QTRY_VERIFY_WITH_TIMEOUT((said += child.readAllStandardOutput()).contains("autosaved"), 20000);
  child.kill();  // SIGKILL: no clean-up runs
  QVERIFY(child.waitForFinished());
  QCOMPARE(child.exitStatus(), QProcess::CrashExit);
}

void TestRecovery::killedEditorsWorkIsOfferedBack() {
  const QString file = folder_.filePath("work.carom");
  crashAChild(file);
  QCOMPARE(SceneRecovery::orphans().size(), 1);
  DialogAnswerer answer(QMessageBox::Yes);
  QVERIFY(window_->offerRecovery());
  QVERIFY(answer.answered());
  QVERIFY2(answer.text().contains("work.carom"), qPrintable(answer.text()));
  // The edit is back, unsaved, belonging to the file it came from, which is as it was.
  QCOMPARE(document().scene().balls[0].name, std::string("unsaved work"));
  QCOMPARE(document().scene().balls[0].position, Vec3(1, 2, 3));
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  QVERIFY(document().isModified());
  QVERIFY(window_->isWindowModified());
  QVERIFY(carom::io::loadSceneFile(file).scene == carom::testing::floorScene());
  // Offered once only.
  QVERIFY(SceneRecovery::orphans().isEmpty());
  QVERIFY(!window_->offerRecovery());
  // Saving puts it in the file.
  QVERIFY(window_->save());
  QCOMPARE(carom::io::loadSceneFile(file).scene->balls[0].name, std::string("unsaved work"));
}

// Issue 34: an edited example came back as "untitled*": the copy's note kept only the file,
// which an example has none of.
void TestRecovery::aRecoveredExampleKeepsItsTitle() {
  crashAChild("example:magic-room");
  DialogAnswerer answer(QMessageBox::Yes);
  QVERIFY(window_->offerRecovery());
  QVERIFY2(answer.text().contains("Magic room"), qPrintable(answer.text()));
  QCOMPARE(document().scene().balls[0].name, std::string("unsaved work"));
  QVERIFY(document().fileName().isEmpty());
  QCOMPARE(document().displayName(), QString("Magic room"));
  QVERIFY(document().isModified());
  QCOMPARE(window_->windowTitle().section(" — ", 0, 0), QString("Magic room[*]"));
}

void TestRecovery::declinedRecoveryIsGone() {
  crashAChild(folder_.filePath("declined.carom"));
  const carom::Scene before = document().scene();
  DialogAnswerer answer(QMessageBox::No);
  QVERIFY(!window_->offerRecovery());
  QVERIFY(answer.answered());
  QVERIFY(document().scene() == before);
  QVERIFY(SceneRecovery::orphans().isEmpty());
  QVERIFY(QDir(SceneRecovery::folder()).entryList({"*.carom"}, QDir::Files).isEmpty());
}

void TestRecovery::notNowKeepsTheCopy() {
  crashAChild(folder_.filePath("later.carom"));
  const carom::Scene before = document().scene();
  {
    DialogAnswerer later(QMessageBox::Cancel);  // as Escape would
    QVERIFY(!window_->offerRecovery());
    QVERIFY(later.answered());
  }
  QVERIFY(document().scene() == before);
  QCOMPARE(SceneRecovery::orphans().size(), 1);  // still there for the next start
  DialogAnswerer recover(QMessageBox::Yes);
  QVERIFY(window_->offerRecovery());
  QCOMPARE(document().scene().balls[0].name, std::string("unsaved work"));
}

void TestRecovery::aCleanEndLeavesNothing() {
  sceneRecovery(*window_)->setInterval(kChildIntervalMilliseconds);
  document().setSelection({{carom::editor::ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QTRY_VERIFY(QFileInfo::exists(sceneRecovery(*window_)->copyFile()));
  const QString copy = sceneRecovery(*window_)->copyFile();
  // A live session's copy is not an orphan.
  QVERIFY(SceneRecovery::orphans().isEmpty());
  DialogAnswerer discard(QMessageBox::Discard);
  QVERIFY(window_->close());
  window_.reset();
  QVERIFY(!QFileInfo::exists(copy));
  QVERIFY(QDir(SceneRecovery::folder()).entryList(QDir::Files).isEmpty());
}

void TestRecovery::copiesFollowTheUnsavedState() {
  SceneRecovery* recovery = sceneRecovery(*window_);
  QVERIFY(recovery->autosave());  // nothing unsaved: no copy
  QVERIFY(!QFileInfo::exists(recovery->copyFile()));
  document().setSelection({{carom::editor::ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QSignalSpy written(recovery, &SceneRecovery::autosaved);
  QVERIFY(recovery->autosave());
  QCOMPARE(written.size(), 1);
  QCOMPARE(carom::io::loadSceneFile(recovery->copyFile()).scene->balls.size(), std::size_t{0});
  QVERIFY(recovery->autosave());  // unchanged since: not written again
  QCOMPARE(written.size(), 1);
  // Undone back to the saved state: nothing to recover.
  document().undoStack()->undo();
  QVERIFY(!QFileInfo::exists(recovery->copyFile()));
}

int main(int argc, char** argv) {
  carom::testing::EditorFixture::initMain();
  QApplication app(argc, argv);
  if (argc == 3 && QByteArray(argv[1]) == "--child")
    return runChild(QString::fromLocal8Bit(argv[2]));
  TestRecovery test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_recovery.moc"
