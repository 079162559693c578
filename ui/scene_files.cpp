#include "ui/scene_files.h"

#include "sim/io/scene_file.h"
#include "ui/editor/scene_document.h"
#include "ui/editor/scene_recovery.h"

#include <QApplication>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QWidget>

#include <algorithm>
#include <iterator>

namespace carom::ui {

namespace {

// The bundled scenes the Examples menu offers, by title, in its order.
constexpr struct {
  const char* file;  // in :/scenes, without ".json"
  const char* title;
} kExamples[] = {{"magic-room", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Magic room")},
                 {"galton-board", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Galton board")},
                 {"gas-box", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Gas box")},
                 {"inelastic-pile", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Inelastic pile")},
                 {"newtons-cradle", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Newton's cradle")},
                 {"staircase", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Staircase")},
                 {"marble-run", QT_TRANSLATE_NOOP("carom::ui::SceneFiles", "Marble run")}};

constexpr const char* kRecentFilesKey = "files/recent";

}  // namespace

SceneFiles::SceneFiles(editor::SceneDocument* document, QWidget* dialogParent, QObject* parent)
    : QObject(parent), document_(document), dialogParent_(dialogParent) {}

void SceneFiles::openScene(carom::Scene scene, const QString& fileName, const QString& title) {
  emit sceneAboutToOpen();
  openedExample_ = -1;
  document_->reset(std::move(scene), fileName, title);
  emit sceneOpened();
}

bool SceneFiles::newScene() {
  if (!maybeSave()) return false;
  openScene(editor::SceneDocument::newScene(), {});
  return true;
}

bool SceneFiles::open() {
  if (!maybeSave()) return false;
  const QString file =
      QFileDialog::getOpenFileName(dialogParent_, tr("Open Scene"), lastFolder(),
                                   tr("Carom scenes (*.carom *.json);;All files (*)"));
  return !file.isEmpty() && openFile(file, false);
}

bool SceneFiles::openFile(const QString& fileName, bool askToSave) {
  if (askToSave && !maybeSave()) return false;
  io::SceneLoadResult loaded = io::loadSceneFile(fileName);
  if (!loaded.scene) {
    // The open scene stays as it was.
    QMessageBox::warning(dialogParent_, tr("Cannot Open Scene"), loaded.error);
    return false;
  }
  openScene(std::move(*loaded.scene), QFileInfo(fileName).absoluteFilePath());
  addRecentFile(document_->fileName());
  return true;
}

bool SceneFiles::openExample(const QString& file, bool askToSave) {
  const auto* example = std::find_if(std::begin(kExamples), std::end(kExamples),
                                     [&](const auto& entry) { return file == entry.file; });
  if (example == std::end(kExamples)) return false;
  if (askToSave && !maybeSave()) return false;
  const io::SceneLoadResult loaded = io::loadSceneFile(QString(":/scenes/%1.json").arg(file));
  if (!loaded.scene) return false;  // bundled and tested: cannot happen
  openScene(*loaded.scene, {}, tr(example->title));
  openedExample_ = static_cast<int>(example - std::begin(kExamples));
  return true;
}

QStringList SceneFiles::exampleFiles() {
  QStringList files;
  for (const auto& example : kExamples) files.append(example.file);
  return files;
}

QString SceneFiles::exampleTitle(int index) {
  return tr(kExamples[index].title);
}

bool SceneFiles::event(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  return QObject::event(event);
}

// Renames an open example in the program's current language.
void SceneFiles::retranslate() {
  if (openedExample_ >= 0) document_->setTitle(exampleTitle(openedExample_));
}

bool SceneFiles::offerRecovery() {
  for (const editor::SceneRecovery::Orphan& orphan : editor::SceneRecovery::orphans()) {
    const QString name = !orphan.originalFile.isEmpty()
                             ? QDir::toNativeSeparators(orphan.originalFile)
                         : !orphan.title.isEmpty() ? tr("“%1”").arg(orphan.title)
                                                   : tr("an unsaved scene");
    QMessageBox box(QMessageBox::Question, tr("Recover Scene"),
                    tr("Carom did not close properly while %1 had unsaved changes. The copy "
                       "saved at %2 can be recovered.")
                        // In the program's language: installTranslation() made its locale
                        // the default one.
                        .arg(name, QLocale().toString(orphan.saved, QLocale::ShortFormat)),
                    QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel, dialogParent_);
    box.button(QMessageBox::Yes)->setText(tr("&Recover"));
    box.button(QMessageBox::No)->setText(tr("&Discard"));
    box.button(QMessageBox::Cancel)->setText(tr("Not &Now"));  // and Escape: asked again next time
    box.setDefaultButton(QMessageBox::Yes);
    const int answer = box.exec();
    if (answer == QMessageBox::Cancel) continue;
    const bool recover = answer == QMessageBox::Yes;
    const io::SceneLoadResult loaded =
        recover ? io::loadSceneFile(orphan.sceneFile) : io::SceneLoadResult{};
    if (recover && !loaded.scene) {
      QMessageBox::warning(dialogParent_, tr("Cannot Recover Scene"), loaded.error);
      continue;  // kept, for a later try
    }
    editor::SceneRecovery::discard(orphan);
    if (!recover) continue;
    openScene(*loaded.scene, orphan.originalFile, orphan.title);
    document_->markUnsaved();
    return true;
  }
  return false;
}

bool SceneFiles::save() {
  if (document_->fileName().isEmpty()) return saveAs();
  return saveTo(document_->fileName());
}

bool SceneFiles::saveAs() {
  QString suggested = document_->fileName();
  if (suggested.isEmpty()) {
    const QString base =
        openedExample_ >= 0 ? kExamples[openedExample_].file : document_->displayName();
    suggested = QDir(lastFolder()).filePath(base + ".carom");
  }
  QString file = QFileDialog::getSaveFileName(dialogParent_, tr("Save Scene"), suggested,
                                              tr("Carom scenes (*.carom);;All files (*)"));
  if (file.isEmpty()) return false;
  if (QFileInfo(file).suffix().isEmpty()) file += ".carom";
  return saveTo(file);
}

bool SceneFiles::saveTo(const QString& fileName) {
  commitTypedValue();
  QString error;
  if (!io::saveSceneFile(document_->scene(), fileName, &error)) {
    // The old file, if any, is untouched: the save writes a new one and renames it over.
    QMessageBox::warning(dialogParent_, tr("Cannot Save Scene"), error);
    return false;
  }
  document_->markSaved(QFileInfo(fileName).absoluteFilePath());
  addRecentFile(document_->fileName());
  emit message(tr("Saved %1").arg(fileName));
  return true;
}

bool SceneFiles::maybeSave() {
  commitTypedValue();
  if (!document_->isModified()) return true;
  const auto answer = QMessageBox::question(
      dialogParent_, tr("Unsaved Changes"),
      tr("The scene %1 has unsaved changes. Save them?").arg(document_->displayName()),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

void SceneFiles::commitTypedValue() {
  // As if the user had pressed Enter: fields and the outline's name editor commit on focus out.
  QWidget* focus = QApplication::focusWidget();
  if (focus && dialogParent_ && focus->window() == dialogParent_->window()) focus->clearFocus();
}

QStringList SceneFiles::recentFiles() {
  return QSettings().value(kRecentFilesKey).toStringList();
}

QString SceneFiles::lastFolder() {
  const QStringList recent = recentFiles();
  return recent.isEmpty() ? QDir::homePath() : QFileInfo(recent.first()).absolutePath();
}

void SceneFiles::addRecentFile(const QString& fileName) {
  QStringList recent = recentFiles();
  recent.removeAll(fileName);
  recent.prepend(fileName);
  while (recent.size() > kMaxRecentFiles) recent.removeLast();
  QSettings().setValue(kRecentFilesKey, recent);
}

}  // namespace carom::ui
