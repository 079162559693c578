#include "ui/editor/scene_document.h"

#include "sim/validation/validation.h"
#include "ui/editor/object_kinds.h"
#include "ui/editor/validation_text.h"

#include <QFileInfo>
#include <QUndoCommand>

#include <optional>
#include <utility>

namespace carom::editor {

namespace {

SceneObjectIndices indicesOf(const Selection& refs) {
  SceneObjectIndices indices;
  for (const ObjectRef& ref : refs)
    (indices.*kindInfo(ref.kind).validated).push_back(static_cast<std::size_t>(ref.index));
  return indices;
}

}  // namespace

// Every edit keeps only what it changes, as Tiled's commands do: the objects removed, the
// objects inserted, the values of the objects edited in place before and after, and the world
// before and after. So a history costs what its edits touched, whatever the size of the scene.
class SceneEditCommand : public QUndoCommand {
 public:
  SceneEditCommand(SceneDocument* document, const QString& text, Selection selectionAfter,
                   int gesture = 0)
      : QUndoCommand(text),
        document_(document),
        selectionBefore_(document->selection_),
        selectionAfter_(std::move(selectionAfter)),
        gesture_(gesture) {}

  Selection removed;
  Scene removedObjects;
  Selection inserted;
  Scene insertedObjects;
  Selection edited;
  Scene editedBefore;
  Scene editedAfter;
  std::optional<World> worldBefore;
  std::optional<World> worldAfter;

  void redo() override {
    emit document_->aboutToChange();
    Scene& scene = document_->scene_;
    remove(scene, removed);
    insert(scene, inserted, insertedObjects);
    assign(scene, edited, editedAfter);
    if (worldAfter) scene.world = *worldAfter;
    document_->changed({worldAfter.has_value(), false, removed, inserted, edited}, selectionAfter_);
  }
  void undo() override {
    emit document_->aboutToChange();
    Scene& scene = document_->scene_;
    assign(scene, edited, editedBefore);
    remove(scene, inserted);
    insert(scene, removed, removedObjects);
    if (worldBefore) scene.world = *worldBefore;
    document_->changed({worldBefore.has_value(), false, inserted, removed, edited},
                       selectionBefore_);
  }
  int id() const override { return gesture_ == 0 ? -1 : kGestureCommandId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const SceneEditCommand*>(other);
    if (next->gesture_ != gesture_ || next->edited != edited || !removed.empty() ||
        !inserted.empty() || !next->removed.empty() || !next->inserted.empty() || worldAfter ||
        next->worldAfter)
      return false;
    editedAfter = next->editedAfter;
    selectionAfter_ = next->selectionAfter_;
    // A drag back to where it began (or cancelled) changed nothing: the stack drops the command.
    setObsolete(editedAfter == editedBefore);
    return true;
  }

 private:
  static constexpr int kGestureCommandId = 1;
  SceneDocument* document_;
  Selection selectionBefore_;
  Selection selectionAfter_;
  int gesture_;
};

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
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

SceneDocument::~SceneDocument() {
  emit aboutToChange();
}

void SceneDocument::reset(Scene scene, const QString& fileName, const QString& title) {
  emit aboutToChange();
  undoStack_.clear();
  // clear() leaves an empty stack's clean state alone, and a recovered scene's was unset.
  undoStack_.setClean();
  fileName_ = fileName;
  title_ = title;
  scene_ = std::move(scene);  // a copy of a million balls took a second
  SceneChange change;
  change.world = change.replaced = true;
  changed(change, {});
  emit displayNameChanged();
  emit modifiedChanged(false);
}

void SceneDocument::markSaved(const QString& fileName) {
  const bool renamed = fileName != fileName_;
  fileName_ = fileName;
  undoStack_.setClean();
  if (renamed) emit displayNameChanged();
}

QString SceneDocument::editObjects(const Selection& refs, const Scene& values, const QString& text,
                                   int gesture) {
  Selection sorted = normalized(refs);
  std::erase_if(sorted, [this](const ObjectRef& ref) { return !exists(scene_, ref); });
  Scene before = extract(scene_, sorted);
  const Selection local = extractedRefs(sorted);
  if (extract(values, local) == before) return {};  // nothing to do
  // Tried in place, then put back: the command makes the change.
  emit aboutToChange();
  assign(scene_, sorted, values);
  const std::vector<ValidationError> errors = validateObjects(scene_, indicesOf(sorted), 1);
  assign(scene_, sorted, before);
  // Worded with the objects as they were: a refused name is not what names the object.
  if (!errors.empty()) return validationText(errors.front(), scene_);
  auto* command = new SceneEditCommand(this, text, selection_, gesture);
  command->edited = sorted;
  command->editedBefore = std::move(before);
  command->editedAfter = extract(values, local);
  undoStack_.push(command);
  return {};
}

QString SceneDocument::addObjects(const Scene& objects, const QString& text) {
  std::size_t sizes[kObjectKindCount] = {};
  forEachKind([&](auto array, ObjectKind kind) { sizes[int(kind)] = (scene_.*array).size(); });
  emit aboutToChange();
  const Selection added = append(scene_, objects);
  const std::vector<ValidationError> errors = validateObjects(scene_, indicesOf(added), 1);
  // Worded while the added objects are there to be named.
  const QString error = errors.empty() ? QString() : validationText(errors.front(), scene_);
  forEachKind([&](auto array, ObjectKind kind) { (scene_.*array).resize(sizes[int(kind)]); });
  if (!error.isEmpty()) return error;
  if (added.empty()) return {};
  auto* command = new SceneEditCommand(this, text, added);
  command->inserted = added;
  command->insertedObjects = objects;
  command->insertedObjects.world = {};
  command->insertedObjects.extra.clear();
  undoStack_.push(command);
  return {};
}

QString SceneDocument::removeObjects(const Selection& refs, const QString& text) {
  Selection sorted = normalized(refs);
  std::erase_if(sorted, [this](const ObjectRef& ref) { return !exists(scene_, ref); });
  if (sorted.empty()) return {};
  auto* command = new SceneEditCommand(this, text, {});
  command->removed = sorted;
  command->removedObjects = extract(scene_, sorted);
  undoStack_.push(command);
  return {};
}

QString SceneDocument::editWorld(const World& world, const QString& text) {
  if (world == scene_.world) return {};
  const std::vector<ValidationError> errors = validateWorld(world, 1);
  if (!errors.empty()) return validationText(errors.front(), scene_);
  auto* command = new SceneEditCommand(this, text, selection_);
  command->worldBefore = scene_.world;
  command->worldAfter = world;
  undoStack_.push(command);
  return {};
}

void SceneDocument::setSelection(Selection selection) {
  if (!selectSilently(std::move(selection))) return;
  emit selectionChanged();
}

bool SceneDocument::selectSilently(Selection selection) {
  selection = normalized(std::move(selection));
  std::erase_if(selection, [this](const ObjectRef& ref) { return !exists(scene_, ref); });
  if (selection == selection_) return false;
  selection_ = std::move(selection);
  return true;
}

void SceneDocument::changed(const SceneChange& change, const Selection& selection) {
  // The selection first: observers of sceneChanged may read it, and old references may no
  // longer exist.
  const bool selectionChanged = selectSilently(selection);
  emit sceneChanged(change);
  if (selectionChanged) emit this->selectionChanged();
}

}  // namespace carom::editor
