// libFuzzer target: any bytes given to the scene loader give a scene or a message, never a
// crash, a hang or an unbounded allocation. Built by scripts/fuzz.sh.

#include "sim/io/scene_file.h"

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
  return 0;
}
