#include "ui/editor/properties_dock.h"

#include "ui/editor/number_field.h"
#include "ui/editor/number_text.h"
#include "ui/editor/object_kinds.h"
#include "ui/editor/scene_document.h"
#include "ui/editor/standing.h"

#include <QColorDialog>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <bit>
#include <optional>

namespace carom::editor {

namespace {

// The value every target shares, or nothing when they differ.
template <typename T, typename Read>
std::optional<T> common(const Selection& targets, Read read) {
  std::optional<T> shared;
  for (const ObjectRef& ref : targets) {
    const T value = read(ref);
    if (!shared)
      shared = value;
    else if (!(*shared == value))
      return std::nullopt;
  }
  return shared;
}

}  // namespace

PropertiesDock::PropertiesDock(SceneDocument* document, QWidget* parent)
    : QDockWidget(parent), document_(document) {
  setObjectName("propertiesDock");
  auto* body = new QWidget;
  auto* layout = new QVBoxLayout(body);
  heading_ = new QLabel;
  heading_->setObjectName("propertiesHeading");
  QFont bold = heading_->font();
  bold.setBold(true);
  heading_->setFont(bold);
  layout->addWidget(heading_);
  form_ = new QFormLayout;
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  layout->addLayout(form_);
  message_ = new QLabel;
  message_->setObjectName("propertiesMessage");
  message_->setWordWrap(true);
  message_->setStyleSheet("color: #b00020");
  message_->setContentsMargins(layout->contentsMargins());
  layout->addStretch(1);

  const char* m = QT_TR_NOOP("m");
  const char* mPerS = QT_TR_NOOP("m/s");
  const char* kg = QT_TR_NOOP("kg");
  const char* s = QT_TR_NOOP("s");
  const char* mPerS2 = QT_TR_NOOP("m/s²");
  const char* direction = QT_TR_NOOP("(any length)");
  addText(kObjects, "name", QT_TR_NOOP("Name"), QT_TR_NOOP("Rename"),
          [](const Scene& scene, const ObjectRef& r) { return &objectInfo(scene, r).name; });
  colorButton_ = new QToolButton;
  colorButton_->setObjectName("pickColor");
  connect(colorButton_, &QToolButton::clicked, this, &PropertiesDock::pickColor);
  addText(
      kObjects, "color", QT_TR_NOOP("Colour"), QT_TR_NOOP("Change Colour"),
      [](const Scene& scene, const ObjectRef& r) { return &objectInfo(scene, r).color; },
      colorButton_);
  colorRow_ = texts_.back().row;
  color_ = texts_.back().edit;
  addRestitution();

  addVector(kBalls, "position", QT_TR_NOOP("Position"), QT_TR_NOOP("Move"), m,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].position; });
  addVector(kBalls, "velocity", QT_TR_NOOP("Velocity"), QT_TR_NOOP("Change Velocity"), mPerS,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].velocity; });
  addNumber(kBalls, "ballRadius", QT_TR_NOOP("Radius"), QT_TR_NOOP("Change Radius"), m,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].radius; });
  addNumber(kBalls, "mass", QT_TR_NOOP("Mass"), QT_TR_NOOP("Change Mass"), kg,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].mass; });
  addVector(kPlanes | kCylinders, "point", QT_TR_NOOP("Point"), QT_TR_NOOP("Move"), m,
            [](const Scene& scene, const ObjectRef& r) {
              return r.kind == ObjectKind::Plane ? &scene.planes[r.index].point
                                                 : &scene.cylinders[r.index].point;
            });
  addVector(
      kPlanes, "normal", QT_TR_NOOP("Normal"), QT_TR_NOOP("Turn Plane"), direction,
      [](const Scene& scene, const ObjectRef& r) { return &scene.planes[r.index].normal; },
      UnitPlace::Below);
  addVector(
      kCylinders, "axis", QT_TR_NOOP("Axis"), QT_TR_NOOP("Turn Cylinder"), direction,
      [](const Scene& scene, const ObjectRef& r) { return &scene.cylinders[r.index].axis; },
      UnitPlace::Below);
  addNumber(
      kCylinders, "cylinderRadius", QT_TR_NOOP("Radius"), QT_TR_NOOP("Change Radius"), m,
      [](const Scene& scene, const ObjectRef& r) { return &scene.cylinders[r.index].radius; });
  addLength();

  addVector(kBoxes, "center", QT_TR_NOOP("Centre"), QT_TR_NOOP("Move"), m,
            [](const Scene& scene, const ObjectRef& r) { return &scene.boxes[r.index].center; });
  addVector(
      kBoxes, "halfExtents", QT_TR_NOOP("Half extents"), QT_TR_NOOP("Resize Box"), m,
      [](const Scene& scene, const ObjectRef& r) { return &scene.boxes[r.index].halfExtents; });
  addRotation();

  addVector(kWorld, "gravity", QT_TR_NOOP("Gravity"), QT_TR_NOOP("Change Gravity"), mPerS2,
            [](const Scene& scene, const ObjectRef&) { return &scene.world.gravity; });
  addNumber(kWorld, "timeStep", QT_TR_NOOP("Time step"), QT_TR_NOOP("Change Time Step"), s,
            [](const Scene& scene, const ObjectRef&) { return &scene.world.timeStep; });
  addNumber(kWorld, "worldRestitution", QT_TR_NOOP("Restitution"), QT_TR_NOOP("Change Restitution"),
            nullptr, [](const Scene& scene, const ObjectRef&) { return &scene.world.restitution; });
  method_ = addChoice("method", QT_TR_NOOP("Method"), QT_TR_NOOP("Change Method"), methodNames(),
                      [](World& world, int index) { world.method = Method(index); });
  integrator_ = addChoice("integrator", QT_TR_NOOP("Integrator"), QT_TR_NOOP("Change Integrator"),
                          integratorNames(),
                          [](World& world, int index) { world.integrator = Integrator(index); });

  scroll_ = new QScrollArea;
  scroll_->setWidget(body);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  // The refusal goes under the scroll area, always in sight: as the rows' last one it lay below
  // a ball's Mass at the default size, out of view, and its height for its width could squash
  // the rows.
  auto* frame = new QWidget;
  auto* frameLayout = new QVBoxLayout(frame);
  frameLayout->setContentsMargins(0, 0, 0, 0);
  frameLayout->setSpacing(0);
  frameLayout->addWidget(scroll_, 1);
  frameLayout->addWidget(message_);
  setWidget(frame);

  // Any change of the scene or the selection makes a refusal old news.
  connect(document_, &SceneDocument::sceneChanged, this, [this] {
    message_->clear();
    refresh();
  });
  connect(document_, &SceneDocument::selectionChanged, this, [this] {
    message_->clear();
    refresh();
  });
  retranslate();
}

void PropertiesDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void PropertiesDock::retranslate() {
  setWindowTitle(tr("Properties"));
  for (const Row& row : rows_) {
    row.labelWidget->setText(tr(row.label));
    if (row.unitWidget) row.unitWidget->setText(tr(row.unit));
  }
  const char* axes[3] = {"x", "y", "z"};
  for (const NumberEditor& editor : numbers_) {
    if (editor.number)
      editor.edit->setName(label(editor.row));
    else
      editor.edit->setName(QString("%1 %2").arg(label(editor.row), axes[editor.component]));
  }
  restitution_->setName(label(restitutionRow_), tr("0 to 1; empty: the world's restitution"));
  length_->setName(label(lengthRow_), tr("Between the caps; empty: infinite"));
  for (int a = 0; a < 3; ++a)
    rotationFields_[a]->setName(QString("%1 %2").arg(label(rotationAxisRow_), axes[a]));
  rotationFields_[3]->setName(label(rotationDegreesRow_),
                              tr("Degrees about the axis, right-handed; empty: not turned"));
  colorButton_->setText(tr("…"));
  colorButton_->setToolTip(tr("Choose a colour"));
  if (auto* dialog = findChild<QColorDialog*>()) dialog->setWindowTitle(tr("Object Colour"));
  refresh();
}

QString PropertiesDock::label(int row) const {
  return tr(rows_[row].label);
}

QString PropertiesDock::change(int row) const {
  return tr(rows_[row].change);
}

QString PropertiesDock::heading() const {
  return heading_->text();
}

QString PropertiesDock::message() const {
  return message_->text();
}

QSize PropertiesDock::sizeHint() const {
  // Hidden rows count too: the dock should not need more room when the selection changes.
  int labels = 0;
  int fields = 0;
  for (const Row& row : rows_) {
    labels = std::max(labels, row.labelWidget->sizeHint().width());
    fields = std::max(fields, row.widgets.back()->sizeHint().width());
  }
  const QMargins margins = scroll_->widget()->layout()->contentsMargins();
  // A scroll bar may come with a long selection's rows; it takes its width from the fields.
  const int body = margins.left() + labels + form_->horizontalSpacing() + fields + margins.right() +
                   scroll_->verticalScrollBar()->sizeHint().width();
  QSize size = QDockWidget::sizeHint();
  size.setWidth(std::max(size.width(), size.width() - scroll_->sizeHint().width() + body));
  return size;
}

int PropertiesDock::addRow(int kinds, const char* label, const char* change, QWidget* field,
                           const char* unit, UnitPlace place) {
  auto* labelWidget = new QLabel;
  std::vector<QWidget*> widgets = {labelWidget};
  QWidget* shown = field;
  QLabel* unitWidget = nullptr;
  if (unit) {
    shown = new QWidget;
    unitWidget = new QLabel;
    if (place == UnitPlace::Beside) {
      auto* line = new QHBoxLayout(shown);
      line->setContentsMargins(0, 0, 0, 0);
      line->addWidget(field, 1);
      line->addWidget(unitWidget);
    } else {
      auto* column = new QVBoxLayout(shown);
      column->setContentsMargins(0, 0, 0, 0);
      column->setSpacing(0);
      column->addWidget(field);
      column->addWidget(unitWidget);
      unitWidget->setForegroundRole(QPalette::PlaceholderText);
    }
  }
  widgets.push_back(shown);
  labelWidget->setBuddy(field);
  form_->addRow(labelWidget, shown);
  rows_.push_back({kinds, label, change, unit, labelWidget, unitWidget, widgets});
  return static_cast<int>(rows_.size()) - 1;
}

void PropertiesDock::addNumber(int kinds, const char* name, const char* label, const char* change,
                               const char* unit, NumberAccess access) {
  auto* edit = new NumberField;
  edit->setObjectName(name);
  const int row = addRow(kinds, label, change, edit, unit);
  numbers_.push_back({edit, row, access, nullptr, 0});
  connect(edit, &QLineEdit::editingFinished, this,
          [this, index = numbers_.size() - 1] { numberEdited(numbers_[index]); });
}

void PropertiesDock::addVector(int kinds, const char* name, const char* label, const char* change,
                               const char* unit, VectorAccess access, UnitPlace place) {
  auto* fields = new QWidget;
  auto* line = new QHBoxLayout(fields);
  line->setContentsMargins(0, 0, 0, 0);
  const int row = addRow(kinds, label, change, fields, unit, place);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    auto* edit = new NumberField;
    edit->setObjectName(QString("%1.%2").arg(name, axes[a]));
    line->addWidget(edit);
    numbers_.push_back({edit, row, nullptr, access, a});
    connect(edit, &QLineEdit::editingFinished, this,
            [this, index = numbers_.size() - 1] { numberEdited(numbers_[index]); });
  }
}

void PropertiesDock::addText(int kinds, const char* name, const char* label, const char* change,
                             TextAccess access, QToolButton* extra) {
  auto* edit = new QLineEdit;
  edit->setObjectName(name);
  QWidget* field = edit;
  if (extra) {
    field = new QWidget;
    auto* line = new QHBoxLayout(field);
    line->setContentsMargins(0, 0, 0, 0);
    line->addWidget(edit, 1);
    line->addWidget(extra);
  }
  const int row = addRow(kinds, label, change, field);
  texts_.push_back({edit, row, access});
  connect(edit, &QLineEdit::editingFinished, this,
          [this, index = texts_.size() - 1] { textEdited(texts_[index]); });
}

void PropertiesDock::addRestitution() {
  restitution_ = new NumberField;
  restitution_->setObjectName("restitution");
  restitutionRow_ =
      addRow(kObjects, QT_TR_NOOP("Restitution"), QT_TR_NOOP("Change Restitution"), restitution_);
  connect(restitution_, &QLineEdit::editingFinished, this, [this] {
    optionalNumberEdited(restitution_, restitutionRow_,
                         [](Scene& values, const ObjectRef& ref, std::optional<double> value) {
                           objectInfo(values, ref).restitution = value;
                         });
  });
}

void PropertiesDock::addLength() {
  length_ = new NumberField;
  length_->setObjectName("cylinderLength");
  lengthRow_ = addRow(kCylinders, QT_TR_NOOP("Length"), QT_TR_NOOP("Resize Cylinder"), length_,
                      QT_TR_NOOP("m"));
  connect(length_, &QLineEdit::editingFinished, this, [this] {
    // One standing on a surface keeps its foot there (standing.h).
    optionalNumberEdited(length_, lengthRow_,
                         [this](Scene& values, const ObjectRef& ref, std::optional<double> value) {
                           Cylinder& cylinder = values.cylinders[ref.index];
                           cylinder = withLength(document_->scene(), cylinder, value);
                         });
  });
  // Once the user has typed, an empty field makes them all infinite, even where it showed
  // "mixed" (left untouched, it changes nothing): the placeholder says what Enter will do.
  connect(length_, &QLineEdit::textEdited, this,
          [this] { length_->setPlaceholderText(tr("infinite")); });
}

void PropertiesDock::addRotation() {
  auto* axisFields = new QWidget;
  auto* line = new QHBoxLayout(axisFields);
  line->setContentsMargins(0, 0, 0, 0);
  rotationAxisRow_ = addRow(kBoxes, QT_TR_NOOP("Rotation axis"), QT_TR_NOOP("Turn Box"), axisFields,
                            QT_TR_NOOP("(any length)"), UnitPlace::Below);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    rotationFields_[a] = new NumberField;
    rotationFields_[a]->setObjectName(QString("rotationAxis.%1").arg(axes[a]));
    line->addWidget(rotationFields_[a]);
  }
  rotationFields_[3] = new NumberField;
  rotationFields_[3]->setObjectName("rotationDegrees");
  rotationDegreesRow_ = addRow(kBoxes, QT_TR_NOOP("Rotation"), QT_TR_NOOP("Turn Box"),
                               rotationFields_[3], QT_TR_NOOP("°"));
  for (int component = 0; component < 4; ++component)
    connect(rotationFields_[component], &QLineEdit::editingFinished, this,
            [this, component] { rotationEdited(component); });
}

QComboBox* PropertiesDock::addChoice(const char* name, const char* label, const char* change,
                                     const std::vector<std::string_view>& keys,
                                     void (*choose)(World&, int)) {
  auto* box = new QComboBox;
  box->setObjectName(name);
  for (std::string_view key : keys) box->addItem(QString::fromUtf8(key));
  const int row = addRow(kWorld, label, change, box);
  connect(box, &QComboBox::currentIndexChanged, this, [this, row, choose](int index) {
    commit(row, [&](Scene& values, const ObjectRef&) { choose(values.world, index); });
  });
  return box;
}

int PropertiesDock::selectedKinds() const {
  int kinds = 0;
  for (const ObjectRef& ref : document_->selection()) kinds |= kindBit(ref.kind);
  return kinds == 0 ? int(kWorld) : kinds;
}

void PropertiesDock::refresh() {
  const Scene& scene = document_->scene();
  const Selection& selection = document_->selection();
  const int kinds = selectedKinds();
  if (selection.empty()) {
    heading_->setText(tr("World (nothing selected)"));
  } else if (selection.size() == 1) {
    const ObjectRef& ref = selection.front();
    // "Ball: first", or just "Ball 3" when it has no name; the Name field below holds it whole.
    heading_->setText(objectInfo(scene, ref).name.empty()
                          ? objectLabel(scene, ref)
                          : tr("%1: %2").arg(kindName(ref.kind), elidedName(objectLabel(scene, ref),
                                                                            heading_->font())));
  } else if (std::has_single_bit(static_cast<unsigned>(kinds))) {
    heading_->setText(tr("%1: %n selected", nullptr, static_cast<int>(selection.size()))
                          .arg(kindPluralName(kindOfBit(kinds))));
  } else {
    heading_->setText(tr("%n objects selected", nullptr, static_cast<int>(selection.size())));
  }
  std::vector<bool> shown(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    shown[r] = (rows_[r].kinds & kinds) == kinds;
    for (QWidget* widget : rows_[r].widgets) widget->setVisible(shown[r]);
  }

  // With nothing selected, the world's rows show: their accessors ignore the reference.
  const Selection refs = selection.empty() ? Selection{ObjectRef{}} : selection;
  const QString mixed = tr("mixed");
  for (const NumberEditor& editor : numbers_) {
    if (!shown[editor.row]) continue;
    const std::optional<double> value = common<double>(refs, [&](const ObjectRef& ref) {
      return editor.number ? *editor.number(scene, ref)
                           : (*editor.vector(scene, ref))[editor.component];
    });
    editor.edit->setValue(value);
    editor.edit->setPlaceholderText(value ? QString() : mixed);
  }
  for (const TextEditor& editor : texts_) {
    if (!shown[editor.row]) continue;
    const std::optional<std::string> value =
        common<std::string>(refs, [&](const ObjectRef& ref) { return *editor.text(scene, ref); });
    const QSignalBlocker blocker(editor.edit);
    editor.edit->setText(value ? QString::fromStdString(*value) : QString());
    editor.edit->setPlaceholderText(value ? QString() : mixed);
    editor.edit->setModified(false);
  }
  if (shown[colorRow_]) {
    if (color_->placeholderText() != mixed) color_->setPlaceholderText(tr("default"));
    const QColor color(color_->text());
    QPixmap swatch(16, 16);
    swatch.fill(color.isValid() ? color : QColor(Qt::transparent));
    colorButton_->setIcon(QIcon(swatch));
  }
  if (shown[restitutionRow_]) {
    const auto value = common<std::optional<double>>(
        refs, [&](const ObjectRef& ref) { return objectInfo(scene, ref).restitution; });
    restitution_->setValue(value ? *value : std::nullopt);
    if (!value)
      restitution_->setPlaceholderText(mixed);
    else if (!*value)
      restitution_->setPlaceholderText(
          tr("world's (%1)").arg(formatNumber(scene.world.restitution)));
    else
      restitution_->setPlaceholderText(QString());
  }
  if (shown[lengthRow_]) {
    const auto value = common<std::optional<double>>(
        refs, [&](const ObjectRef& ref) { return scene.cylinders[ref.index].length; });
    length_->setValue(value ? *value : std::nullopt);
    length_->setPlaceholderText(!value ? mixed : *value ? QString() : tr("infinite"));
  }
  if (shown[rotationDegreesRow_]) {
    const auto value = common<std::optional<Rotation>>(
        refs, [&](const ObjectRef& ref) { return scene.boxes[ref.index].rotation; });
    // A box not turned shows empty fields with the axis a turn would start from.
    const Rotation unturned;
    for (int a = 0; a < 3; ++a) {
      rotationFields_[a]->setValue(value && *value ? std::optional((*value)->axis[a])
                                                   : std::nullopt);
      rotationFields_[a]->setPlaceholderText(!value   ? mixed
                                             : *value ? QString()
                                                      : formatNumber(unturned.axis[a]));
    }
    rotationFields_[3]->setValue(value && *value ? std::optional((*value)->degrees) : std::nullopt);
    rotationFields_[3]->setPlaceholderText(!value ? mixed : *value ? QString() : tr("none"));
  }
  if (kinds == kWorld) {
    const QSignalBlocker methodBlocker(method_);
    const QSignalBlocker integratorBlocker(integrator_);
    method_->setCurrentIndex(int(scene.world.method));
    integrator_->setCurrentIndex(int(scene.world.integrator));
  }
}

bool PropertiesDock::commit(int row, const std::function<void(Scene&, const ObjectRef&)>& set) {
  // A field left over from another selection (a colour picked after the selection changed):
  // its row no longer applies.
  const int kinds = selectedKinds();
  if ((rows_[row].kinds & kinds) != kinds) return false;
  // Only the selected objects are copied and changed, never the whole scene.
  const Selection& selection = document_->selection();
  QString error;
  if (selection.empty()) {
    Scene values;
    values.world = document_->scene().world;
    set(values, ObjectRef{});
    error = document_->editWorld(values.world, change(row));
  } else {
    Scene values = extract(document_->scene(), selection);
    for (const ObjectRef& ref : extractedRefs(selection)) set(values, ref);
    error = document_->editObjects(selection, values, change(row));
  }
  if (!error.isEmpty()) {
    refuse(error);
    return false;
  }
  message_->clear();
  return true;
}

void PropertiesDock::refuse(const QString& message) {
  message_->setText(message);
  refresh();  // the fields show the scene as it still is
  emit refused(message);
}

void PropertiesDock::numberEdited(const NumberEditor& editor) {
  if (!editor.edit->isModified()) {
    message_->clear();  // left holding a valid value: the scene's
    return;
  }
  editor.edit->setModified(false);
  const ParsedNumber parsed = parseNumber(editor.edit->text());
  if (!parsed.value) {
    refuse(tr("%1: %2").arg(label(editor.row), parsed.problem));
    return;
  }
  const double value = *parsed.value;
  commit(editor.row, [&](Scene& values, const ObjectRef& ref) {
    double* field =
        editor.number ? const_cast<double*>(editor.number(values, ref))
                      : &const_cast<Vec3*>(editor.vector(values, ref))->coeffRef(editor.component);
    *field = value;
  });
}

void PropertiesDock::textEdited(const TextEditor& editor) {
  if (!editor.edit->isModified()) {
    message_->clear();
    return;
  }
  editor.edit->setModified(false);
  const std::string value = editor.edit->text().trimmed().toStdString();
  commit(editor.row, [&](Scene& values, const ObjectRef& ref) {
    *const_cast<std::string*>(editor.text(values, ref)) = value;
  });
}

void PropertiesDock::optionalNumberEdited(
    NumberField* edit, int row,
    const std::function<void(Scene&, const ObjectRef&, std::optional<double>)>& set) {
  // Not edited: left empty (several that differ) or as it was, which changes nothing.
  if (!edit->isModified()) {
    message_->clear();
    return;
  }
  edit->setModified(false);
  std::optional<double> value;
  if (!edit->text().trimmed().isEmpty()) {
    const ParsedNumber parsed = parseNumber(edit->text());
    if (!parsed.value) {
      refuse(tr("%1: %2").arg(label(row), parsed.problem));
      return;
    }
    value = parsed.value;
  }
  commit(row, [&](Scene& values, const ObjectRef& ref) { set(values, ref, value); });
}

void PropertiesDock::rotationEdited(int component) {
  NumberField* edit = rotationFields_[component];
  if (!edit->isModified()) {
    message_->clear();
    return;
  }
  edit->setModified(false);
  const bool degrees = component == 3;
  const int row = degrees ? rotationDegreesRow_ : rotationAxisRow_;
  if (degrees && edit->text().trimmed().isEmpty()) {
    commit(row, [](Scene& values, const ObjectRef& ref) { values.boxes[ref.index].rotation = {}; });
    return;
  }
  const ParsedNumber parsed = parseNumber(edit->text());
  if (!parsed.value) {
    refuse(tr("%1: %2").arg(label(row), parsed.problem));
    return;
  }
  const double value = *parsed.value;
  commit(row, [&](Scene& values, const ObjectRef& ref) {
    // A box not turned starts from no turn about the default axis.
    Rotation rotation = values.boxes[ref.index].rotation.value_or(Rotation{});
    (degrees ? rotation.degrees : rotation.axis[component]) = value;
    values.boxes[ref.index].rotation = rotation;
  });
}

void PropertiesDock::pickColor() {
  // Not modal to the application, so the scene stays visible; one picker at a time.
  auto* dialog = findChild<QColorDialog*>();
  if (!dialog) {
    dialog = new QColorDialog(this);
    dialog->setWindowTitle(tr("Object Colour"));
    connect(dialog, &QColorDialog::colorSelected, this, [this](const QColor& color) {
      commit(colorRow_, [&](Scene& values, const ObjectRef& ref) {
        objectInfo(values, ref).color = color.name().toStdString();
      });
    });
  }
  const QColor current(color_->text());
  dialog->setCurrentColor(current.isValid() ? current : QColor(Qt::white));
  dialog->open();
}

}  // namespace carom::editor
