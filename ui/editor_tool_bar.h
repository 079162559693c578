#pragma once
// The editing tools as actions: Select, Add Ball, Add Plane, Add Cylinder and Add Box with
// their keys, Add Cylinder's length beside its tool, and Snap to Grid; on a toolbar, and the same
// actions as the Tools menu.

#include <QToolBar>

class QAction;
class QMenuBar;

namespace carom::editor {
class EditorTools;
}  // namespace carom::editor
namespace carom::ui {

class EditorToolBar : public QToolBar {
  Q_OBJECT
 public:
  // The tools' keys work all over `window`.
  EditorToolBar(editor::EditorTools* tools, QWidget* window, QWidget* parent = nullptr);

  // Adds the Tools menu, with the same actions, to `menuBar`.
  void addMenuTo(QMenuBar* menuBar);

 signals:
  // A typed cylinder length was not taken.
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  static constexpr int kToolCount = 5;
  QAction* toolActions_[kToolCount] = {};  // in EditorTools::Tool order
  QAction* snapAction_ = nullptr;
  QMenu* menu_ = nullptr;
};

}  // namespace carom::ui
