// The file side of the editor without a window: open, save, Save As, the recent files and the
// question about unsaved changes, on a document and a plain widget for the dialogs.

#include "sim/io/scene_file.h"
#include "tests/dialog_answerer.h"
#include "tests/scene_edits.h"
#include "tests/scene_helpers.h"
#include "ui/editor/scene_document.h"
#include "ui/scene_files.h"

#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

#include <memory>

using carom::Scene;
using carom::Vec3;
using carom::editor::SceneDocument;
using carom::testing::DialogAnswerer;
using carom::testing::ModalAnswerer;
using carom::ui::SceneFiles;

namespace {

// A floor and one ball resting on it, named so that the files written can be told apart.
Scene ballScene(const std::string& name) {
  Scene scene;
  scene.planes.push_back(carom::testing::makePlane(Vec3::Zero(), Vec3::UnitY()));
  carom::Ball ball = carom::testing::makeBall(Vec3(0, 0.5, 0), Vec3::Zero(), 0.5);
  ball.name = name;
  scene.balls.push_back(ball);
  return scene;
}

}  // namespace

class TestSceneFiles : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
  void init();
  void cleanup();

  void opensAGoodFile();
  void aBrokenFileLeavesTheSceneAlone();
  void saveAsAddsTheSuffix();
  void saveAsCancelledWritesNothing();
  void aFailedSaveKeepsTheEdits();
  void saveAsSuggestsTheExamplesFile();
  void recentFilesNewestFirstAndLimited();
  void unsavedChangesQuestion_data();
  void unsavedChangesQuestion();

 private:
  QString writeScene(const QString& name, const Scene& scene);
  void edit();

  QTemporaryDir folder_;
  std::unique_ptr<QWidget> parent_;
  SceneDocument* document_ = nullptr;
  SceneFiles* files_ = nullptr;
};

void TestSceneFiles::init() {
  QSettings().clear();  // no recent files from another test
  parent_ = std::make_unique<QWidget>();
  parent_->show();
  document_ = new SceneDocument(parent_.get());
  files_ = new SceneFiles(document_, parent_.get(), parent_.get());
  files_->openScene(ballScene("start"), {}, "start");
}

void TestSceneFiles::cleanup() {
  parent_.reset();
}

QString TestSceneFiles::writeScene(const QString& name, const Scene& scene) {
  const QString file = folder_.filePath(name);
  QFile out(file);
  if (out.open(QIODevice::WriteOnly)) out.write(carom::io::serializeScene(scene));
  return file;
}

// Removes the ball: an edit to save or to ask about.
void TestSceneFiles::edit() {
  Scene edited = document_->scene();
  edited.balls.clear();
  QVERIFY(carom::testing::applyEdit(*document_, edited, "Delete").isEmpty());
  QVERIFY(document_->isModified());
}

void TestSceneFiles::opensAGoodFile() {
  const QString file = writeScene("good.carom", ballScene("good"));
  QSignalSpy aboutToOpen(files_, &SceneFiles::sceneAboutToOpen);
  QSignalSpy opened(files_, &SceneFiles::sceneOpened);
  QVERIFY(files_->openFile(file, false));
  QCOMPARE(aboutToOpen.size(), 1);
  QCOMPARE(opened.size(), 1);
  QCOMPARE(document_->fileName(), QFileInfo(file).absoluteFilePath());
  QVERIFY(document_->scene() == ballScene("good"));
  QVERIFY(!document_->isModified());
  QCOMPARE(SceneFiles::recentFiles(), QStringList{QFileInfo(file).absoluteFilePath()});
}

void TestSceneFiles::aBrokenFileLeavesTheSceneAlone() {
  QByteArray json = carom::io::serializeScene(ballScene("broken"));
  const qsizetype radius = json.indexOf("\"radius\"");
  QVERIFY(radius > 0);
  json.insert(json.indexOf(':', radius) + 1, " -2, \"unused\":");  // radius: -2
  const QString file = folder_.filePath("broken.carom");
  {
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(json);
  }
  const Scene before = document_->scene();
  QSignalSpy opened(files_, &SceneFiles::sceneOpened);
  DialogAnswerer answer(QMessageBox::Ok);
  QVERIFY(!files_->openFile(file, false));
  QVERIFY(answer.answered());
  QVERIFY2(answer.text().contains("balls[0].radius"), qPrintable(answer.text()));
  QVERIFY(document_->scene() == before);
  QVERIFY(document_->fileName().isEmpty());
  QCOMPARE(opened.size(), 0);
  QVERIFY(SceneFiles::recentFiles().isEmpty());
}

void TestSceneFiles::saveAsAddsTheSuffix() {
  edit();
  QStringList suggested;
  const QString typed = folder_.filePath("chosen");
  ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    suggested = dialog->selectedFiles();
    dialog->selectFile(typed);
    QMetaObject::invokeMethod(dialog, "accept");  // the Save button's slot
  });
  QSignalSpy messages(files_, &SceneFiles::message);
  QVERIFY(files_->saveAs());
  QVERIFY(answer.answered());
  QCOMPARE(suggested.size(), 1);
  QVERIFY2(suggested.first().endsWith("start.carom"), qPrintable(suggested.first()));
  const QString file = typed + ".carom";
  const carom::io::SceneLoadResult saved = carom::io::loadSceneFile(file);
  QVERIFY2(saved.scene, qPrintable(saved.error));
  QVERIFY(*saved.scene == document_->scene());
  QCOMPARE(document_->fileName(), QFileInfo(file).absoluteFilePath());
  QVERIFY(!document_->isModified());
  QCOMPARE(messages.size(), 1);
  QCOMPARE(messages.first().first().toString(), "Saved " + file);
  QCOMPARE(SceneFiles::recentFiles().first(), QFileInfo(file).absoluteFilePath());
}

void TestSceneFiles::saveAsCancelledWritesNothing() {
  edit();
  const QStringList filesBefore = QDir(folder_.path()).entryList(QDir::Files);
  ModalAnswerer<QFileDialog> answer([](QFileDialog* dialog) { dialog->reject(); });
  QSignalSpy messages(files_, &SceneFiles::message);
  QVERIFY(!files_->saveAs());
  QVERIFY(answer.answered());
  QVERIFY(document_->isModified());
  QVERIFY(document_->fileName().isEmpty());
  QCOMPARE(QDir(folder_.path()).entryList(QDir::Files), filesBefore);
  QCOMPARE(messages.size(), 0);
}

void TestSceneFiles::aFailedSaveKeepsTheEdits() {
  // A scene file that cannot be replaced: its name has become a folder with a file in it.
  const QString file = writeScene("blocked.carom", ballScene("blocked"));
  QVERIFY(files_->openFile(file, false));
  QVERIFY(QFile::remove(file));
  QVERIFY(QDir(folder_.path()).mkpath("blocked.carom/inside"));
  edit();
  DialogAnswerer answer(QMessageBox::Ok);
  QVERIFY(!files_->save());
  QVERIFY(answer.answered());
  QVERIFY(!answer.text().isEmpty());
  QVERIFY(document_->isModified());
  QVERIFY(document_->scene().balls.empty());
  QCOMPARE(document_->fileName(), QFileInfo(file).absoluteFilePath());
}

void TestSceneFiles::saveAsSuggestsTheExamplesFile() {
  QVERIFY(!files_->openExample("no-such-example", false));
  QVERIFY(files_->openExample("gas-box", false));
  QCOMPARE(document_->displayName(), "Gas box");
  QCOMPARE(SceneFiles::exampleFiles().indexOf("gas-box"), 2);
  QCOMPARE(SceneFiles::exampleTitle(2), "Gas box");
  QStringList suggested;
  ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    suggested = dialog->selectedFiles();
    dialog->reject();
  });
  QVERIFY(!files_->saveAs());
  QVERIFY(answer.answered());
  QCOMPARE(suggested.size(), 1);
  QVERIFY2(suggested.first().endsWith("/gas-box.carom"), qPrintable(suggested.first()));
}

void TestSceneFiles::recentFilesNewestFirstAndLimited() {
  QStringList opened;
  for (int i = 0; i < SceneFiles::kMaxRecentFiles + 2; ++i) {
    const QString file = writeScene(QString("scene%1.carom").arg(i), ballScene("recent"));
    QVERIFY(files_->openFile(file, false));
    opened.prepend(QFileInfo(file).absoluteFilePath());
  }
  QCOMPARE(SceneFiles::recentFiles(), opened.mid(0, SceneFiles::kMaxRecentFiles));
  // Opened again, a file moves to the front, listed once.
  const QString again = opened[3];
  QVERIFY(files_->openFile(again, false));
  opened.removeAt(3);
  opened.prepend(again);
  QCOMPARE(SceneFiles::recentFiles(), opened.mid(0, SceneFiles::kMaxRecentFiles));
}

void TestSceneFiles::unsavedChangesQuestion_data() {
  QTest::addColumn<int>("answer");
  QTest::addColumn<bool>("goesOn");
  QTest::addColumn<bool>("written");
  QTest::newRow("save") << int(QMessageBox::Save) << true << true;
  QTest::newRow("discard") << int(QMessageBox::Discard) << true << false;
  QTest::newRow("cancel") << int(QMessageBox::Cancel) << false << false;
}

void TestSceneFiles::unsavedChangesQuestion() {
  QFETCH(int, answer);
  QFETCH(bool, goesOn);
  QFETCH(bool, written);
  const QString file = writeScene("asked.carom", ballScene("asked"));
  QVERIFY(files_->openFile(file, false));
  // Unmodified: nothing to ask.
  QVERIFY(files_->maybeSave());
  edit();
  DialogAnswerer answerer(static_cast<QMessageBox::StandardButton>(answer));
  QCOMPARE(files_->maybeSave(), goesOn);
  QVERIFY(answerer.answered());
  QVERIFY2(answerer.text().contains("asked.carom"), qPrintable(answerer.text()));
  QCOMPARE(carom::io::loadSceneFile(file).scene->balls.empty(), written);
  QCOMPARE(document_->isModified(), !written);
}

QTEST_MAIN(TestSceneFiles)
#include "test_scene_files.moc"
