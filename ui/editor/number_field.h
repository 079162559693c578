#pragma once
// A field for a number: six significant digits to read, as the toolbar's boxes show them, and
// the shortest text that reads back as the same value while it is edited and in its tooltip. A
// field left without a change is not modified, so it never rounds what is stored.

#include <QLineEdit>
#include <QString>

#include <optional>

namespace carom::editor {

class NumberField : public QLineEdit {
 public:
  // What the tooltip calls the field ("Position x"); `hint` is a line added under it.
  void setName(const QString& name, const QString& hint = {});
  // Nothing: an empty field (several objects that differ, a restitution left to the world).
  void setValue(std::optional<double> value);
  // Room for a six-digit value with its sign ("-0.642395") instead of QLineEdit's 17 x's.
  QSize sizeHint() const override;

 protected:
  void focusInEvent(QFocusEvent* event) override;
  void focusOutEvent(QFocusEvent* event) override;

 private:
  void showValue() { showValue(hasFocus()); }
  void showValue(bool editing);

  // The text cursor's width, which QLineEdit's own size hint leaves room for as well.
  static constexpr int kCursorWidth = 1;

  QString name_;
  QString hint_;
  std::optional<double> value_;
};

}  // namespace carom::editor
