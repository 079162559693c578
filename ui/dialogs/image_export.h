#pragma once
// File > Export Image: the view's current picture rendered offscreen at a chosen size
// (SceneView::renderPicture, not a grab of the screen) and written as a PNG.

#include <QDialog>
#include <QObject>
#include <QSize>
#include <QString>

class QImage;
class QLabel;
class QLineEdit;

namespace carom::render {
class SceneView;
}
namespace carom::ui {

// Width and height in pixels, typed; OK with a bad value says why and keeps the dialog open.
class ImageSizeDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ImageSizeDialog(const QSize& initial, QWidget* parent = nullptr);

  QSize chosenSize() const { return size_; }
  // The size typed, as whole pixels (in the user's locale or plain digits), each side from
  // SceneView::kMinPictureSide to kMaxPictureSide; otherwise the message saying why.
  static QString readSize(const QString& width, const QString& height, QSize* size);
  QString error() const;

  void accept() override;

 private:
  QLineEdit* width_;
  QLineEdit* height_;
  QLabel* error_;
  QSize size_;
};

class ImageExport : public QObject {
  Q_OBJECT
 public:
  // Dialogs open over `dialogParent`.
  ImageExport(render::SceneView* view, QWidget* dialogParent, QObject* parent = nullptr);

  // Asks for the size (the view's own to start with) and the file, then writes the image.
  // False when cancelled or the image could not be made or written (which a dialog says).
  bool exportImage();
  // Renders the view's current picture at `size` and writes it to `fileName` as a PNG; empty
  // when done, otherwise the reason.
  QString write(const QString& fileName, const QSize& size);
  // Writes `image` to `fileName` as a PNG, whole or not at all (a full disk leaves no cut file);
  // empty when done, otherwise the reason.
  static QString writePng(const QImage& image, const QString& fileName);

 signals:
  void message(const QString& text);

 private:
  render::SceneView* view_;
  QWidget* dialogParent_;
};

}  // namespace carom::ui
