#pragma once

#include <QDoubleSpinBox>

namespace carom::ui {

// A spin box for the toolbar that refuses what it cannot take with a message, where
// QDoubleSpinBox silently drops keystrokes or clamps. It shows six significant digits rather
// than fixed decimals, so its range can be the scene validation's whole range.
class NumberBox : public QDoubleSpinBox {
  Q_OBJECT

 public:
  // `name` starts the messages: "Time step: must be between …".
  NumberBox(const QString& name, double low, double high, double step, QWidget* parent = nullptr);
  // In another language.
  void setName(const QString& name) { name_ = name; }

  QValidator::State validate(QString& text, int& position) const override;
  void fixup(QString& text) const override;
  double valueFromText(const QString& text) const override;
  QString textFromValue(double value) const override;
  QSize sizeHint() const override;

 signals:
  // A typed text was not taken; the box shows its value again.
  void refused(const QString& message);

 protected:
  void focusOutEvent(QFocusEvent* event) override;

 private:
  // Why `text` cannot be the value, or nothing when it can.
  QString problem(const QString& text) const;
  void reportRefusal();

  QString name_;
  // Set by fixup(), which QAbstractSpinBox calls with text it will not take, and reported when
  // editing finishes.
  mutable QString refusedText_;
};

}  // namespace carom::ui
