#include "ui/editor/validation_text.h"

#include "ui/editor/object_kinds.h"
#include "ui/editor/object_ref.h"

#include <QCoreApplication>
#include <QFont>
#include <QGuiApplication>
#include <QLocale>

#include <cmath>
#include <optional>

namespace carom::editor {
namespace {

QString translated(const char* context, const char* text) {
  return QCoreApplication::translate(context, text);
}

// As the Outline names it, shortened as the window's other messages shorten names. An object
// `scene` lacks (a caller's wrong scene) is named by kind and index rather than read past the end.
QString objectName(const ValidationObject& object, const Scene& scene) {
  const ObjectRef ref{*kindOfSubject(object.subject), static_cast<int>(object.index.value_or(0))};
  const QString label =
      exists(scene, ref) ? objectLabel(scene, ref)
                         : translated("ObjectRef", "%1 %2").arg(kindName(ref.kind)).arg(ref.index);
  return elidedName(label, QGuiApplication::font());
}

struct FieldWords {
  const char* context;
  const char* label;
  const char* unit;  // in the Properties dock's context, or null
};

// The Properties dock's labels and units (and the world tool bar's), in their translations.
FieldWords fieldWords(ValidationField field) {
  using F = ValidationField;
  const char* dock = "carom::editor::PropertiesDock";
  const char* m = QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "m");
  switch (field) {
    case F::None:
      break;
    case F::Position:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Position"), m};
    case F::Velocity:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Velocity"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "m/s")};
    case F::AngularVelocity:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Angular velocity"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "rad/s")};
    case F::Radius:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Radius"), m};
    case F::Mass:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Mass"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "kg")};
    case F::Point:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Point"), m};
    case F::Normal:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Normal"), nullptr};
    case F::Axis:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Axis"), nullptr};
    case F::Length:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Length"), m};
    case F::Center:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Centre"), m};
    case F::HalfExtentX:
    case F::HalfExtentY:
    case F::HalfExtentZ:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Half extents"), m};
    case F::RotationAxis:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Rotation axis"), nullptr};
    case F::RotationDegrees:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Rotation"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "°")};
    case F::Name:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Name"), nullptr};
    case F::Restitution:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Restitution"), nullptr};
    case F::Friction:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Friction"), nullptr};
    case F::RollingResistance:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Rolling resistance"),
              nullptr};
    case F::SpinningFriction:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Spinning friction"),
              nullptr};
    case F::TangentialRestitution:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Tangential restitution"),
              nullptr};
    case F::Color:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Colour"), nullptr};
    case F::Gravity:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Gravity"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "m/s²")};
    case F::TimeStep:
      return {dock, QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "Time step"),
              QT_TRANSLATE_NOOP("carom::editor::PropertiesDock", "s")};
    case F::EnergyTolerance:
      return {"carom::ui::WorldToolBar", QT_TRANSLATE_NOOP("carom::ui::WorldToolBar", "Accuracy"),
              nullptr};
    case F::PenetrationTolerance:
      return {"ValidationText", QT_TRANSLATE_NOOP("ValidationText", "Penetration tolerance"),
              nullptr};
  }
  return {"ValidationText", "", nullptr};
}

// As the dock names a half extent's field: the row's label and the axis.
QString fieldLabel(ValidationField field) {
  const FieldWords words = fieldWords(field);
  const QString label = translated(words.context, words.label);
  switch (field) {
    case ValidationField::HalfExtentX:
      return QString("%1 x").arg(label);
    case ValidationField::HalfExtentY:
      return QString("%1 y").arg(label);
    case ValidationField::HalfExtentZ:
      return QString("%1 z").arg(label);
    default:
      return label;
  }
}

constexpr int kAllDigits = QLocale::FloatingPointShortest;

// In the current locale, with its group separators, to `significant` digits or as the value
// was typed; an exponent (in lower case, as the number fields write it) only for the very large
// and the very small.
QString number(double value, int significant = kAllDigits) {
  const QLocale locale;
  if (!std::isfinite(value)) return locale.toString(value);
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < 1e-4 || magnitude >= 1e9)) {
    QString text = locale.toString(value, 'g', significant);
    const QString exponent = locale.exponential();
    return text.replace(exponent, exponent.toLower());
  }
  // Rounded first, so that the shortest fixed notation stops at those digits.
  const double shown =
      significant == kAllDigits ? value : QString::number(value, 'g', significant).toDouble();
  return locale.toString(shown, 'f', QLocale::FloatingPointShortest);
}

// A value the user gave, or a limit, with the field's unit.
QString quantity(double value, ValidationField field, int significant = kAllDigits) {
  const QString text = number(value, significant);
  const FieldWords words = fieldWords(field);
  if (!words.unit) return text;
  const QString unit = translated("carom::editor::PropertiesDock", words.unit);
  return QString(words.unit) == "°" ? text + unit : QString("%1 %2").arg(text, unit);
}

// An overlap's depth: three digits say enough of how far.
QString distance(double value) {
  return quantity(value, ValidationField::Position, 3);
}

}  // namespace

QString validationText(const ValidationError& error, const Scene& scene) {
  using P = ValidationProblem;
  const ValidationObject& object = error.object;
  const ValidationField field = error.field;
  if (error.problem == P::Overlaps || error.problem == P::BehindSurface) {
    const QString ball = objectName(object, scene);
    const QString other = error.other ? objectName(*error.other, scene) : QString();
    if (error.problem == P::BehindSurface)
      return QCoreApplication::translate("ValidationText",
                                         "%1 would be %2 behind the surface of %3")
          .arg(ball, distance(error.value), other);
    return QCoreApplication::translate("ValidationText", "%1 would overlap %2 by %3")
        .arg(ball, other, distance(error.value));
  }
  if (error.problem == P::TooMany)
    return QCoreApplication::translate("ValidationText",
                                       "%1: at most %2 in a scene (this would make %3)")
        .arg(kindPluralName(*kindOfSubject(object.subject)), number(error.high),
             number(error.value));

  // The field, of its object when it has one ("Radius of Ball 3"); the world's settings alone.
  const QString what = kindOfSubject(object.subject)
                           ? QCoreApplication::translate("ValidationText", "%1 of %2")
                                 .arg(fieldLabel(field), objectName(object, scene))
                           : fieldLabel(field);
  switch (error.problem) {
    case P::NotFinite:
      return QCoreApplication::translate("ValidationText", "%1 must be a finite number").arg(what);
    case P::TooLarge:
      return QCoreApplication::translate("ValidationText", "%1 must lie within ±%2 (got %3)")
          .arg(what, quantity(error.high, field), quantity(error.value, field));
    case P::NotPositive:
    case P::NotAboveZero:
      return QCoreApplication::translate("ValidationText", "%1 must be above zero (got %2)")
          .arg(what, quantity(error.value, field));
    case P::TooSmall:
      return QCoreApplication::translate("ValidationText", "%1 must be at least %2 (got %3)")
          .arg(what, quantity(error.low, field), quantity(error.value, field));
    case P::NotBetween:
      return QCoreApplication::translate("ValidationText", "%1 must be between %2 and %3 (got %4)")
          .arg(what, quantity(error.low, field), quantity(error.high, field),
               quantity(error.value, field));
    case P::ZeroLength:
      return QCoreApplication::translate("ValidationText",
                                         "%1 must not be zero: it gives a direction")
          .arg(what);
    case P::NameTooLong:
      return QCoreApplication::translate("ValidationText",
                                         "%1 must be at most %n characters long (got %2)", nullptr,
                                         int(error.high))
          .arg(what, number(error.value));
    case P::BadColor:
      return QCoreApplication::translate("ValidationText",
                                         "%1 must be empty or a colour such as #ff8000 (got “%2”)")
          .arg(what, QString::fromStdString(error.quoted));
    case P::TooMany:
    case P::Overlaps:
    case P::BehindSurface:
      break;
  }
  return QString::fromStdString(error.text());
}

}  // namespace carom::editor
