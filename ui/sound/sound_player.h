#pragma once
// The window's collision sounds in a process of their own, `carom-sound`: Qt 6.4's audio backend
// gives up on a sound server that stays away for more than 3 s, for the rest of the process
// (sound_board.cpp), so the window plays through a player it can start anew (ui/sound_thread).
// They talk in lines on the player's standard input and output:
//   window → player: "hits CLACKS HARDEST THUDS HARDEST", one frame's FrameHits
//   player → window: "ready" once it can play, and "counts PLAYED DROPPED" (the player's own
//                    totals) after each frame
// The player exits when it cannot play (no output, the server lost, a sound that does not load)
// or when its input ends.

#include "ui/sound/sound_board.h"

#include <QByteArray>
#include <QObject>

#include <optional>

class QSocketNotifier;

namespace carom::sound {

QByteArray hitsLine(const FrameHits& hits);
std::optional<FrameHits> parseHitsLine(const QByteArray& line);

struct PlayerCounts {
  int played = 0;
  int dropped = 0;
};
QByteArray countsLine(const PlayerCounts& counts);
std::optional<PlayerCounts> parseCountsLine(const QByteArray& line);

inline constexpr char kReadyLine[] = "ready";

// Reads frames from a file descriptor and writes its answers to standard output; quits the
// application when it cannot play or the input ends.
class SoundPlayer : public QObject {
  Q_OBJECT
 public:
  explicit SoundPlayer(int input, QObject* parent = nullptr);

 private:
  void readInput();
  void say(const QByteArray& line);

  SoundBoard* board_;  // made once Qt's warnings are filtered
  int input_;
  QSocketNotifier* notifier_;
  QByteArray pending_;  // input up to an unfinished line
};

}  // namespace carom::sound
