#include "ui/editor/number_field.h"

#include "ui/editor/number_text.h"
#include "ui/editor/properties_dock.h"

#include <QFocusEvent>
#include <QSignalBlocker>

namespace carom::editor {

void NumberField::setName(const QString& name, const QString& hint) {
  name_ = name;
  hint_ = hint;
  showValue();
}

void NumberField::setValue(std::optional<double> value) {
  value_ = value;
  showValue();
}

QSize NumberField::sizeHint() const {
  QSize size = QLineEdit::sizeHint();
  const QFontMetrics metrics = fontMetrics();
  size.rwidth() += metrics.horizontalAdvance(formatNumber(-0.888888, 'f', 6)) -
                   17 * metrics.horizontalAdvance(QLatin1Char('x')) + kCursorWidth;
  return size;
}

void NumberField::focusInEvent(QFocusEvent* event) {
  if (!isModified()) showValue(true);
  QLineEdit::focusInEvent(event);
}

void NumberField::focusOutEvent(QFocusEvent* event) {
  QLineEdit::focusOutEvent(event);  // finishes the edit, which may show a new value
  // A context menu takes the focus for a moment, in the middle of an edit.
  if (event->reason() != Qt::PopupFocusReason && !isModified()) showValue(false);
}

void NumberField::showValue(bool editing) {
  const QSignalBlocker blocker(this);
  QString text;
  if (value_) text = editing ? formatNumber(*value_) : formatShortNumber(*value_);
  setText(text);
  // setText() leaves the cursor at the end, and a field too narrow for its text scrolls to
  // show the cursor: "-0.642395" read "642395". Shown at rest, the value's start (its sign
  // and leading digits) matters most.
  if (!editing) setCursorPosition(0);
  setModified(false);
  // In the properties dock's words, where the field shows.
  QStringList tip{value_ ? PropertiesDock::tr("%1: %2").arg(name_, formatNumber(*value_)) : name_};
  if (!hint_.isEmpty()) tip << hint_;
  setToolTip(tip.join('\n'));
}

}  // namespace carom::editor
