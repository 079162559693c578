#include "ui/dialogs/image_export.h"

#include "sim/io/atomic_file.h"
#include "ui/render/scene_view.h"

#include <QBuffer>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QImageWriter>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <cmath>

namespace carom::ui {
namespace {

constexpr const char* kFolderKey = "export/imageFolder";

// A whole number of pixels in the user's locale ("1.920" in German) or plain digits.
bool readPixels(const QString& text, int* value) {
  bool ok = false;
  *value = QLocale().toInt(text.trimmed(), &ok);
  if (!ok) *value = text.trimmed().toInt(&ok);
  return ok;
}

}  // namespace

ImageSizeDialog::ImageSizeDialog(const QSize& initial, QWidget* parent)
    : QDialog(parent), width_(new QLineEdit), height_(new QLineEdit), error_(new QLabel) {
  setObjectName("imageSizeDialog");
  setWindowTitle(tr("Export Image"));
  width_->setObjectName("imageWidth");
  height_->setObjectName("imageHeight");
  width_->setText(QString::number(initial.width()));
  height_->setText(QString::number(initial.height()));
  error_->setObjectName("imageSizeError");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #d04040");
  error_->hide();
  auto* form = new QFormLayout;
  form->addRow(tr("Width (pixels)"), width_);
  form->addRow(tr("Height (pixels)"), height_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &ImageSizeDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &ImageSizeDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addWidget(buttons);
}

QString ImageSizeDialog::readSize(const QString& width, const QString& height, QSize* size) {
  const int low = render::SceneView::kMinPictureSide, high = render::SceneView::kMaxPictureSide;
  const QString texts[2] = {width, height};
  const QString names[2] = {tr("Width"), tr("Height")};
  int values[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    if (!readPixels(texts[i], &values[i]))
      return tr("%1: must be a whole number of pixels (got \"%2\")").arg(names[i], texts[i]);
    if (values[i] < low || values[i] > high)
      return tr("%1: must be between %2 and %3 pixels (got %4)")
          .arg(names[i])
          .arg(low)
          .arg(high)
          .arg(values[i]);
  }
  *size = QSize(values[0], values[1]);
  return {};
}

QString ImageSizeDialog::error() const {
  return error_->isVisible() ? error_->text() : QString();
}

void ImageSizeDialog::accept() {
  QSize size;
  const QString error = readSize(width_->text(), height_->text(), &size);
  if (!error.isEmpty()) {
    // The dialog stays open with what was typed, to be corrected or cancelled.
    error_->setText(error);
    error_->show();
    return;
  }
  size_ = size;
  QDialog::accept();
}

ImageExport::ImageExport(render::SceneView* view, QWidget* dialogParent, QObject* parent)
    : QObject(parent), view_(view), dialogParent_(dialogParent) {}

bool ImageExport::exportImage() {
  const double ratio = view_->devicePixelRatioF();
  const QSize viewPixels(static_cast<int>(std::lround(view_->width() * ratio)),
                         static_cast<int>(std::lround(view_->height() * ratio)));
  ImageSizeDialog sizeDialog(viewPixels, dialogParent_);
  if (sizeDialog.exec() != QDialog::Accepted) return false;
  const QSize size = sizeDialog.chosenSize();

  QSettings settings;
  const QString folder =
      settings.value(kFolderKey, QStandardPaths::writableLocation(QStandardPaths::PicturesLocation))
          .toString();
  QString file =
      QFileDialog::getSaveFileName(dialogParent_, tr("Export Image"),
                                   QDir(folder).filePath("carom.png"), tr("PNG images (*.png)"));
  if (file.isEmpty()) return false;
  if (QFileInfo(file).suffix().isEmpty()) file += ".png";
  settings.setValue(kFolderKey, QFileInfo(file).absolutePath());
  const QString error = write(file, size);
  if (!error.isEmpty()) {
    QMessageBox::warning(dialogParent_, tr("Cannot Export Image"), error);
    return false;
  }
  emit message(tr("Exported a %1×%2 image to %3").arg(size.width()).arg(size.height()).arg(file));
  return true;
}

QString ImageExport::write(const QString& fileName, const QSize& size) {
  QSize checked;
  const QString sizeError = ImageSizeDialog::readSize(QString::number(size.width()),
                                                      QString::number(size.height()), &checked);
  if (!sizeError.isEmpty()) return sizeError;
  // The scene as shown, without what belongs to the editor (handles, the selection's highlight),
  // as Export Video draws it.
  render::SceneView::Picture picture = view_->picture();
  picture.handleArrows.clear();
  picture.highlights = false;
  const QImage image = view_->renderPicture(picture, size);
  if (image.isNull())
    return tr("The graphics driver could not draw a %1×%2 picture.")
        .arg(size.width())
        .arg(size.height());
  return writePng(image, fileName);
}

QString ImageExport::writePng(const QImage& image, const QString& fileName) {
  QBuffer encoded;
  encoded.open(QIODevice::WriteOnly);
  QImageWriter writer(&encoded, "png");
  QString error;
  if (writer.write(image) ? io::writeFileAtomically(fileName, encoded.data(), &error)
                          : (error = writer.errorString(), false))
    return {};
  return tr("Could not write %1: %2").arg(QDir::toNativeSeparators(fileName), error);
}

}  // namespace carom::ui
