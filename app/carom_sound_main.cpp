// carom-sound: the window's collision sounds in a process of their own, which carom starts and
// starts again (ui/sound/sound_player.h says why and how they talk).

#include "ui/sound/sound_player.h"

#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>

#include <unistd.h>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  if (argc > 1) {
    std::fprintf(stderr,
                 "carom-sound: the collision sounds of carom's window, which starts it; it takes "
                 "no arguments\n");
    return 2;
  }
  carom::sound::SoundPlayer player(STDIN_FILENO);
  const int code = app.exec();
  // The window ends a player whenever it likes, often just after a sound started, and freeing a
  // PulseAudio stream right after a write can crash (a fresh-clone CI run saw the player end
  // with a crash once its input closed). It owns nothing else that needs tearing down: it
  // flushes what it said and leaves.
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(code);
}
