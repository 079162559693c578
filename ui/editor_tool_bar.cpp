#include "ui/editor_tool_bar.h"

#include "ui/editor/cylinder_length_field.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/number_text.h"

#include <QAction>
#include <QActionGroup>
#include <QEvent>
#include <QMenuBar>

namespace carom::ui {

using editor::EditorTools;

EditorToolBar::EditorToolBar(EditorTools* tools, QWidget* window, QWidget* parent)
    : QToolBar(parent) {
  setObjectName("tools");
  auto* group = new QActionGroup(this);
  const struct {
    EditorTools::Tool tool;
    const char* name;
    Qt::Key key;
  } entries[] = {{EditorTools::Tool::Select, "toolSelect", Qt::Key_V},
                 {EditorTools::Tool::AddBall, "toolAddBall", Qt::Key_B},
                 {EditorTools::Tool::AddPlane, "toolAddPlane", Qt::Key_P},
                 {EditorTools::Tool::AddCylinder, "toolAddCylinder", Qt::Key_C},
                 {EditorTools::Tool::AddBox, "toolAddBox", Qt::Key_K}};
  for (const auto& entry : entries) {
    QAction* action = group->addAction(QString());
    action->setObjectName(entry.name);
    action->setCheckable(true);
    action->setShortcut(entry.key);
    action->setChecked(entry.tool == tools->tool());
    connect(action, &QAction::triggered, this,
            [tools, tool = entry.tool] { tools->setTool(tool); });
    addAction(action);
    toolActions_[int(entry.tool)] = action;
  }
  // Add Cylinder's length, beside the tool while it is chosen.
  auto* cylinderLength = new editor::CylinderLengthField(tools);
  connect(cylinderLength, &editor::CylinderLengthField::refused, this, &EditorToolBar::message);
  QAction* cylinderLengthAction =
      insertWidget(toolActions_[int(EditorTools::Tool::AddBox)], cylinderLength);
  const auto showCylinderLength = [cylinderLengthAction](EditorTools::Tool tool) {
    cylinderLengthAction->setVisible(tool == EditorTools::Tool::AddCylinder);
  };
  showCylinderLength(tools->tool());
  connect(tools, &EditorTools::toolChanged, cylinderLengthAction, showCylinderLength);
  snapAction_ = new QAction(this);
  snapAction_->setObjectName("snapToGrid");
  snapAction_->setCheckable(true);
  connect(snapAction_, &QAction::toggled, this, [tools](bool on) { tools->setSnapToGrid(on); });
  addAction(snapAction_);
  window->addActions(group->actions());
  retranslate();
}

void EditorToolBar::addMenuTo(QMenuBar* menuBar) {
  menu_ = menuBar->addMenu(QString());
  menu_->setObjectName("toolsMenu");
  for (QAction* action : toolActions_) menu_->addAction(action);
  menu_->addSeparator();
  menu_->addAction(snapAction_);
  retranslate();
}

void EditorToolBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QToolBar::changeEvent(event);
}

void EditorToolBar::retranslate() {
  if (menu_) menu_->setTitle(tr("&Tools"));
  setWindowTitle(tr("Tools"));
  const QString toolTexts[] = {tr("Select"), tr("Add Ball"), tr("Add Plane"), tr("Add Cylinder"),
                               tr("Add Box")};
  for (int i = 0; i < int(std::size(toolTexts)); ++i) {
    toolActions_[i]->setText(toolTexts[i]);
    toolActions_[i]->setToolTip(tr("%1 (%2)").arg(
        toolTexts[i], toolActions_[i]->shortcut().toString(QKeySequence::NativeText)));
  }
  snapAction_->setText(tr("Snap to &Grid"));
  snapAction_->setToolTip(
      tr("Moves land on multiples of %1 m").arg(editor::formatNumber(EditorTools::gridStep())));
}

}  // namespace carom::ui
