#pragma once
// The Help menu's windows: every key and mouse action of the program, the physics notes
// (docs/physics.md, built in), and the About box. The two windows are not modal, so they can stay
// open beside the scene while it is used.

#include <QDialog>

class QTextBrowser;
class QWidget;

namespace carom::ui {

// A page of help in a window of its own, written again when the language changes.
class HelpWindow : public QDialog {
  Q_OBJECT
 public:
  enum class Page {
    KeyboardAndMouse,  // every key and mouse action, translated
    PhysicsNotes,      // docs/physics.md, in English
  };
  explicit HelpWindow(Page page, QWidget* parent = nullptr);
  Page page() const { return page_; }

  // The page as plain text.
  QString text() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  // The reference of keys and mouse actions as HTML tables.
  static QString keyboardAndMouseHtml();

  Page page_;
  QTextBrowser* browser_;
};

// Carom's version, Qt's, the licence and what Carom is, in a modal message box.
void showAbout(QWidget* parent);

}  // namespace carom::ui
