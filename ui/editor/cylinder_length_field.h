#pragma once
// Add Cylinder's option on the tools bar: the length of the cylinders the tool places, empty for
// infinite ones. It shows the tool's length (which follows the cylinder last added or changed)
// and sets it as typed.

#include <QWidget>

class QLabel;
class QLineEdit;

namespace carom::editor {

class EditorTools;

class CylinderLengthField : public QWidget {
  Q_OBJECT
 public:
  explicit CylinderLengthField(EditorTools* tools, QWidget* parent = nullptr);

 signals:
  // A typed length was not taken (not a number, not positive); the field shows the tool's again.
  void refused(const QString& message);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void showLength();
  void lengthTyped();

  EditorTools* tools_;
  QLabel* label_;
  QLineEdit* edit_;
};

}  // namespace carom::editor
