// libFuzzer target: carom-cli's argument parsing, with the input cut into arguments at NUL
// bytes. Every command line parses into a command or a message. Built by scripts/fuzz.sh.

#include "app/cli/cli_arguments.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  QStringList arguments;
  const char* text = reinterpret_cast<const char*>(data);
  std::size_t start = 0;
  for (std::size_t i = 0; i <= size; ++i) {
    if (i == size || text[i] == '\0') {
      arguments.push_back(QString::fromUtf8(text + start, static_cast<qsizetype>(i - start)));
      start = i + 1;
    }
  }
  const carom::cli::ParseResult result = carom::cli::parseArguments(arguments);
  if (!result.command && result.error.isEmpty()) __builtin_trap();  // a refusal says why
  return 0;
}
