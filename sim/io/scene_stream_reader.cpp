#include "sim/io/scene_stream_reader.h"

#include "sim/core/prefault.h"
#include "sim/core/tolerances.h"
#include "sim/io/json_cursor.h"
#include "sim/io/scene_file.h"
#include "sim/io/scene_format.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace carom::io {
namespace {

using stream::Cursor;
using stream::giveUp;
using stream::GiveUp;
using stream::Member;
using stream::Value;

// Qt's compact JSON of an object whose members' texts `members` holds, comma-separated: the text
// ObjectReader::extra gives for the same unknown members.
std::string compactObject(QByteArray members) {
  return QJsonDocument(QJsonDocument::fromJson('{' + members + '}').object())
      .toJson(QJsonDocument::Compact)
      .toStdString();
}

// The members of one object, looked up by key as ObjectReader does in scene_file.cpp.
class Fields {
 public:
  // Reads the object at the cursor, whose known keys are `known`.
  void read(Cursor& cursor, std::span<const std::string_view> known) {
    count_ = 0;
    known_ = known;
    cursor.members([&](const std::string& key, const char* start) {
      for (int k = 0; k < count_; ++k)
        if (members_[k].key == key) giveUp();
      if (count_ == static_cast<int>(members_.size())) members_.emplace_back();
      Member& member = members_[count_++];
      member.key = key;
      cursor.value(member.value);
      member.raw = std::string_view(start, static_cast<std::size_t>(cursor.position() - start));
    });
  }

  const Value* find(std::string_view key) const {
    for (int k = 0; k < count_; ++k)
      if (members_[k].key == key) return &members_[k].value;
    return nullptr;
  }
  double number(std::string_view key) const {
    const Value* value = find(key);
    if (!value || value->kind != Value::Kind::Number) giveUp();
    return value->number;
  }
  double number(std::string_view key, double fallback) const {
    return find(key) ? number(key) : fallback;
  }
  std::optional<double> optionalNumber(std::string_view key) const {
    if (!find(key)) return std::nullopt;
    return number(key);
  }
  template <int Count>
  std::array<double, 4> numbers(std::string_view key) const {
    const Value* value = find(key);
    if (!value || value->kind != Value::Kind::Numbers || value->count != Count) giveUp();
    return value->numbers;
  }
  Vec3 vector(std::string_view key) const {
    const std::array<double, 4> v = numbers<3>(key);
    return Vec3(v[0], v[1], v[2]);
  }
  Vec3 vector(std::string_view key, const Vec3& fallback) const {
    return find(key) ? vector(key) : fallback;
  }
  const std::string& string(std::string_view key) const {
    const Value* value = find(key);
    if (!value || value->kind != Value::Kind::String) giveUp();
    return value->text;
  }
  std::string optionalString(std::string_view key) const {
    return find(key) ? string(key) : std::string();
  }

  // The unknown members as the text ObjectReader::extra gives: Qt's compact JSON of them.
  std::string extra() const {
    QByteArray text;
    for (int k = 0; k < count_; ++k) {
      const Member& member = members_[k];
      if (std::find(known_.begin(), known_.end(), member.key) != known_.end()) continue;
      if (!text.isEmpty()) text += ',';
      text.append(member.raw.data(), static_cast<qsizetype>(member.raw.size()));
    }
    return text.isEmpty() ? std::string() : compactObject(text);
  }

  void readInfo(int version, ObjectInfo& info) const {
    info.restitution = optionalNumber("restitution");
    if (version >= format::kFirstVersionWithFriction) {
      info.friction = optionalNumber("friction");
      info.rollingResistance = optionalNumber("rollingResistance");
      info.spinningFriction = optionalNumber("spinningFriction");
    }
    info.name = optionalString("name");
    info.color = optionalString("color");
    info.extra = extra();
  }

 private:
  std::vector<Member> members_;  // kept from object to object, so that strings keep their room
  int count_ = 0;
  std::span<const std::string_view> known_;
};

template <typename Value>
Value named(const Fields& fields, std::string_view key, Value fallback,
            std::optional<Value> (*fromName)(std::string_view)) {
  if (!fields.find(key)) return fallback;
  const std::optional<Value> value = fromName(fields.string(key));
  if (!value) giveUp();
  return *value;
}

// Calls read() for each element of the array at the cursor, which must be objects, at most
// `limit` of them.
template <typename Read>
void forEachObject(Cursor& cursor, std::size_t limit, Read&& read) {
  std::size_t count = 0;
  cursor.elements([&] {
    if (++count > limit || cursor.peek() != '{') giveUp();
    read();
  });
}

Scene read(Cursor& cursor, std::size_t textSize) {
  Scene scene;
  // Room for more balls than the text can hold (a ball takes 32 bytes at least), so that the
  // list is never copied as it grows; room never written to costs no memory.
  scene.balls.reserve(std::min<std::size_t>(tolerance::kMaxBalls, textSize / 32));
  Fields fields;
  int version = 0;
  bool formatSeen = false;
  int membersRead = 0;
  std::vector<std::string> keys;
  QByteArray unknown;
  if (cursor.peek() != '{') giveUp();
  cursor.members([&](const std::string& key, const char* start) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) giveUp();
    keys.push_back(key);
    // Format and version first, as the writer puts them: what the other keys mean depends on
    // the version.
    if (membersRead++ < 2) {
      if (key == "format") {
        std::string name;
        cursor.stringValue(name);
        if (name != format::kName) giveUp();
        formatSeen = true;
      } else if (key == "version") {
        const double number = cursor.number();
        if (number != std::floor(number) || number < 1 || number > format::kVersion) giveUp();
        version = static_cast<int>(number);
      } else {
        giveUp();
      }
      return;
    }
    if (!formatSeen || version == 0) giveUp();
    const bool versionOne = version < format::kFirstVersionWithBoxes;
    const bool withFriction = version >= format::kFirstVersionWithFriction;
    const format::VersionKeys known = format::versionKeys(version);
    if (key == "world") {
      if (cursor.peek() != '{') giveUp();
      fields.read(cursor, known.world);
      const World defaults;
      World& world = scene.world;
      world.gravity = fields.vector("gravity", defaults.gravity);
      world.timeStep = fields.number("timeStep", defaults.timeStep);
      world.restitution = fields.number("restitution", defaults.restitution);
      if (withFriction) {
        world.friction = fields.number("friction", defaults.friction);
        world.rollingResistance = fields.number("rollingResistance", defaults.rollingResistance);
        world.spinningFriction = fields.number("spinningFriction", defaults.spinningFriction);
        world.tangentialRestitution =
            fields.number("tangentialRestitution", defaults.tangentialRestitution);
      }
      if (fields.find("method") && fields.string("method") == format::kAutoMethodName) {
        world.autoMethod = AccuracyTolerance{};
        if (fields.find("tolerance")) {
          const std::array<double, 4> tolerance = fields.numbers<2>("tolerance");
          world.autoMethod = AccuracyTolerance{tolerance[0], tolerance[1]};
        }
      } else {
        if (fields.find("tolerance")) giveUp();  // the other reader says why
        world.method = named(fields, "method", defaults.method, &methodFromName);
      }
      world.integrator = named(fields, "integrator", defaults.integrator, &integratorFromName);
      world.extra = fields.extra();
    } else if (key == "planes") {
      forEachObject(cursor, tolerance::kMaxPlanes, [&] {
        fields.read(cursor, known.plane);
        Plane& plane = scene.planes.emplace_back();
        plane.point = fields.vector("point");
        plane.normal = fields.vector("normal");
        fields.readInfo(version, plane);
      });
    } else if (key == "cylinders") {
      forEachObject(cursor, tolerance::kMaxCylinders, [&] {
        fields.read(cursor, known.cylinder);
        Cylinder& cylinder = scene.cylinders.emplace_back();
        cylinder.point = fields.vector("point");
        cylinder.axis = fields.vector("axis");
        cylinder.radius = fields.number("radius");
        if (!versionOne) cylinder.length = fields.optionalNumber("length");
        fields.readInfo(version, cylinder);
      });
    } else if (key == "boxes" && !versionOne) {
      forEachObject(cursor, tolerance::kMaxBoxes, [&] {
        fields.read(cursor, known.box);
        Box& box = scene.boxes.emplace_back();
        box.center = fields.vector("center");
        box.halfExtents = fields.vector("halfExtents");
        if (fields.find("rotation")) {
          const std::array<double, 4> rotation = fields.numbers<4>("rotation");
          box.rotation = Rotation{Vec3(rotation[0], rotation[1], rotation[2]), rotation[3]};
        }
        fields.readInfo(version, box);
      });
    } else if (key == "balls") {
      const Ball defaults;
      forEachObject(cursor, tolerance::kMaxBalls, [&] {
        // The room reserved is mapped in a piece at a time, ahead of the balls written to it.
        constexpr std::size_t kPiece = 16384;
        std::vector<Ball>& balls = scene.balls;
        if (balls.size() % kPiece == 0 && balls.size() < balls.capacity())
          prefaultForWriting(balls.data() + balls.size(),
                             std::min(kPiece, balls.capacity() - balls.size()) * sizeof(Ball));
        fields.read(cursor, known.ball);
        Ball& ball = scene.balls.emplace_back();
        ball.position = fields.vector("position");
        ball.velocity = fields.vector("velocity", defaults.velocity);
        if (withFriction)
          ball.angularVelocity = fields.vector("angularVelocity", defaults.angularVelocity);
        ball.radius = fields.number("radius");
        ball.mass = fields.number("mass", defaults.mass);
        fields.readInfo(version, ball);
      });
    } else {
      cursor.skipValue(1);
      if (!unknown.isEmpty()) unknown += ',';
      unknown.append(start, static_cast<qsizetype>(cursor.position() - start));
    }
  });
  if (!cursor.atEnd() || !formatSeen || version == 0) giveUp();
  if (!unknown.isEmpty()) scene.extra = compactObject(unknown);
  return scene;
}

}  // namespace

std::optional<Scene> readSceneStreaming(std::string_view json) {
  try {
    Cursor cursor(json);
    return read(cursor, json.size());
  } catch (const GiveUp&) {
    return std::nullopt;
  }
}

}  // namespace carom::io
