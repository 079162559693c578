#pragma once
// The Help menu's windows: every key and mouse action of the program, the user guide
// (docs/user-guide.md, built in, with a link to the developers' physics notes, docs/physics.md),
// and the About box. The two windows are not modal, so they can stay open
// beside the scene while it is used.

#include <QDialog>

class QPushButton;
class QTextBrowser;
class QWidget;

namespace carom::ui {

// A page of help in a window of its own, written again when the language changes.
class HelpWindow : public QDialog {
  Q_OBJECT
 public:
  enum class Page {
    KeyboardAndMouse,  // every key and mouse action, translated
    UserGuide,         // docs/user-guide.md, in English
  };
  explicit HelpWindow(Page page, QWidget* parent = nullptr);
  Page page() const { return page_; }

  // The page shown, as plain text.
  QString text() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  // The reference of keys and mouse actions as HTML tables.
  static QString keyboardAndMouseHtml();

  Page page_;
  QTextBrowser* browser_;
  QPushButton* back_ = nullptr;  // the user guide's, back from the developer notes
};

// Carom's version, Qt's, the licence and what Carom is, in a modal message box.
void showAbout(QWidget* parent);

}  // namespace carom::ui
