// carom-sound: the window's collision sounds in a process of their own, which carom starts and
// starts again (ui/sound/sound_player.h says why and how they talk).

#include "ui/sound/sound_player.h"

#include <QCoreApplication>

#include <cstdio>

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
  return app.exec();
}
