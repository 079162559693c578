#pragma once
// Answerers for modal dialogs, for tests with or without a window: each waits for the next
// dialog of its kind and never lets one hang the run.

#include <QApplication>
#include <QDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <functional>

namespace carom::testing {

// Waits for the next modal dialog of type `Dialog`, then hands it to `answer` (which must close
// it). Gives up after five seconds, closing whatever modal dialog is up, so no test hangs.
template <typename Dialog>
class ModalAnswerer {
 public:
  explicit ModalAnswerer(std::function<void(Dialog*)> answer) : answer_(std::move(answer)) {
    QTimer::singleShot(0, [this] { poll(); });
  }
  bool answered() const { return answered_; }

 private:
  void poll() {
    QWidget* modal = QApplication::activeModalWidget();
    if (auto* dialog = qobject_cast<Dialog*>(modal)) {
      answered_ = true;
      answer_(dialog);
      return;
    }
    if (++attempts_ < 500) {
      QTimer::singleShot(10, [this] { poll(); });
    } else if (auto* other = qobject_cast<QDialog*>(modal)) {
      other->reject();
    }
  }
  std::function<void(Dialog*)> answer_;
  bool answered_ = false;
  int attempts_ = 0;
};

// Presses `button` in the next message box and records its text.
class DialogAnswerer {
 public:
  explicit DialogAnswerer(QMessageBox::StandardButton button)
      : answerer_([this, button](QMessageBox* box) {
          text_ = box->text();
          box->button(button)->click();
        }) {}
  QString text() const { return text_; }
  bool answered() const { return answerer_.answered(); }

 private:
  QString text_;
  ModalAnswerer<QMessageBox> answerer_;
};

}  // namespace carom::testing
