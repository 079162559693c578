#pragma once
// The Edit menu's work on the document, as Tiled's MapDocumentActionHandler and
// ClipboardManager: copy and paste through the system clipboard, duplicate, delete and select
// all. It needs no view: the window tells it which way is "across" the screen, where inserted
// objects move until they fit.

#include "sim/model/scene.h"

#include <QObject>
#include <QString>

#include <functional>

namespace carom::editor {
class SceneDocument;
}  // namespace carom::editor
namespace carom::ui {

class EditActions : public QObject {
  Q_OBJECT
 public:
  // `across` gives the direction, in world space, in which inserted balls are shifted aside.
  EditActions(editor::SceneDocument* document, std::function<Vec3()> across,
              QObject* parent = nullptr);

  // The selection, as scene JSON, onto the clipboard (as text too, for other programs).
  void copy();
  // The clipboard's scene objects, moved aside until they fit; refuses text that is no scene.
  void paste();
  void duplicate();
  void deleteSelection();
  void selectAll();
  // Adds copies of `objects`, moved aside as far as needed to overlap nothing, as one command.
  void insertObjects(Scene objects, const QString& text);

  static constexpr const char* kSceneMimeType = "application/x-carom-scene";
  static constexpr int kMaxPlacementAttempts = 20;

 signals:
  // A refusal, for the status bar.
  void message(const QString& text);

 private:
  editor::SceneDocument* document_;
  std::function<Vec3()> across_;
};

}  // namespace carom::ui
