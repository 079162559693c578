#include "sim/io/scene_file.h"

#include "sim/core/tolerances.h"
#include "sim/io/atomic_file.h"
#include "sim/io/file_names.h"
#include "sim/io/json_scan.h"
#include "sim/io/json_text.h"
#include "sim/io/scene_format.h"
#include "sim/io/scene_stream_reader.h"
#include "sim/validation/validation.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QScopeGuard>
#include <QSet>
#include <QStringList>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace carom::io {
namespace {

using format::kFirstVersionWithBoxes;
using format::kFirstVersionWithFriction;
constexpr int kFormatVersion = format::kVersion;
const QString kFormatName = QString::fromLatin1(format::kName.data(), format::kName.size());

// Parsing stops at the first problem; it travels to parseScene as this exception.
struct ParseFailure {
  QString path;
  QString what;
};

[[noreturn]] void fail(const QString& path, const QString& what) {
  throw ParseFailure{path, what};
}

QString describeType(const QJsonValue& value) {
  switch (value.type()) {
    case QJsonValue::Null:
      return "null";
    case QJsonValue::Bool:
      return "a boolean";
    case QJsonValue::Double:
      return "a number";
    case QJsonValue::String:
      return "a string";
    case QJsonValue::Array:
      return "an array";
    case QJsonValue::Object:
      return "an object";
    case QJsonValue::Undefined:
      break;
  }
  return "nothing";
}

QString quoted(const QString& text) {
  return '"' + text + '"';
}

std::string compactJson(const QJsonObject& object) {
  return QJsonDocument(object).toJson(QJsonDocument::Compact).toStdString();
}

// The fields of one JSON object, read by key; keys it is not asked about are the unknown ones.
class ObjectReader {
 public:
  ObjectReader(const QJsonObject& object, QString path, const QStringList& knownKeys)
      : object_(object), path_(std::move(path)), knownKeys_(knownKeys) {}

  bool has(const QString& key) const { return object_.contains(key); }
  QString pathOf(const QString& key) const { return memberPath(path_, key); }

  QJsonValue required(const QString& key) const {
    if (!has(key)) fail(pathOf(key), "is required but missing");
    return object_.value(key);
  }

  double number(const QString& key) const { return toNumber(required(key), pathOf(key)); }
  double number(const QString& key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }
  std::optional<double> optionalNumber(const QString& key) const {
    if (!has(key)) return std::nullopt;
    return number(key);
  }

  template <int Count>
  Eigen::Matrix<double, Count, 1> numbers(const QString& key) const {
    const QString path = pathOf(key);
    const QJsonValue value = required(key);
    const QString expected = QString("expected an array of %1 numbers, got ").arg(Count);
    if (!value.isArray()) fail(path, expected + describeType(value));
    const QJsonArray array = value.toArray();
    if (array.size() != Count)
      fail(path, expected + "an array of " + QString::number(array.size()) +
                     (array.size() == 1 ? " value" : " values"));
    Eigen::Matrix<double, Count, 1> result;
    for (int k = 0; k < Count; ++k) result[k] = toNumber(array[k], elementPath(path, k));
    return result;
  }
  Vec3 vector(const QString& key) const { return numbers<3>(key); }
  Vec3 vector(const QString& key, const Vec3& fallback) const {
    return has(key) ? vector(key) : fallback;
  }

  QString string(const QString& key) const {
    const QJsonValue value = required(key);
    if (!value.isString()) fail(pathOf(key), "expected a string, got " + describeType(value));
    return value.toString();
  }
  std::string optionalString(const QString& key) const {
    return has(key) ? string(key).toStdString() : std::string();
  }

  QJsonObject object(const QString& key) const {
    const QJsonValue value = required(key);
    if (!value.isObject()) fail(pathOf(key), "expected an object, got " + describeType(value));
    return value.toObject();
  }

  // Calls `readItem(object, path)` for each entry of the array under `key` (none when absent).
  void forEach(const QString& key, std::size_t limit,
               const std::function<void(const QJsonObject&, const QString&)>& readItem) const {
    if (!has(key)) return;
    const QString path = pathOf(key);
    const QJsonValue value = object_.value(key);
    if (!value.isArray()) fail(path, "expected an array, got " + describeType(value));
    const QJsonArray array = value.toArray();
    // Refused before building anything, as validation would after building it all.
    if (static_cast<std::size_t>(array.size()) > limit)
      fail(path, QString("must have at most %1 entries (got %2)").arg(limit).arg(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
      const QJsonValue item = array[i];
      if (!item.isObject())
        fail(elementPath(path, i), "expected an object, got " + describeType(item));
      readItem(item.toObject(), elementPath(path, i));
    }
  }

  // The unknown keys as the text of a JSON object, or empty when there are none.
  std::string extra() const {
    QJsonObject unknown;
    for (auto it = object_.begin(); it != object_.end(); ++it)
      if (!knownKeys_.contains(it.key())) unknown.insert(it.key(), it.value());
    return unknown.isEmpty() ? std::string() : compactJson(unknown);
  }

 private:
  static double toNumber(const QJsonValue& value, const QString& path) {
    if (!value.isDouble()) fail(path, "expected a number, got " + describeType(value));
    const double number = value.toDouble();
    // Qt's parser already refuses numbers beyond the range of double; this keeps it that way.
    if (!std::isfinite(number)) fail(path, "must be finite");
    return number;
  }

  const QJsonObject& object_;
  QString path_;
  const QStringList& knownKeys_;
};

void readInfo(const ObjectReader& reader, int version, ObjectInfo& info) {
  info.restitution = reader.optionalNumber("restitution");
  if (version >= kFirstVersionWithFriction) {
    info.friction = reader.optionalNumber("friction");
    info.rollingResistance = reader.optionalNumber("rollingResistance");
    info.spinningFriction = reader.optionalNumber("spinningFriction");
  }
  info.name = reader.optionalString("name");
  info.color = reader.optionalString("color");
  info.extra = reader.extra();
}

// Returns the version.
int checkFormatAndVersion(const ObjectReader& top) {
  const QJsonValue format = top.required("format");
  if (format.toString() != kFormatName)
    fail("format",
         "expected " + quoted(kFormatName) + ", got " +
             (format.isString() ? quoted(shortenedText(format.toString())) : describeType(format)));

  const QJsonValue version = top.required("version");
  if (!version.isDouble()) fail("version", "expected an integer, got " + describeType(version));
  const double number = version.toDouble();
  const QString text = QString::fromLatin1(numberText(number));
  if (number != std::floor(number)) fail("version", "expected an integer, got " + text);
  if (number < 1) fail("version", "must be at least 1 (got " + text + ")");
  if (number > kFormatVersion)
    fail("version", QString("version %1 was written by a newer Carom; this one reads version %2")
                        .arg(text)
                        .arg(kFormatVersion));
  return static_cast<int>(number);
}

template <typename Value>
Value readName(const ObjectReader& reader, const QString& key, Value fallback,
               std::optional<Value> (*fromName)(std::string_view),
               std::vector<std::string_view> (*allNames)(), const QString& what) {
  if (!reader.has(key)) return fallback;
  const QString name = reader.string(key);
  if (const auto value = fromName(name.toStdString())) return *value;
  QStringList valid;
  for (std::string_view entry : allNames())
    valid << QString::fromUtf8(entry.data(), static_cast<qsizetype>(entry.size()));
  fail(reader.pathOf(key),
       "unknown " + what + ' ' + quoted(shortenedText(name)) + "; use one of: " + valid.join(", "));
}

// The methods a file may name: the physics' own, and auto.
std::vector<std::string_view> fileMethodNames() {
  std::vector<std::string_view> names = methodNames();
  names.push_back(format::kAutoMethodName);
  return names;
}

World readWorld(const QJsonObject& object, int version) {
  const ObjectReader reader(object, "world", knownKeys(version).world);
  const World defaults;
  World world;
  world.gravity = reader.vector("gravity", defaults.gravity);
  world.timeStep = reader.number("timeStep", defaults.timeStep);
  world.restitution = reader.number("restitution", defaults.restitution);
  if (version >= kFirstVersionWithFriction) {
    world.friction = reader.number("friction", defaults.friction);
    world.rollingResistance = reader.number("rollingResistance", defaults.rollingResistance);
    world.spinningFriction = reader.number("spinningFriction", defaults.spinningFriction);
    world.tangentialRestitution =
        reader.number("tangentialRestitution", defaults.tangentialRestitution);
  }
  if (reader.has("method") && reader.string("method") == QLatin1String(format::kAutoMethodName)) {
    world.autoMethod = AccuracyTolerance{};
    if (reader.has("tolerance")) {
      const Eigen::Vector2d tolerance = reader.numbers<2>("tolerance");
      world.autoMethod = AccuracyTolerance{tolerance[0], tolerance[1]};
    }
  } else {
    if (reader.has("tolerance"))
      fail(reader.pathOf("tolerance"),
           "belongs to method \"auto\" alone; give that method or "
           "leave the tolerance out");
    world.method =
        readName(reader, "method", defaults.method, &methodFromName, &fileMethodNames, "method");
  }
  world.integrator = readName(reader, "integrator", defaults.integrator, &integratorFromName,
                              &integratorNames, "integrator");
  world.extra = reader.extra();
  return world;
}

Scene readScene(const QJsonObject& object) {
  // Format and version first: a newer file may mean something else by its other fields.
  const int version =
      checkFormatAndVersion(ObjectReader(object, QString(), knownKeys(format::kVersion).top));
  const KnownKeys& known = knownKeys(version);
  const ObjectReader top(object, QString(), known.top);

  Scene scene;
  if (top.has("world")) scene.world = readWorld(top.object("world"), version);
  top.forEach("planes", tolerance::kMaxPlanes, [&](const QJsonObject& item, const QString& path) {
    const ObjectReader reader(item, path, known.plane);
    Plane plane;
    plane.point = reader.vector("point");
    plane.normal = reader.vector("normal");
    readInfo(reader, version, plane);
    scene.planes.push_back(std::move(plane));
  });
  top.forEach("cylinders", tolerance::kMaxCylinders,
              [&](const QJsonObject& item, const QString& path) {
                const ObjectReader reader(item, path, known.cylinder);
                Cylinder cylinder;
                cylinder.point = reader.vector("point");
                cylinder.axis = reader.vector("axis");
                cylinder.radius = reader.number("radius");
                if (version >= kFirstVersionWithBoxes && reader.has("length"))
                  cylinder.length = reader.number("length");
                readInfo(reader, version, cylinder);
                scene.cylinders.push_back(std::move(cylinder));
              });
  if (version >= kFirstVersionWithBoxes)
    top.forEach("boxes", tolerance::kMaxBoxes, [&](const QJsonObject& item, const QString& path) {
      const ObjectReader reader(item, path, known.box);
      Box box;
      box.center = reader.vector("center");
      box.halfExtents = reader.vector("halfExtents");
      if (reader.has("rotation")) {
        const Eigen::Vector4d rotation = reader.numbers<4>("rotation");
        box.rotation = Rotation{rotation.head<3>(), rotation[3]};
      }
      readInfo(reader, version, box);
      scene.boxes.push_back(std::move(box));
    });
  top.forEach("balls", tolerance::kMaxBalls, [&](const QJsonObject& item, const QString& path) {
    const ObjectReader reader(item, path, known.ball);
    const Ball defaults;
    Ball ball;
    ball.position = reader.vector("position");
    ball.velocity = reader.vector("velocity", defaults.velocity);
    if (version >= kFirstVersionWithFriction)
      ball.angularVelocity = reader.vector("angularVelocity", defaults.angularVelocity);
    ball.radius = reader.number("radius");
    ball.mass = reader.number("mass", defaults.mass);
    readInfo(reader, version, ball);
    scene.balls.push_back(std::move(ball));
  });
  scene.extra = top.extra();
  return scene;
}

QString errorLine(const QString& sourceName, const QString& path, const QString& what) {
  return sourceName + ": " + (path.isEmpty() ? what : path + ": " + what);
}

SceneLoadResult validated(Scene scene, const QString& sourceName) {
  const auto errors = validateScene(scene, 1);
  if (!errors.empty())
    return {std::nullopt, sourceName + ": " + QString::fromStdString(errors.front().text())};
  return {std::move(scene), QString()};
}

}  // namespace

SceneLoadResult parseSceneNamingErrors(const QByteArray& json, const QString& sourceName) {
  const DocumentCounts counts = countDocument(json);
  if (counts.values > kMaxSceneValues)
    return {std::nullopt, sourceName + QString(": the document holds more than %1 values, the "
                                               "limit for scene files")
                                           .arg(kMaxSceneValues)};
  if (const auto errors = validateCounts(counts.lists); !errors.empty())
    return {std::nullopt, sourceName + ": " + QString::fromStdString(errors.front().text())};
  QJsonParseError parseError;
  const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
  if (parseError.error != QJsonParseError::NoError) {
    const auto [line, column] = lineAndColumn(json, parseError.offset);
    return {std::nullopt, sourceName + QString(": invalid JSON at line %1, column %2: %3")
                                           .arg(line)
                                           .arg(column)
                                           .arg(parseError.errorString())};
  }
  if (!document.isObject())
    return {std::nullopt, sourceName + ": expected a JSON object at the top, got an array"};
  if (const std::optional<QString> path = duplicateKeyPath(json))
    return {std::nullopt,
            errorLine(sourceName, *path, "duplicate key: a key may appear once in an object")};

  Scene scene;
  try {
    scene = readScene(document.object());
  } catch (const ParseFailure& failure) {
    return {std::nullopt, errorLine(sourceName, failure.path, failure.what)};
  }
  return validated(std::move(scene), sourceName);
}

namespace {

SceneLoadResult parseText(std::string_view json, const QString& sourceName) {
  if (std::optional<Scene> scene = readSceneStreaming(json))
    return validated(std::move(*scene), sourceName);
  return parseSceneNamingErrors(
      QByteArray::fromRawData(json.data(), static_cast<qsizetype>(json.size())), sourceName);
}

}  // namespace

SceneLoadResult parseScene(const QByteArray& json, const QString& sourceName) {
  try {
    return parseText(std::string_view(json.constData(), static_cast<std::size_t>(json.size())),
                     sourceName);
  } catch (const std::bad_alloc&) {
    return {std::nullopt, sourceName + ": not enough memory to load the scene"};
  }
}

namespace {

// What a refused load may have built (a document tree, a million balls) goes back to the
// system rather than stay with the process: the window lives on after the refusal.
void releaseFreeMemory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

struct FileText {
  QByteArray text;
  QString error;  // set when it could not be read whole
};

// The file's bytes, read into memory. Mapped instead, it killed the process with SIGBUS when it
// shrank under the reader; read, a change while it is read is found and said.
FileText readSceneText(const QString& fileName) {
  // The bundled examples are Qt resources (":/scenes/..."), in the program's memory.
  if (fileName.startsWith(":/")) {
    QFile resource(fileName);
    if (!resource.open(QIODevice::ReadOnly))
      return {{}, fileName + ": cannot open the file: " + resource.errorString()};
    return {resource.readAll(), {}};
  }
  // O_NONBLOCK: opening a FIFO with no writer would wait forever. Only regular files are read.
  const int descriptor =
      ::open(encodeFileName(fileName).constData(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (descriptor < 0) return {{}, fileName + ": cannot open the file: " + qt_error_string(errno)};
  const auto closeAfter = qScopeGuard([descriptor] { ::close(descriptor); });
  struct stat before;
  if (::fstat(descriptor, &before) != 0)
    return {{}, fileName + ": cannot read the file: " + qt_error_string(errno)};
  if (S_ISDIR(before.st_mode))
    return {{}, fileName + ": cannot open the file: file to open is a directory"};
  if (!S_ISREG(before.st_mode))
    return {{},
            fileName +
                ": not a regular file (a FIFO, device or socket); scene files are read "
                "from regular files only"};
  const QString tooLarge =
      fileName + QString(": the file is larger than the limit of %1 MiB for scene files")
                     .arg(kMaxSceneFileBytes / (1024 * 1024));
  if (before.st_size > kMaxSceneFileBytes) return {{}, tooLarge};
  QByteArray text;
  // One byte more than the size: a file that grows while it is read shows as a longer read.
  text.resize(qsizetype(before.st_size) + 1);
  qsizetype length = 0;
  while (true) {
    if (length == text.size()) {
      if (text.size() > kMaxSceneFileBytes) return {{}, tooLarge};
      text.resize(std::min<qsizetype>(2 * text.size() + 4096, kMaxSceneFileBytes + 1));
    }
    const ssize_t got = ::read(descriptor, text.data() + length, std::size_t(text.size() - length));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return {{}, fileName + ": cannot read the file: " + qt_error_string(errno)};
    if (got == 0) break;
    length += got;
  }
  text.truncate(length);
  struct stat after;
  const bool changed = ::fstat(descriptor, &after) != 0 || after.st_size != before.st_size ||
                       after.st_mtim.tv_sec != before.st_mtim.tv_sec ||
                       after.st_mtim.tv_nsec != before.st_mtim.tv_nsec ||
                       (before.st_size > 0 && length != before.st_size);
  if (changed)
    return {{},
            fileName + QString(": the file changed while it was read (it had %1 bytes, %2 "
                               "were read); open it again once it is written")
                           .arg(before.st_size)
                           .arg(length)};
  return {std::move(text), {}};
}

}  // namespace

SceneLoadResult loadSceneFile(const QString& fileName) {
  SceneLoadResult result;
  try {
    FileText file = readSceneText(fileName);
    if (!file.error.isEmpty()) return {std::nullopt, file.error};
    result = parseScene(file.text, fileName);
  } catch (const std::bad_alloc&) {
    result = {std::nullopt, fileName + ": not enough memory to load the scene"};
  }
  if (!result.scene) releaseFreeMemory();
  return result;
}

}  // namespace carom::io
