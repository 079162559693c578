#include "ui/editor/cylinder_length_field.h"

#include "ui/editor/editor_tools.h"
#include "ui/editor/number_text.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

#include <cmath>

namespace carom::editor {

CylinderLengthField::CylinderLengthField(EditorTools* tools, QWidget* parent)
    : QWidget(parent), tools_(tools), label_(new QLabel), edit_(new QLineEdit) {
  edit_->setObjectName("toolCylinderLength");
  edit_->setMaximumWidth(edit_->fontMetrics().horizontalAdvance(QString(12, '0')));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 0, 4, 0);
  layout->addWidget(label_);
  layout->addWidget(edit_);
  connect(edit_, &QLineEdit::editingFinished, this, &CylinderLengthField::lengthTyped);
  connect(tools_, &EditorTools::cylinderLengthChanged, this, &CylinderLengthField::showLength);
  retranslate();
  showLength();
}

void CylinderLengthField::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void CylinderLengthField::retranslate() {
  label_->setText(tr("Length (m):"));
  edit_->setPlaceholderText(tr("infinite"));
  edit_->setToolTip(tr("The length of the cylinders Add Cylinder places; empty: infinite"));
  showLength();
}

void CylinderLengthField::showLength() {
  const std::optional<double> length = tools_->cylinderLength();
  edit_->setText(length ? formatShortNumber(*length) : QString());
  edit_->setModified(false);
}

void CylinderLengthField::lengthTyped() {
  if (!edit_->isModified()) return;
  const QString typed = edit_->text().trimmed();
  if (typed.isEmpty()) {
    tools_->setCylinderLength(std::nullopt);
    showLength();
    return;
  }
  const ParsedNumber parsed = parseNumber(typed);
  if (!parsed.value) {
    emit refused(tr("Cylinder length: %1").arg(parsed.problem));
  } else if (!(std::isfinite(*parsed.value) && *parsed.value > 0.0)) {
    emit refused(tr("Cylinder length: must be a positive number (got %1)").arg(typed));
  } else {
    tools_->setCylinderLength(parsed.value);
  }
  showLength();
}

}  // namespace carom::editor
