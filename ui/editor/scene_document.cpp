#include "ui/editor/scene_document.h"

#include "sim/validation.h"

#include <QFileInfo>
#include <QUndoCommand>

#include <utility>

namespace carom::ui {

// Every edit is the scene before and after. Shared pointers make a long history cost one scene
// per command, since each command's "after" is the next one's "before".
class SceneEditCommand : public QUndoCommand {
 public:
  SceneEditCommand(SceneDocument* document, std::shared_ptr<const Scene> before,
                   Selection selectionBefore, std::shared_ptr<const Scene> after,
                   Selection selectionAfter, const QString& text, int gesture)
      : QUndoCommand(text),
        document_(document),
        before_(std::move(before)),
        after_(std::move(after)),
        selectionBefore_(std::move(selectionBefore)),
        selectionAfter_(std::move(selectionAfter)),
        gesture_(gesture) {}

  void undo() override { document_->setState(before_, selectionBefore_); }
  void redo() override { document_->setState(after_, selectionAfter_); }
  int id() const override { return gesture_ == 0 ? -1 : kGestureCommandId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const SceneEditCommand*>(other);
    if (next->gesture_ != gesture_) return false;
    after_ = next->after_;
    selectionAfter_ = next->selectionAfter_;
    return true;
  }

 private:
  static constexpr int kGestureCommandId = 1;
  SceneDocument* document_;
  std::shared_ptr<const Scene> before_;
  std::shared_ptr<const Scene> after_;
  Selection selectionBefore_;
  Selection selectionAfter_;
  int gesture_;
};

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent), scene_(std::make_shared<const Scene>()) {
  connect(&undoStack_, &QUndoStack::cleanChanged, this,
          [this](bool clean) { emit modifiedChanged(!clean); });
}

QString SceneDocument::displayName() const {
  if (!fileName_.isEmpty()) return QFileInfo(fileName_).fileName();
  return title_.isEmpty() ? tr("untitled") : title_;
}

void SceneDocument::setTitle(const QString& title) {
  if (title == title_) return;
  title_ = title;
  if (fileName_.isEmpty()) emit displayNameChanged();
}

Scene SceneDocument::newScene() {
  Scene scene;
  Plane floor;
  floor.point = Vec3::Zero();
  floor.normal = Vec3::UnitY();
  floor.name = tr("floor").toUtf8().toStdString();
  scene.planes.push_back(floor);
  return scene;
}

void SceneDocument::reset(const Scene& scene, const QString& fileName, const QString& title) {
  undoStack_.clear();
  // clear() leaves an empty stack's clean state alone, and a recovered scene's was unset.
  undoStack_.setClean();
  fileName_ = fileName;
  title_ = title;
  setState(std::make_shared<const Scene>(scene), {});
  emit displayNameChanged();
  emit modifiedChanged(false);
}

void SceneDocument::markSaved(const QString& fileName) {
  const bool renamed = fileName != fileName_;
  fileName_ = fileName;
  undoStack_.setClean();
  if (renamed) emit displayNameChanged();
}

QString SceneDocument::apply(const Scene& edited, const QString& text, const Selection& selection,
                             int gesture) {
  const std::vector<ValidationError> errors = validateScene(edited, 1);
  if (!errors.empty()) return QString::fromStdString(errors.front().text());
  undoStack_.push(new SceneEditCommand(this, scene_, selection_,
                                       std::make_shared<const Scene>(edited), normalized(selection),
                                       text, gesture));
  return {};
}

void SceneDocument::setSelection(Selection selection) {
  if (!selectSilently(std::move(selection))) return;
  emit selectionChanged();
}

bool SceneDocument::selectSilently(Selection selection) {
  selection = normalized(std::move(selection));
  std::erase_if(selection, [this](const ObjectRef& ref) { return !exists(*scene_, ref); });
  if (selection == selection_) return false;
  selection_ = std::move(selection);
  return true;
}

void SceneDocument::setState(std::shared_ptr<const Scene> scene, const Selection& selection) {
  scene_ = std::move(scene);
  // The selection first: observers of sceneChanged may read it, and old references may no
  // longer exist.
  const bool selectionChanged = selectSilently(selection);
  emit sceneChanged();
  if (selectionChanged) emit this->selectionChanged();
}

}  // namespace carom::ui
