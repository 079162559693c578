#pragma once
// Every object of the scene in a tree grouped by kind, with names and colours, after Tiled's
// Objects dock. Its selection and the document's are one: selecting in either shows in both.
// Names are edited in place (double-click or F2), as one command each.

#include "ui/editor/object_ref.h"

#include <QAbstractItemModel>
#include <QDockWidget>

#include <array>
#include <optional>

class QTreeView;

namespace carom::editor {

class SceneDocument;
struct SceneChange;

// Reads the document's scene directly: building it costs nothing however many balls there are.
class OutlineModel : public QAbstractItemModel {
  Q_OBJECT
 public:
  explicit OutlineModel(SceneDocument* document, QObject* parent = nullptr);

  QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
  QModelIndex parent(const QModelIndex& child) const override;
  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;

  QModelIndex groupIndex(ObjectKind kind) const;
  QModelIndex indexOf(const ObjectRef& ref) const;
  // The object an index names; nothing for a group.
  std::optional<ObjectRef> objectAt(const QModelIndex& index) const;
  // Tells the views that every row's text changed, as after a change of language.
  void retranslate();

 signals:
  // A rename was refused; the text says why.
  void refused(const QString& message);

 private:
  // Brings the rows in line with the document's scene.
  void sync(const SceneChange& change);

  SceneDocument* document_;
  // The rows each group has in the views' eyes, updated with insert and remove notices.
  std::array<int, kObjectKindCount> counts_{};
};

class OutlineDock : public QDockWidget {
  Q_OBJECT
 public:
  explicit OutlineDock(SceneDocument* document, QWidget* parent = nullptr);

  QTreeView* tree() const { return tree_; }
  OutlineModel* model() const { return model_; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void showSelection();
  void selectionEdited();

  SceneDocument* document_;
  OutlineModel* model_;
  QTreeView* tree_;
  bool showingSelection_ = false;
};

}  // namespace carom::editor
