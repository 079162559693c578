#pragma once
// The file side of the window, as Tiled's DocumentManager: New, Open, Save, Save As, the recent
// files, the bundled examples, the question about unsaved changes and the offer to recover a
// scene a crash left unsaved. Dialogs open over `dialogParent`; the window hears of results
// through signals.

#include "sim/model/scene.h"

#include <QObject>
#include <QString>
#include <QStringList>

class QWidget;

namespace carom::editor {
class SceneDocument;
}  // namespace carom::editor
namespace carom::ui {

class SceneFiles : public QObject {
  Q_OBJECT
 public:
  SceneFiles(editor::SceneDocument* document, QWidget* dialogParent, QObject* parent = nullptr);

  // Shows `scene` (valid) as the document read from `fileName` (empty for a new scene; `title`
  // then names it in the title bar and in Save As). Discards unsaved changes.
  void openScene(carom::Scene scene, const QString& fileName, const QString& title = {});
  // File > New: a new scene, once the user has answered about unsaved changes.
  bool newScene();
  // File > Open: asks about unsaved changes, then for a file.
  bool open();
  // Open, asking first about unsaved changes when `askToSave`; a broken file gets a dialog with
  // the loader's message and leaves the open scene as it was.
  bool openFile(const QString& fileName, bool askToSave);
  // A bundled example by its file's base name ("magic-room"), titled in the program's language
  // ("Magic room"); false when there is none or the user cancels the question about saving.
  bool openExample(const QString& file, bool askToSave);
  bool save();
  bool saveAs();
  // Asks about unsaved changes; false when the user cancels (or a save fails).
  bool maybeSave();
  // Offers the scenes that sessions which did not end cleanly left unsaved, newest first, to
  // recover, discard or keep for later; the first one recovered opens as an unsaved scene.
  // Returns whether one did.
  bool offerRecovery();

  // Files opened or saved, the latest first.
  static QStringList recentFiles();
  static constexpr int kMaxRecentFiles = 8;

  // The bundled examples, in the Examples menu's order: file base names, and titles in the
  // program's current language.
  static QStringList exampleFiles();
  static QString exampleTitle(int index);

 signals:
  // Around every scene that opens: the window stops the old one first and frames the new one.
  void sceneAboutToOpen();
  void sceneOpened();
  // For the status bar ("Saved …").
  void message(const QString& text);

 protected:
  // A LanguageChange, which the window passes on to its children, renames an open example.
  bool event(QEvent* event) override;

 private:
  void retranslate();
  bool saveTo(const QString& fileName);
  // Commits what the user is typing in a dock, before a save or a question about saving.
  void commitTypedValue();
  static QString lastFolder();
  static void addRecentFile(const QString& fileName);

  editor::SceneDocument* document_;
  QWidget* dialogParent_;
  // The bundled example open, as an index of exampleFiles(), until another scene opens: its
  // title follows the language, and Save As suggests its file's name.
  int openedExample_ = -1;
};

}  // namespace carom::ui
