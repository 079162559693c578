#include "ui/editor/outline_dock.h"

#include "ui/editor/object_kinds.h"
#include "ui/editor/scene_document.h"

#include <QColor>
#include <QHeaderView>
#include <QItemSelection>
#include <QKeyEvent>
#include <QPixmap>
#include <QTreeView>

#include <algorithm>

namespace carom::editor {
namespace {

// Children carry their group's number plus one; groups carry 0.
constexpr quintptr kGroupId = 0;

ObjectKind kindOfGroup(int row) {
  return static_cast<ObjectKind>(row);
}

}  // namespace

OutlineModel::OutlineModel(SceneDocument* document, QObject* parent)
    : QAbstractItemModel(parent), document_(document) {
  for (int g = 0; g < kObjectKindCount; ++g)
    counts_[g] = objectCount(document_->scene(), kindOfGroup(g));
  connect(document_, &SceneDocument::sceneChanged, this, &OutlineModel::sync);
}

void OutlineModel::sync(const SceneChange& change) {
  if (change.replaced) {
    beginResetModel();
    for (int g = 0; g < kObjectKindCount; ++g)
      counts_[g] = objectCount(document_->scene(), kindOfGroup(g));
    endResetModel();
    return;
  }
  // Rows are removed and inserted where the objects were and are, in runs of neighbours, and
  // only rows whose label may have changed are announced: edited objects, and those whose
  // index moved ("Ball 7" becomes "Ball 6").
  for (int g = 0; g < kObjectKindCount; ++g) {
    const ObjectKind kind = kindOfGroup(g);
    const QModelIndex group = index(g, 0);
    std::vector<int> removed, inserted;
    for (const ObjectRef& ref : change.removed)
      if (ref.kind == kind) removed.push_back(ref.index);
    for (const ObjectRef& ref : change.inserted)
      if (ref.kind == kind) inserted.push_back(ref.index);
    for (std::size_t end = removed.size(); end > 0;) {
      std::size_t begin = end - 1;
      while (begin > 0 && removed[begin - 1] == removed[begin] - 1) --begin;
      beginRemoveRows(group, removed[begin], removed[end - 1]);
      counts_[g] -= int(end - begin);
      endRemoveRows();
      end = begin;
    }
    for (std::size_t begin = 0; begin < inserted.size();) {
      std::size_t end = begin + 1;
      while (end < inserted.size() && inserted[end] == inserted[end - 1] + 1) ++end;
      beginInsertRows(group, inserted[begin], inserted[end - 1]);
      counts_[g] += int(end - begin);
      endInsertRows();
      begin = end;
    }
    if (!removed.empty() || !inserted.empty()) {
      const int firstMoved = std::min(removed.empty() ? counts_[g] : removed.front(),
                                      inserted.empty() ? counts_[g] : inserted.front());
      if (firstMoved < counts_[g])
        emit dataChanged(index(firstMoved, 0, group), index(counts_[g] - 1, 0, group));
      emit dataChanged(group, group);  // its count
    }
  }
  // Runs of neighbours as one range each: Use Current State edits every ball.
  const Selection& edited = change.edited;
  for (std::size_t first = 0; first < edited.size();) {
    std::size_t last = first;
    while (last + 1 < edited.size() && edited[last + 1].kind == edited[first].kind &&
           edited[last + 1].index == edited[last].index + 1)
      ++last;
    const QModelIndex top = indexOf(edited[first]), bottom = indexOf(edited[last]);
    if (top.isValid() && bottom.isValid()) emit dataChanged(top, bottom);
    first = last + 1;
  }
}

QModelIndex OutlineModel::index(int row, int column, const QModelIndex& parent) const {
  if (column != 0 || row < 0) return {};
  if (!parent.isValid())
    return row < kObjectKindCount ? createIndex(row, 0, kGroupId) : QModelIndex();
  if (parent.internalId() != kGroupId || row >= counts_[parent.row()]) return {};
  return createIndex(row, 0, quintptr(parent.row() + 1));
}

QModelIndex OutlineModel::parent(const QModelIndex& child) const {
  if (!child.isValid() || child.internalId() == kGroupId) return {};
  return createIndex(int(child.internalId() - 1), 0, kGroupId);
}

int OutlineModel::rowCount(const QModelIndex& parent) const {
  if (!parent.isValid()) return kObjectKindCount;
  if (parent.internalId() != kGroupId) return 0;
  return counts_[parent.row()];
}

int OutlineModel::columnCount(const QModelIndex&) const {
  return 1;
}

QModelIndex OutlineModel::groupIndex(ObjectKind kind) const {
  return index(static_cast<int>(kind), 0);
}

QModelIndex OutlineModel::indexOf(const ObjectRef& ref) const {
  return index(ref.index, 0, groupIndex(ref.kind));
}

void OutlineModel::retranslate() {
  // Group names and unnamed objects' labels ("Ball 3") are made in the current language.
  for (int g = 0; g < kObjectKindCount; ++g) {
    const QModelIndex group = index(g, 0);
    emit dataChanged(group, group, {Qt::DisplayRole});
    if (counts_[g] > 0)
      emit dataChanged(index(0, 0, group), index(counts_[g] - 1, 0, group), {Qt::DisplayRole});
  }
}

std::optional<ObjectRef> OutlineModel::objectAt(const QModelIndex& index) const {
  if (!index.isValid() || index.internalId() == kGroupId) return std::nullopt;
  const ObjectRef ref{kindOfGroup(int(index.internalId() - 1)), index.row()};
  if (!exists(document_->scene(), ref)) return std::nullopt;
  return ref;
}

QVariant OutlineModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid()) return {};
  const Scene& scene = document_->scene();
  if (index.internalId() == kGroupId) {
    const ObjectKind kind = kindOfGroup(index.row());
    if (role == Qt::DisplayRole)
      return tr("%1 (%2)").arg(kindPluralName(kind)).arg(objectCount(scene, kind));
    return {};
  }
  const std::optional<ObjectRef> ref = objectAt(index);
  if (!ref) return {};
  switch (role) {
    case Qt::DisplayRole:
      return objectLabel(scene, *ref);
    case Qt::EditRole:
      return QString::fromStdString(objectInfo(scene, *ref).name);
    case Qt::ToolTipRole:
      // The scene file's list name, as the validation's messages use.
      return QString("%1[%2]").arg(kindInfo(ref->kind).list).arg(ref->index);
    case Qt::DecorationRole: {
      const QColor color(QString::fromStdString(objectInfo(scene, *ref).color));
      if (!color.isValid()) return {};
      QPixmap swatch(12, 12);
      swatch.fill(color);
      return swatch;
    }
    default:
      return {};
  }
}

bool OutlineModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  const std::optional<ObjectRef> ref = objectAt(index);
  if (!ref || role != Qt::EditRole) return false;
  Scene values = extract(document_->scene(), {*ref});
  objectInfo(values, extractedRefs({*ref}).front()).name = value.toString().trimmed().toStdString();
  const QString error = document_->editObjects({*ref}, values, tr("Rename"));
  if (!error.isEmpty()) emit refused(error);
  return error.isEmpty();
}

Qt::ItemFlags OutlineModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::NoItemFlags;
  if (index.internalId() == kGroupId) return Qt::ItemIsEnabled;
  return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable;
}

OutlineDock::OutlineDock(SceneDocument* document, QWidget* parent)
    : QDockWidget(parent),
      document_(document),
      model_(new OutlineModel(document, this)),
      tree_(new QTreeView) {
  setObjectName("outlineDock");
  tree_->setObjectName("outline");
  tree_->setModel(model_);
  tree_->setHeaderHidden(true);
  tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  // F2, the usual key, is the window's for following a ball, wherever the focus is.
  tree_->setEditTriggers(QAbstractItemView::DoubleClicked);
  // Every row is one line: the view need not measure 100,000 of them.
  tree_->setUniformRowHeights(true);
  // Long names keep their start and their end, where names of a series differ ("post 12").
  tree_->setTextElideMode(Qt::ElideMiddle);
  tree_->expandAll();
  setWidget(tree_);
  connect(tree_->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          &OutlineDock::selectionEdited);
  // After the model has caught up with the scene (it connected first).
  connect(document_, &SceneDocument::sceneChanged, this, &OutlineDock::showSelection);
  connect(document_, &SceneDocument::selectionChanged, this, &OutlineDock::showSelection);
  showSelection();
  retranslate();
}

void OutlineDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void OutlineDock::retranslate() {
  setWindowTitle(tr("Outline"));
  model_->retranslate();
}

void OutlineDock::showSelection() {
  // Runs of consecutive indices become one range each, so Select All on a large scene is one
  // range a kind.
  QItemSelection selection;
  const Selection& refs = document_->selection();
  for (std::size_t i = 0; i < refs.size();) {
    std::size_t last = i;
    while (last + 1 < refs.size() && refs[last + 1].kind == refs[i].kind &&
           refs[last + 1].index == refs[last].index + 1)
      ++last;
    selection.select(model_->indexOf(refs[i]), model_->indexOf(refs[last]));
    i = last + 1;
  }
  showingSelection_ = true;
  tree_->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
  if (!refs.empty()) {
    const QModelIndex first = model_->indexOf(refs.front());
    tree_->expand(first.parent());
    tree_->selectionModel()->setCurrentIndex(first, QItemSelectionModel::NoUpdate);
    tree_->scrollTo(first);
  }
  showingSelection_ = false;
}

void OutlineDock::selectionEdited() {
  if (showingSelection_) return;
  Selection selection;
  for (const QItemSelectionRange& range : tree_->selectionModel()->selection()) {
    const QModelIndex top = range.topLeft();
    const std::optional<ObjectRef> first = model_->objectAt(top);
    if (!first) continue;
    for (int row = top.row(); row <= range.bottom(); ++row) selection.push_back({first->kind, row});
  }
  document_->setSelection(selection);
}

}  // namespace carom::editor
