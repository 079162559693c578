// Writing scene files: a fixed key order and one line per plane, cylinder and ball keep files
// readable and make saving deterministic, so that saving a loaded file again gives the same bytes.

#include "sim/io/scene_file.h"

#include "sim/io/atomic_file.h"
#include "sim/io/json_text.h"
#include "sim/io/scene_format.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>

namespace carom::io {
namespace {

QByteArray jsonText(const QJsonValue& value) {
  // QJsonDocument holds only arrays and objects: wrap the value in an array and unwrap it.
  const QByteArray text = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
  return text.mid(1, text.size() - 2);
}

QByteArray jsonString(std::string_view text) {
  return jsonText(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
}

QByteArray jsonVector(const Vec3& v) {
  return '[' + numberText(v.x()) + ", " + numberText(v.y()) + ", " + numberText(v.z()) + ']';
}

// The "key": value pairs of one object being written.
class JsonFields {
 public:
  void add(std::string_view key, const QByteArray& value) {
    fields_ << jsonString(key) + ": " + value;
  }
  // The unknown keys kept in `extra`, after the known ones.
  void addExtra(const std::string& extra, const QStringList& knownKeys) {
    if (extra.empty()) return;
    const QJsonObject object = QJsonDocument::fromJson(QByteArray::fromStdString(extra)).object();
    for (auto it = object.begin(); it != object.end(); ++it) {
      // A key that a field also writes would appear twice; the field wins.
      if (knownKeys.contains(it.key())) continue;
      fields_ << jsonText(it.key()) + ": " + jsonText(it.value());
    }
  }
  void addInfo(const ObjectInfo& info) {
    if (info.restitution) add("restitution", numberText(*info.restitution));
    if (info.friction) add("friction", numberText(*info.friction));
    if (info.rollingResistance) add("rollingResistance", numberText(*info.rollingResistance));
    if (info.spinningFriction) add("spinningFriction", numberText(*info.spinningFriction));
    if (!info.color.empty()) add("color", jsonString(info.color));
  }

  QByteArray oneLine() const { return '{' + fields_.join(", ") + '}'; }
  QByteArray indented(const QByteArray& indent) const {
    return "{\n" + indent + "  " + fields_.join(",\n" + indent + "  ") + '\n' + indent + '}';
  }

 private:
  QByteArrayList fields_;
};

JsonFields startFields(const ObjectInfo& info) {
  JsonFields fields;
  if (!info.name.empty()) fields.add("name", jsonString(info.name));
  return fields;
}

QByteArray listText(const QByteArrayList& items) {
  if (items.isEmpty()) return "[]";
  return "[\n    " + items.join(",\n    ") + "\n  ]";
}

void appendVector(std::string& out, const Vec3& v) {
  out += '[';
  appendNumber(out, v.x());
  out += ", ";
  appendNumber(out, v.y());
  out += ", ";
  appendNumber(out, v.z());
  out += ']';
}

// A string as Qt's JSON writer quotes it, taken directly when it needs no escape.
void appendString(std::string& out, const std::string& text) {
  const bool plain = std::all_of(text.begin(), text.end(), [](char c) {
    return c >= 0x20 && c < 0x7f && c != '"' && c != '\\';
  });
  if (plain) {
    out += '"';
    out += text;
    out += '"';
  } else {
    out += jsonString(text).toStdString();
  }
}

// Written only when turning: zero is the default, and versions before friction have no key.
bool spins(const Ball& ball) {
  return !ball.angularVelocity.isZero(0.0);
}

void appendOptional(std::string& out, std::string_view key, const std::optional<double>& value) {
  if (!value) return;
  out += ", \"";
  out += key;
  out += "\": ";
  appendNumber(out, *value);
}

// A ball's line, as JsonFields writes it.
void appendBall(std::string& out, const Ball& ball, const QStringList& knownKeys) {
  if (!ball.extra.empty()) {
    // Rare: the unknown keys go through Qt's JSON as they came.
    JsonFields fields = startFields(ball);
    fields.add("position", jsonVector(ball.position));
    fields.add("velocity", jsonVector(ball.velocity));
    if (spins(ball)) fields.add("angularVelocity", jsonVector(ball.angularVelocity));
    fields.add("radius", numberText(ball.radius));
    fields.add("mass", numberText(ball.mass));
    fields.addInfo(ball);
    fields.addExtra(ball.extra, knownKeys);
    out += fields.oneLine().toStdString();
    return;
  }
  out += '{';
  if (!ball.name.empty()) {
    out += "\"name\": ";
    appendString(out, ball.name);
    out += ", ";
  }
  out += "\"position\": ";
  appendVector(out, ball.position);
  out += ", \"velocity\": ";
  appendVector(out, ball.velocity);
  if (spins(ball)) {
    out += ", \"angularVelocity\": ";
    appendVector(out, ball.angularVelocity);
  }
  out += ", \"radius\": ";
  appendNumber(out, ball.radius);
  out += ", \"mass\": ";
  appendNumber(out, ball.mass);
  appendOptional(out, "restitution", ball.restitution);
  appendOptional(out, "friction", ball.friction);
  appendOptional(out, "rollingResistance", ball.rollingResistance);
  appendOptional(out, "spinningFriction", ball.spinningFriction);
  if (!ball.color.empty()) {
    out += ", \"color\": ";
    appendString(out, ball.color);
  }
  out += '}';
}

bool givesCoefficient(const ObjectInfo& info) {
  return info.friction || info.rollingResistance || info.spinningFriction;
}

template <typename Objects>
bool anyGivesCoefficient(const Objects& objects) {
  return std::any_of(objects.begin(), objects.end(), givesCoefficient);
}

// The oldest version that holds the scene. An object's coefficient given as 0 needs version 3
// too, though it asks for no friction: older versions have no key to keep it in.
int versionToWrite(const Scene& scene) {
  if (usesFriction(scene) || anyGivesCoefficient(scene.planes) ||
      anyGivesCoefficient(scene.cylinders) || anyGivesCoefficient(scene.boxes) ||
      anyGivesCoefficient(scene.balls))
    return format::kFirstVersionWithFriction;
  const bool capped = std::any_of(scene.cylinders.begin(), scene.cylinders.end(),
                                  [](const Cylinder& c) { return c.length.has_value(); });
  return scene.boxes.empty() && !capped ? 1 : format::kFirstVersionWithBoxes;
}

// A world coefficient, written only when it is not the default so that a frictionless world
// is written as before friction.
void addUnlessDefault(JsonFields& fields, std::string_view key, double value, double fallback) {
  if (value != fallback) fields.add(key, numberText(value));
}

// Writes the scene's text to `write(const char*, size)` in pieces: all but the balls from
// JsonFields, the balls line by line (a million of them go to a file without the whole text in
// memory).
template <typename Write>
void writeScene(const Scene& scene, Write&& write) {
  JsonFields top;
  top.add("format", jsonString(format::kName));
  const int version = versionToWrite(scene);
  const KnownKeys& known = knownKeys(version);
  top.add("version", QByteArray::number(version));
  // Unknown top-level keys such as "units" go right after the header, where a reader looks.
  // In version 1 "boxes" is one of them.
  top.addExtra(scene.extra, known.top);

  const World& world = scene.world;
  const World defaults;
  JsonFields worldFields;
  worldFields.add("gravity", jsonVector(world.gravity));
  worldFields.add("timeStep", numberText(world.timeStep));
  worldFields.add("restitution", numberText(world.restitution));
  addUnlessDefault(worldFields, "friction", world.friction, defaults.friction);
  addUnlessDefault(worldFields, "rollingResistance", world.rollingResistance,
                   defaults.rollingResistance);
  addUnlessDefault(worldFields, "spinningFriction", world.spinningFriction,
                   defaults.spinningFriction);
  addUnlessDefault(worldFields, "tangentialRestitution", world.tangentialRestitution,
                   defaults.tangentialRestitution);
  worldFields.add(
      "method", jsonString(world.autoMethod ? format::kAutoMethodName : methodName(world.method)));
  worldFields.add("integrator", jsonString(integratorName(world.integrator)));
  if (world.autoMethod)
    worldFields.add("tolerance", "[" + numberText(world.autoMethod->energyPerSecond) + ", " +
                                     numberText(world.autoMethod->penetrationFraction) + "]");
  worldFields.addExtra(world.extra, known.world);
  top.add("world", worldFields.indented("  "));

  QByteArrayList planes;
  for (const Plane& plane : scene.planes) {
    JsonFields fields = startFields(plane);
    fields.add("point", jsonVector(plane.point));
    fields.add("normal", jsonVector(plane.normal));
    fields.addInfo(plane);
    fields.addExtra(plane.extra, known.plane);
    planes << fields.oneLine();
  }
  top.add("planes", listText(planes));

  QByteArrayList cylinders;
  for (const Cylinder& cylinder : scene.cylinders) {
    JsonFields fields = startFields(cylinder);
    fields.add("point", jsonVector(cylinder.point));
    fields.add("axis", jsonVector(cylinder.axis));
    fields.add("radius", numberText(cylinder.radius));
    if (cylinder.length) fields.add("length", numberText(*cylinder.length));
    fields.addInfo(cylinder);
    fields.addExtra(cylinder.extra, known.cylinder);
    cylinders << fields.oneLine();
  }
  top.add("cylinders", listText(cylinders));

  if (!scene.boxes.empty()) {
    QByteArrayList boxes;
    for (const Box& box : scene.boxes) {
      JsonFields fields = startFields(box);
      fields.add("center", jsonVector(box.center));
      fields.add("halfExtents", jsonVector(box.halfExtents));
      if (box.rotation)
        fields.add("rotation", '[' + numberText(box.rotation->axis.x()) + ", " +
                                   numberText(box.rotation->axis.y()) + ", " +
                                   numberText(box.rotation->axis.z()) + ", " +
                                   numberText(box.rotation->degrees) + ']');
      fields.addInfo(box);
      fields.addExtra(box.extra, known.box);
      boxes << fields.oneLine();
    }
    top.add("boxes", listText(boxes));
  }

  // The balls are the last field: the text up to them, then theirs, then the closing brace.
  QByteArray head = top.indented("");
  head.chop(2);  // "\n}"
  head += scene.balls.empty() ? ",\n  \"balls\": []" : ",\n  \"balls\": [\n    ";
  write(head.constData(), static_cast<std::size_t>(head.size()));
  constexpr std::size_t kPiece = 1 << 20;
  std::string piece;
  piece.reserve(kPiece + 4096);
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    if (i > 0) piece += ",\n    ";
    appendBall(piece, scene.balls[i], known.ball);
    if (piece.size() >= kPiece) {
      write(piece.data(), piece.size());
      piece.clear();
    }
  }
  piece += scene.balls.empty() ? "\n}\n" : "\n  ]\n}\n";
  write(piece.data(), piece.size());
}

}  // namespace

QByteArray serializeScene(const Scene& scene) {
  QByteArray text;
  writeScene(scene, [&text](const char* data, std::size_t size) {
    text.append(data, static_cast<qsizetype>(size));
  });
  return text;
}

bool saveSceneFile(const Scene& scene, const QString& fileName, QString* error) {
  AtomicFile file(fileName);
  bool written = file.open();
  if (written) {
    writeScene(scene, [&](const char* data, std::size_t size) {
      written = written && file.write(data, size);
    });
    written = written && file.commit();
  }
  if (error) *error = written ? QString() : fileName + ": cannot save: " + file.errorString();
  return written;
}

}  // namespace carom::io
