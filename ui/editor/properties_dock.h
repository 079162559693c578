#pragma once
// Edits every field of the selection, or the world settings when nothing is selected. Each
// field is typed in; a change becomes one document command, checked by the same scene
// validation the loader uses, and a refused value leaves the scene as it was. Numbers show six
// significant digits, all of them while a field is edited and in its tooltip.

#include "sim/model/scene.h"
#include "ui/editor/object_ref.h"

#include <QDockWidget>

#include <QString>
#include <functional>

#include <optional>
#include <string_view>
#include <vector>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QScrollArea;
class QToolButton;

namespace carom::editor {

class NumberField;
class SceneDocument;

class PropertiesDock : public QDockWidget {
  Q_OBJECT
 public:
  explicit PropertiesDock(SceneDocument* document, QWidget* parent = nullptr);

  // What the dock shows at the top: the object's name, a count of the selection, or "World".
  QString heading() const;
  // The last refusal, shown under the fields until a field is entered or left with a valid
  // value, or the scene or the selection changes.
  QString message() const;
  // Wide enough for every row any selection shows, so that three six-digit values with their
  // signs fit each vector row whole; the window opens the dock this wide.
  QSize sizeHint() const override;

 signals:
  // A typed value was refused; the text says why.
  void refused(const QString& message);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  // Which objects a row applies to; a row shows when every selected object is of its kinds.
  // The object bits are kindBit()s (object_kinds.h).
  enum Kinds { kBalls = 1, kPlanes = 2, kCylinders = 4, kBoxes = 8, kObjects = 15, kWorld = 16 };
  // Accessors return the field inside a scene, for one object (unused for world rows). The
  // scene is const for reading; a write goes through the same accessor on the edited copy.
  using NumberAccess = const double* (*)(const Scene&, const ObjectRef&);
  using VectorAccess = const Vec3* (*)(const Scene&, const ObjectRef&);
  using TextAccess = const std::string* (*)(const Scene&, const ObjectRef&);

  // Texts are kept untranslated and translated when shown, so that they follow the language.
  struct Row {
    int kinds;
    const char* label;
    const char* change;  // the command's text
    const char* unit;    // or null
    QLabel* labelWidget;
    QLabel* unitWidget;  // or null
    std::vector<QWidget*> widgets;
  };
  struct NumberEditor {
    NumberField* edit;
    int row;
    NumberAccess number;  // a number field, or
    VectorAccess vector;  // one component of a vector field
    int component;
  };
  struct TextEditor {
    QLineEdit* edit;
    int row;
    TextAccess text;
  };

  // A unit stands beside its field; a direction's "(any length)" goes under its three fields,
  // which need the dock's width for their values.
  enum class UnitPlace { Beside, Below };
  int addRow(int kinds, const char* label, const char* change, QWidget* field,
             const char* unit = nullptr, UnitPlace place = UnitPlace::Beside);
  void addNumber(int kinds, const char* name, const char* label, const char* change,
                 const char* unit, NumberAccess access);
  void addVector(int kinds, const char* name, const char* label, const char* change,
                 const char* unit, VectorAccess access, UnitPlace place = UnitPlace::Beside);
  void addText(int kinds, const char* name, const char* label, const char* change,
               TextAccess access, QToolButton* extra = nullptr);
  void addRestitution();
  // A cylinder's length: empty for an infinite one.
  void addLength();
  // A box's turn: its axis's components and its degrees, all empty for a box not turned.
  void addRotation();
  // A world setting chosen from `keys`; `choose` sets the index chosen.
  QComboBox* addChoice(const char* name, const char* label, const char* change,
                       const std::vector<std::string_view>& keys, void (*choose)(World&, int));

  // Every text in the current language.
  void retranslate();
  QString label(int row) const;
  QString change(int row) const;
  // Document to fields.
  void refresh();
  int selectedKinds() const;
  // Fields to document, as one command; false (and a message) when refused. `row`'s field was
  // edited, and `set` changes one
  // selected object of a scene holding copies of the selected objects only (the world rows'
  // accessors ignore the reference and change the world). An edit that changes nothing is no
  // command, and takes the message away as a successful one does.
  bool commit(int row, const std::function<void(Scene&, const ObjectRef&)>& set);
  void refuse(const QString& message);
  void numberEdited(const NumberEditor& editor);
  void textEdited(const TextEditor& editor);
  // A field whose emptied text means none (the restitution, the length); `set` stores the
  // value typed, or none, into one selected object.
  void optionalNumberEdited(
      NumberField* edit, int row,
      const std::function<void(Scene&, const ObjectRef&, std::optional<double>)>& set);
  // `component` 0 to 2 of the axis, or 3 for the degrees; emptied degrees take the turn away.
  void rotationEdited(int component);
  void pickColor();

  SceneDocument* document_;
  QFormLayout* form_ = nullptr;
  QLabel* heading_ = nullptr;
  QLabel* message_ = nullptr;  // a refusal, under the rows' scroll area
  QScrollArea* scroll_ = nullptr;
  std::vector<Row> rows_;
  std::vector<NumberEditor> numbers_;
  std::vector<TextEditor> texts_;
  int restitutionRow_ = -1;
  NumberField* restitution_ = nullptr;
  int lengthRow_ = -1;
  NumberField* length_ = nullptr;
  int rotationAxisRow_ = -1;
  int rotationDegreesRow_ = -1;
  NumberField* rotationFields_[4] = {};  // the axis's x, y, z and the degrees
  int colorRow_ = -1;
  QLineEdit* color_ = nullptr;
  QToolButton* colorButton_ = nullptr;
  QComboBox* method_ = nullptr;
  QComboBox* integrator_ = nullptr;
};

}  // namespace carom::editor
