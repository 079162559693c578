#include "properties_dock.h"

#include "number_text.h"
#include "scene_document.h"

#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <bit>
#include <optional>

namespace carom::ui {
namespace {

// The dock's kind bits are ObjectKind's values as powers of two.
int flagOf(ObjectKind kind) {
  return 1 << static_cast<int>(kind);
}

ObjectKind kindOfFlag(int flag) {
  return static_cast<ObjectKind>(std::countr_zero(static_cast<unsigned>(flag)));
}

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
    : QDockWidget(tr("Properties"), parent), document_(document) {
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
  layout->addWidget(message_);
  layout->addStretch(1);

  const QString m = tr("m"), mPerS = tr("m/s"), kg = tr("kg"), s = tr("s"), mPerS2 = tr("m/s²");
  const QString direction = tr("(any length)");
  addText(kObjects, "name", tr("Name"), tr("Rename"),
          [](const Scene& scene, const ObjectRef& r) { return &objectInfo(scene, r).name; });
  colorButton_ = new QToolButton;
  colorButton_->setObjectName("pickColor");
  colorButton_->setText(tr("…"));
  colorButton_->setToolTip(tr("Choose a colour"));
  connect(colorButton_, &QToolButton::clicked, this, &PropertiesDock::pickColor);
  addText(
      kObjects, "color", tr("Colour"), tr("Change Colour"),
      [](const Scene& scene, const ObjectRef& r) { return &objectInfo(scene, r).color; },
      colorButton_);
  colorRow_ = texts_.back().row;
  color_ = texts_.back().edit;
  color_->setPlaceholderText(tr("default"));
  addRestitution();

  addVector(kBalls, "position", tr("Position"), tr("Move"), m,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].position; });
  addVector(kBalls, "velocity", tr("Velocity"), tr("Change Velocity"), mPerS,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].velocity; });
  addNumber(kBalls, "ballRadius", tr("Radius"), tr("Change Radius"), m,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].radius; });
  addNumber(kBalls, "mass", tr("Mass"), tr("Change Mass"), kg,
            [](const Scene& scene, const ObjectRef& r) { return &scene.balls[r.index].mass; });
  addVector(kPlanes | kCylinders, "point", tr("Point"), tr("Move"), m,
            [](const Scene& scene, const ObjectRef& r) {
              return r.kind == ObjectKind::Plane ? &scene.planes[r.index].point
                                                 : &scene.cylinders[r.index].point;
            });
  addVector(kPlanes, "normal", tr("Normal"), tr("Turn Plane"), direction,
            [](const Scene& scene, const ObjectRef& r) { return &scene.planes[r.index].normal; });
  addVector(kCylinders, "axis", tr("Axis"), tr("Turn Cylinder"), direction,
            [](const Scene& scene, const ObjectRef& r) { return &scene.cylinders[r.index].axis; });
  addNumber(
      kCylinders, "cylinderRadius", tr("Radius"), tr("Change Radius"), m,
      [](const Scene& scene, const ObjectRef& r) { return &scene.cylinders[r.index].radius; });

  addVector(kWorld, "gravity", tr("Gravity"), tr("Change Gravity"), mPerS2,
            [](const Scene& scene, const ObjectRef&) { return &scene.world.gravity; });
  addNumber(kWorld, "timeStep", tr("Time step"), tr("Change Time Step"), s,
            [](const Scene& scene, const ObjectRef&) { return &scene.world.timeStep; });
  addNumber(kWorld, "worldRestitution", tr("Restitution"), tr("Change Restitution"), {},
            [](const Scene& scene, const ObjectRef&) { return &scene.world.restitution; });
  method_ = addChoice("method", tr("Method"), tr("Change Method"), methodNames(),
                      [](World& world, int index) { world.method = Method(index); });
  integrator_ =
      addChoice("integrator", tr("Integrator"), tr("Change Integrator"), integratorNames(),
                [](World& world, int index) { world.integrator = Integrator(index); });

  auto* scroll = new QScrollArea;
  scroll->setWidget(body);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  setWidget(scroll);

  connect(document_, &SceneDocument::sceneChanged, this, &PropertiesDock::refresh);
  connect(document_, &SceneDocument::selectionChanged, this, [this] {
    message_->clear();
    refresh();
  });
  refresh();
}

QString PropertiesDock::heading() const {
  return heading_->text();
}

QString PropertiesDock::message() const {
  return message_->text();
}

int PropertiesDock::addRow(int kinds, const QString& label, const QString& change, QWidget* field,
                           const QString& unit) {
  auto* labelWidget = new QLabel(label);
  std::vector<QWidget*> widgets = {labelWidget};
  QWidget* shown = field;
  if (!unit.isEmpty()) {
    shown = new QWidget;
    auto* line = new QHBoxLayout(shown);
    line->setContentsMargins(0, 0, 0, 0);
    line->addWidget(field, 1);
    line->addWidget(new QLabel(unit));
  }
  widgets.push_back(shown);
  labelWidget->setBuddy(field);
  form_->addRow(labelWidget, shown);
  rows_.push_back({kinds, label, change, widgets});
  return static_cast<int>(rows_.size()) - 1;
}

void PropertiesDock::addNumber(int kinds, const char* name, const QString& label,
                               const QString& change, const QString& unit, NumberAccess access) {
  auto* edit = new QLineEdit;
  edit->setObjectName(name);
  const int row = addRow(kinds, label, change, edit, unit);
  numbers_.push_back({edit, row, access, nullptr, 0});
  connect(edit, &QLineEdit::editingFinished, this,
          [this, index = numbers_.size() - 1] { numberEdited(numbers_[index]); });
}

void PropertiesDock::addVector(int kinds, const char* name, const QString& label,
                               const QString& change, const QString& unit, VectorAccess access) {
  auto* fields = new QWidget;
  auto* line = new QHBoxLayout(fields);
  line->setContentsMargins(0, 0, 0, 0);
  const int row = addRow(kinds, label, change, fields, unit);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    auto* edit = new QLineEdit;
    edit->setObjectName(QString("%1.%2").arg(name, axes[a]));
    edit->setToolTip(QString("%1 %2").arg(label, axes[a]));
    line->addWidget(edit);
    numbers_.push_back({edit, row, nullptr, access, a});
    connect(edit, &QLineEdit::editingFinished, this,
            [this, index = numbers_.size() - 1] { numberEdited(numbers_[index]); });
  }
}

void PropertiesDock::addText(int kinds, const char* name, const QString& label,
                             const QString& change, TextAccess access, QToolButton* extra) {
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
  restitution_ = new QLineEdit;
  restitution_->setObjectName("restitution");
  restitution_->setToolTip(tr("0 to 1; empty: the world's restitution"));
  restitutionRow_ = addRow(kObjects, tr("Restitution"), tr("Change Restitution"), restitution_);
  connect(restitution_, &QLineEdit::editingFinished, this, &PropertiesDock::restitutionEdited);
}

QComboBox* PropertiesDock::addChoice(const char* name, const QString& label, const QString& change,
                                     const std::vector<std::string_view>& keys,
                                     void (*choose)(World&, int)) {
  auto* box = new QComboBox;
  box->setObjectName(name);
  for (std::string_view key : keys) box->addItem(QString::fromUtf8(key));
  addRow(kWorld, label, change, box);
  connect(box, &QComboBox::currentIndexChanged, this, [this, change, choose](int index) {
    Scene edited = document_->scene();
    choose(edited.world, index);
    if (!(edited.world == document_->scene().world)) commit(edited, change);
  });
  return box;
}

int PropertiesDock::selectedKinds() const {
  int kinds = 0;
  for (const ObjectRef& ref : document_->selection()) kinds |= flagOf(ref.kind);
  return kinds == 0 ? int(kWorld) : kinds;
}

Selection PropertiesDock::targets() const {
  const Selection& selection = document_->selection();
  return selection.empty() ? Selection{ObjectRef{}} : selection;
}

void PropertiesDock::refresh() {
  const Scene& scene = document_->scene();
  const Selection& selection = document_->selection();
  const int kinds = selectedKinds();
  if (selection.empty()) {
    heading_->setText(tr("World (nothing selected)"));
  } else if (selection.size() == 1) {
    const ObjectRef& ref = selection.front();
    // "Ball: first", or just "Ball 3" when it has no name.
    heading_->setText(objectInfo(scene, ref).name.empty()
                          ? objectLabel(scene, ref)
                          : tr("%1: %2").arg(kindName(ref.kind), objectLabel(scene, ref)));
  } else if (kinds == kBalls || kinds == kPlanes || kinds == kCylinders) {
    heading_->setText(tr("%1: %n selected", nullptr, static_cast<int>(selection.size()))
                          .arg(kindPluralName(kindOfFlag(kinds))));
  } else {
    heading_->setText(tr("%n objects selected", nullptr, static_cast<int>(selection.size())));
  }
  std::vector<bool> shown(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    shown[r] = (rows_[r].kinds & kinds) == kinds;
    for (QWidget* widget : rows_[r].widgets) widget->setVisible(shown[r]);
  }

  const Selection refs = targets();
  const QString mixed = tr("mixed");
  const auto show = [&](QLineEdit* edit, const std::optional<QString>& value) {
    const QSignalBlocker blocker(edit);
    edit->setText(value.value_or(QString()));
    edit->setPlaceholderText(value ? QString() : mixed);
    edit->setModified(false);
  };
  for (const NumberEditor& editor : numbers_) {
    if (!shown[editor.row]) continue;
    const std::optional<double> value = common<double>(refs, [&](const ObjectRef& ref) {
      return editor.number ? *editor.number(scene, ref)
                           : (*editor.vector(scene, ref))[editor.component];
    });
    show(editor.edit, value ? std::optional(formatNumber(*value)) : std::nullopt);
  }
  for (const TextEditor& editor : texts_) {
    if (!shown[editor.row]) continue;
    const std::optional<std::string> value =
        common<std::string>(refs, [&](const ObjectRef& ref) { return *editor.text(scene, ref); });
    show(editor.edit, value ? std::optional(QString::fromStdString(*value)) : std::nullopt);
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
    show(restitution_,
         value ? std::optional(*value ? formatNumber(**value) : QString()) : std::nullopt);
    if (value && !*value)
      restitution_->setPlaceholderText(
          tr("world's (%1)").arg(formatNumber(scene.world.restitution)));
  }
  if (kinds == kWorld) {
    const QSignalBlocker methodBlocker(method_);
    const QSignalBlocker integratorBlocker(integrator_);
    method_->setCurrentIndex(int(scene.world.method));
    integrator_->setCurrentIndex(int(scene.world.integrator));
  }
}

bool PropertiesDock::commit(const Scene& edited, const QString& change) {
  const QString error = document_->apply(edited, change);
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
  if (!editor.edit->isModified()) return;
  editor.edit->setModified(false);
  const ParsedNumber parsed = parseNumber(editor.edit->text());
  if (!parsed.value) {
    refuse(tr("%1: %2").arg(rows_[editor.row].label, parsed.problem));
    return;
  }
  const double value = *parsed.value;
  Scene edited = document_->scene();
  for (const ObjectRef& ref : targets()) {
    double* field =
        editor.number ? const_cast<double*>(editor.number(edited, ref))
                      : &const_cast<Vec3*>(editor.vector(edited, ref))->coeffRef(editor.component);
    *field = value;
  }
  if (!(edited == document_->scene())) commit(edited, rows_[editor.row].change);
}

void PropertiesDock::textEdited(const TextEditor& editor) {
  if (!editor.edit->isModified()) return;
  editor.edit->setModified(false);
  Scene edited = document_->scene();
  const std::string value = editor.edit->text().trimmed().toStdString();
  for (const ObjectRef& ref : targets())
    *const_cast<std::string*>(editor.text(edited, ref)) = value;
  if (!(edited == document_->scene())) commit(edited, rows_[editor.row].change);
}

void PropertiesDock::restitutionEdited() {
  if (!restitution_->isModified()) return;
  restitution_->setModified(false);
  std::optional<double> value;
  if (!restitution_->text().trimmed().isEmpty()) {
    const ParsedNumber parsed = parseNumber(restitution_->text());
    if (!parsed.value) {
      refuse(tr("%1: %2").arg(rows_[restitutionRow_].label, parsed.problem));
      return;
    }
    value = parsed.value;
  }
  Scene edited = document_->scene();
  for (const ObjectRef& ref : targets()) objectInfo(edited, ref).restitution = value;
  if (!(edited == document_->scene())) commit(edited, rows_[restitutionRow_].change);
}

void PropertiesDock::pickColor() {
  // Not modal to the application, so the scene stays visible; one picker at a time.
  auto* dialog = findChild<QColorDialog*>();
  if (!dialog) {
    dialog = new QColorDialog(this);
    dialog->setWindowTitle(tr("Object Colour"));
    connect(dialog, &QColorDialog::colorSelected, this, [this](const QColor& color) {
      Scene edited = document_->scene();
      for (const ObjectRef& ref : document_->selection())
        objectInfo(edited, ref).color = color.name().toStdString();
      if (!(edited == document_->scene())) commit(edited, rows_[colorRow_].change);
    });
  }
  const QColor current(color_->text());
  dialog->setCurrentColor(current.isValid() ? current : QColor(Qt::white));
  dialog->open();
}

}  // namespace carom::ui
