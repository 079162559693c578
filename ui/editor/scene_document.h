#pragma once
// The open scene, as Tiled's MapDocument: it owns the scene's initial state, the selection and
// the undo stack. Every change is a command on the stack; views and docks observe the signals.

#include "sim/model/scene.h"
#include "ui/editor/object_ref.h"
#include "ui/editor/scene_change.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

namespace carom::editor {

class SceneDocument : public QObject {
  Q_OBJECT
 public:
  explicit SceneDocument(QObject* parent = nullptr);
  ~SceneDocument() override;

  const Scene& scene() const { return scene_; }
  QUndoStack* undoStack() { return &undoStack_; }

  // The file the scene was read from or last saved to; empty for a new scene.
  QString fileName() const { return fileName_; }
  // For the title and the questions about saving: the file's name, else the title it was opened
  // with (an example's), else "untitled".
  QString displayName() const;
  bool isModified() const { return !undoStack_.isClean(); }

  // New and Open: `scene` (valid) replaces the document's, unmodified, with an empty history.
  // `title` names a scene that has no file yet.
  void reset(Scene scene, const QString& fileName, const QString& title = {});
  // Renames a scene that has no file yet (an example's title in another language).
  void setTitle(const QString& title);
  QString title() const { return title_; }
  // What File > New gives: the default world and a floor at y = 0 to build on.
  static Scene newScene();
  // After a successful save to `fileName`: the current state becomes the unmodified one.
  void markSaved(const QString& fileName);
  // A scene recovered after a crash: unsaved, with no history to undo back to the saved file.
  void markUnsaved() { undoStack_.resetClean(); }

  // The edits. Each is one user action, checked with the scene validation every loader uses
  // (for the objects it touches only, so that an edit costs the same in any scene). When that
  // fails nothing changes and the first problem is returned in the user's words ("Radius of
  // Ball 2 must be above zero (got -1 m)", validation_text.h); otherwise it becomes one command
  // named `text` and an empty string is returned.
  //
  // The objects `refs` names take the values `values` holds for them, in the order extract()
  // gives. Successive edits of the same objects with the same non-zero `gesture` (one mouse
  // drag) merge into one command.
  QString editObjects(const Selection& refs, const Scene& values, const QString& text,
                      int gesture = 0);
  // Appends the planes, cylinders, boxes and balls of `objects` and selects them.
  QString addObjects(const Scene& objects, const QString& text);
  // Removes the objects `refs` names and clears the selection.
  QString removeObjects(const Selection& refs, const QString& text);
  QString editWorld(const World& world, const QString& text);
  // A number for a new gesture, never 0.
  int newGesture() { return ++lastGesture_; }

  const Selection& selection() const { return selection_; }
  // References to objects the scene lacks are dropped.
  void setSelection(Selection selection);

 signals:
  // After every change of the scene: an edit, undo, redo or reset.
  void sceneChanged(const carom::editor::SceneChange& change);
  // Before the scene is written to in any way, and before it is destroyed: whoever reads it on
  // another thread finishes here (connect directly).
  void aboutToChange();
  void selectionChanged();
  // The file name or the title changed, and with them displayName().
  void displayNameChanged();
  void modifiedChanged(bool modified);

 private:
  friend class SceneEditCommand;
  // Called by commands: no validation, no history.
  void changed(const SceneChange& change, const Selection& selection);
  // Whether the selection changed; emits nothing.
  bool selectSilently(Selection selection);

  Scene scene_;
  Selection selection_;
  QString fileName_;
  QString title_;
  QUndoStack undoStack_;
  int lastGesture_ = 0;
};

}  // namespace carom::editor
