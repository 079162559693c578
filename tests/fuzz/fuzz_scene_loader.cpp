// libFuzzer target: any bytes given to the scene loader give a scene or a message, never a
// crash, a hang or an unbounded allocation; and the streaming reader accepts only what the
// reader that names errors accepts, building the same scene. Built by scripts/fuzz.sh.

#include "sim/io/scene_file.h"
#include "sim/io/scene_stream_reader.h"
#include "sim/validation/validation.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  const carom::io::SceneLoadResult result = carom::io::parseScene(json, "fuzz");
  // A loaded scene writes and reads back as the same scene.
  if (result.scene) {
    const carom::io::SceneLoadResult again =
        carom::io::parseScene(carom::io::serializeScene(*result.scene), "again");
    if (!again.scene || !(*again.scene == *result.scene)) __builtin_trap();
  } else if (result.error.isEmpty()) {
    __builtin_trap();  // a refusal always says why
  }
  const std::optional<carom::Scene> streamed = carom::io::readSceneStreaming(
      std::string_view(json.constData(), static_cast<std::size_t>(json.size())));
  const carom::io::SceneLoadResult named = carom::io::parseSceneNamingErrors(json, "fuzz");
  if (streamed) {
    // Either both read the same scene, or it reads and fails validation.
    const bool same = named.scene && *named.scene == *streamed;
    if (!same && (named.scene || carom::validateScene(*streamed, 1).empty())) __builtin_trap();
  }
  if (bool(named.scene) != bool(result.scene)) __builtin_trap();
  return 0;
}
