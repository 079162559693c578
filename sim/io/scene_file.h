#pragma once
// Scene files: the JSON format of docs/scene-format.md, read and written with QtCore.

#include "sim/model/scene.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace carom::io {

struct SceneLoadResult {
  std::optional<Scene> scene;  // set on success
  QString error;               // on failure: "<file>: <field path>: <what is wrong>"
};

// Reads a scene from JSON text; `sourceName` starts every error message. The scene is validated
// (validateScene), so a returned scene is ready to simulate.
SceneLoadResult parseScene(const QByteArray& json, const QString& sourceName);
// Reads the file into memory (a file that changes while it is read is refused with a message),
// then as parseScene. Names go to the system as decodeFileName's bytes (file_names.h). Running
// out of memory is a message too.
SceneLoadResult loadSceneFile(const QString& fileName);
// The reader behind parseScene's messages: Qt's JSON parser (line and column of a syntax
// error), then each field by its path. parseScene turns to it whenever the streaming reader
// (scene_stream_reader.h) gives up; it is several times slower and takes several times the
// memory of the scene.
SceneLoadResult parseSceneNamingErrors(const QByteArray& json, const QString& sourceName);

// Indented JSON, in the oldest format version that holds the scene (scene_format.h); unknown keys
// kept in the scene's `extra` fields are written back, so that saving what was loaded loses
// nothing.
QByteArray serializeScene(const Scene& scene);
// Replaces `fileName` whole (atomic_file.h): on failure the old file is untouched and `*error`
// (when given) says why.
bool saveSceneFile(const Scene& scene, const QString& fileName, QString* error);

// Files larger than this are refused unread.
inline constexpr qint64 kMaxSceneFileBytes = qint64{256} * 1024 * 1024;
// Documents with more values than this are refused before they are parsed, since the parsed
// tree takes tens of bytes a value. A million balls with every field set hold about 14 million.
inline constexpr qint64 kMaxSceneValues = 30'000'000;

}  // namespace carom::io
