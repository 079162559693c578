#include "ui/dialogs/help_dialogs.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QKeySequence>
#include <QMessageBox>
#include <QPushButton>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include <initializer_list>

namespace carom::ui {
namespace {

// Key names as the menus show them, in the program's language ("Strg+Z", "Leertaste").
QString keys(std::initializer_list<QKeySequence> sequences) {
  QStringList names;
  for (const QKeySequence& sequence : sequences)
    names << sequence.toString(QKeySequence::NativeText);
  return names.join(", ");
}

struct Entry {
  QString keys;
  QString action;
};

struct Section {
  QString title;
  QList<Entry> entries;
};

}  // namespace

HelpWindow::HelpWindow(Page page, QWidget* parent) : QDialog(parent), page_(page) {
  browser_ = new QTextBrowser;
  browser_->setOpenExternalLinks(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  if (page == Page::UserGuide) {
    // The guide links to the developer notes (docs/physics.md), which the browser opens in
    // place; Back returns to the guide.
    back_ = buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    back_->setObjectName("back");
    back_->setEnabled(false);
    connect(back_, &QPushButton::clicked, browser_, &QTextBrowser::backward);
    connect(browser_, &QTextBrowser::backwardAvailable, back_, &QPushButton::setEnabled);
    browser_->setSource(QUrl("qrc:/docs/user-guide.md"));
  }
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(page == Page::UserGuide ? 820 : 720, 760);
  retranslate();
}

QString HelpWindow::text() const {
  return browser_->toPlainText();
}

void HelpWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

void HelpWindow::retranslate() {
  switch (page_) {
    case Page::KeyboardAndMouse:
      setWindowTitle(tr("Keyboard and Mouse"));
      browser_->setHtml(keyboardAndMouseHtml());
      return;
    case Page::UserGuide:
      // The guide itself is in English only, so it is loaded once, in the constructor.
      setWindowTitle(tr("User Guide"));
      back_->setText(tr("Back"));
      return;
  }
}

QString HelpWindow::keyboardAndMouseHtml() {
  // What main_window.cpp, editor_tools.cpp, scene_view.cpp and outline_dock.cpp do with keys
  // and the mouse, by what they act on.
  const QList<Section> sections = {
      {tr("Simulation"),
       {{keys({Qt::Key_Space}), tr("Run or pause the simulation")},
        {keys({Qt::Key_S}), tr("Advance one time step, paused")},
        {keys({Qt::Key_R}), tr("Back to the scene's initial state, paused")},
        {keys({Qt::Key_Plus, Qt::Key_Equal}), tr("Larger time step (×1.25)")},
        {keys({Qt::Key_Minus}), tr("Smaller time step (÷1.25)")},
        {tr("Up, Down, wheel over a toolbar box"), tr("Change its value by a step")},
        {tr("Typing in a toolbar box, then Enter"), tr("Set the value exactly")},
        {keys({Qt::Key_F3}), tr("Mute or unmute the collision sounds")}}},
      {tr("View"),
       {{tr("Left drag on empty space"), tr("Orbit the camera round the scene")},
        {tr("Middle drag"), tr("Pan the camera")},
        {tr("Mouse wheel"), tr("Zoom")},
        {tr("Arrow keys (in the view)"), tr("Rotate the camera")},
        {keys({Qt::Key_Home}), tr("Frame the whole scene")},
        {keys({Qt::Key_F2}), tr("Follow the selected ball, or the first one; again to stop")},
        {keys({Qt::Key_F11, Qt::Key_F1}), tr("Full screen on or off")}}},
      {tr("Editing tools"),
       {{keys({Qt::Key_V}), tr("Select: click to pick, drag to move")},
        {keys({Qt::Key_B}), tr("Add Ball")},
        {keys({Qt::Key_P}), tr("Add Plane")},
        {keys({Qt::Key_C}), tr("Add Cylinder")},
        {keys({Qt::Key_K}), tr("Add Box")},
        {tr("Click with an Add tool"),
         tr("Place the object where the cursor points, on a surface or the ground")}}},
      {tr("Selecting and moving"),
       {{tr("Click"), tr("Select the object under the cursor; on nothing, clear the selection")},
        {tr("Ctrl+click, Shift+click"), tr("Add the object to the selection or take it out")},
        {tr("Drag a selected object"), tr("Move the selection in the plane facing the camera")},
        {tr("X, Y or Z held while dragging"), tr("Move along that axis only")},
        {tr("Drag the tip of the arrow"),
         tr("Change a ball's velocity, a plane's normal or a cylinder's axis")},
        {tr("Alt+drag from a ball"), tr("Draw the ball's velocity, also for a ball at rest")},
        {tr("Escape while dragging or grabbing"),
         tr("Cancel the drag: everything as it was before the press")}}},
      {tr("Running world"),
       {{tr("Drag a ball once the run has begun"),
         tr("Grab it: it follows the cursor and pushes other balls; let go to throw it")},
        {tr("X, Y or Z held while grabbing"), tr("Keep the grabbed ball on that axis")},
        {tr("Drag the timeline under the view"),
         tr("Show an earlier moment; Run goes on from there and forgets the rest")},
        {tr("Arrows, Page Up/Down, Home, End (on the timeline)"),
         tr("Step through the recorded frames")}}},
      {tr("Edit"),
       {{keys({QKeySequence::Undo}), tr("Undo")},
        {keys({Qt::CTRL | Qt::SHIFT | Qt::Key_Z, Qt::CTRL | Qt::Key_Y}), tr("Redo")},
        {keys({QKeySequence::Copy}), tr("Copy the selection (as scene text)")},
        {keys({QKeySequence::Paste}), tr("Paste objects, moved aside where they would overlap")},
        {keys({Qt::CTRL | Qt::Key_D}), tr("Duplicate the selection")},
        {keys({QKeySequence::Delete}), tr("Delete the selection")},
        {keys({QKeySequence::SelectAll}), tr("Select every object")}}},
      {tr("Files"),
       {{keys({QKeySequence::New}), tr("New scene")},
        {keys({QKeySequence::Open}), tr("Open a scene")},
        {keys({QKeySequence::Save}), tr("Save")},
        {keys({Qt::CTRL | Qt::SHIFT | Qt::Key_S}), tr("Save under another name")},
        {keys({QKeySequence::Quit}), tr("Quit")},
        {tr("Dropping a file on the window"), tr("Open it")}}},
      {tr("Outline and Properties"),
       {{tr("Click, Ctrl+click, Shift+click"), tr("Select objects, as in the view")},
        {tr("Double-click (in the outline)"), tr("Rename the object")},
        {tr("Enter, or leaving a field"), tr("Apply the typed value")}}},
      {tr("Speed vs Accuracy"),
       {{tr("Click a point"), tr("Select its run in the table")},
        {tr("Double-click a run"), tr("Apply its settings to the scene")}}}};
  QString html;
  for (const Section& section : sections) {
    html += QString("<h3>%1</h3><table cellspacing=\"0\" cellpadding=\"3\">")
                .arg(section.title.toHtmlEscaped());
    for (const Entry& entry : section.entries)
      html += QString("<tr><td width=\"40%\"><b>%1</b></td><td>%2</td></tr>")
                  .arg(entry.keys.toHtmlEscaped(), entry.action.toHtmlEscaped());
    html += "</table>";
  }
  return html;
}

void showAbout(QWidget* parent) {
  QMessageBox::about(
      parent, QCoreApplication::translate("About", "About Carom"),
      QString("<h3>%1</h3><p>%2</p><p>%3<br>%4</p>")
          .arg(
              QCoreApplication::translate("About", "Carom %1")
                  .arg(QCoreApplication::applicationVersion())
                  .toHtmlEscaped(),
              QCoreApplication::translate("About",
                                          "A sandbox and scene editor for collision physics: "
                                          "balls, planes and cylinders under gravity, solved "
                                          "exactly or in steps.")
                  .toHtmlEscaped(),
              QCoreApplication::translate("About", "Qt version %1").arg(qVersion()).toHtmlEscaped(),
              QCoreApplication::translate("About", "Released under the MIT licence.")
                  .toHtmlEscaped()));
}

}  // namespace carom::ui
