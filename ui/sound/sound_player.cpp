#include "ui/sound/sound_player.h"

#include <QCoreApplication>
#include <QList>
#include <QSocketNotifier>

#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace carom::sound {

QByteArray hitsLine(const FrameHits& hits) {
  return "hits " + QByteArray::number(hits.count[Clack]) + ' ' +
         QByteArray::number(hits.hardest[Clack], 'g', 6) + ' ' +
         QByteArray::number(hits.count[Thud]) + ' ' +
         QByteArray::number(hits.hardest[Thud], 'g', 6);
}

std::optional<FrameHits> parseHitsLine(const QByteArray& line) {
  const QList<QByteArray> words = line.split(' ');
  if (words.size() != 5 || words[0] != "hits") return std::nullopt;
  FrameHits hits;
  for (int s = 0; s < SoundCount; ++s) {
    bool countOk = false;
    bool speedOk = false;
    hits.count[s] = words[1 + 2 * s].toInt(&countOk);
    hits.hardest[s] = words[2 + 2 * s].toDouble(&speedOk);
    if (!countOk || !speedOk || hits.count[s] < 0 || !std::isfinite(hits.hardest[s]))
      return std::nullopt;
  }
  return hits;
}

QByteArray countsLine(const PlayerCounts& counts) {
  return "counts " + QByteArray::number(counts.played) + ' ' + QByteArray::number(counts.dropped);
}

std::optional<PlayerCounts> parseCountsLine(const QByteArray& line) {
  const QList<QByteArray> words = line.split(' ');
  if (words.size() != 3 || words[0] != "counts") return std::nullopt;
  bool playedOk = false;
  bool droppedOk = false;
  const PlayerCounts counts{words[1].toInt(&playedOk), words[2].toInt(&droppedOk)};
  if (!playedOk || !droppedOk) return std::nullopt;
  return counts;
}

namespace {
constexpr qsizetype kLongestLine = 4096;
// Until the player can play, Qt's warnings only say that there is no sound server, and the
// window, which says so in its status line, starts a player every few seconds while there is
// none: they are dropped until then.
bool quiet = true;
QtMessageHandler qtHandler = nullptr;
void filterMessage(QtMsgType type, const QMessageLogContext& context, const QString& message) {
  if (quiet && type == QtWarningMsg) return;
  qtHandler(type, context, message);
}
}  // namespace

SoundPlayer::SoundPlayer(int input, QObject* parent)
    : QObject(parent),
      input_(input),
      notifier_(new QSocketNotifier(input, QSocketNotifier::Read, this)) {
  qtHandler = qInstallMessageHandler(filterMessage);
  board_ = new SoundBoard(this);
  connect(notifier_, &QSocketNotifier::activated, this, &SoundPlayer::readInput);
  connect(board_, &SoundBoard::availabilityChanged, this, [this](bool available) {
    if (!available) return;
    quiet = false;
    say(kReadyLine);
  });
  connect(board_, &SoundBoard::failure, this, [] { QCoreApplication::exit(0); });
  // Queued: exit() does nothing before the event loop runs.
  if (board_->failed())
    QMetaObject::invokeMethod(
        qApp, [] { QCoreApplication::exit(0); }, Qt::QueuedConnection);
}

void SoundPlayer::readInput() {
  char buffer[4096];
  const ssize_t got = ::read(input_, buffer, sizeof buffer);
  if (got <= 0) {  // the window is gone, or closed its end
    notifier_->setEnabled(false);
    QCoreApplication::exit(0);
    return;
  }
  pending_.append(buffer, got);
  // The window's lines are a few dozen bytes: anything longer is not from it.
  if (pending_.size() > kLongestLine && pending_.indexOf('\n') < 0) {
    std::fprintf(stderr, "carom-sound: a line over %d bytes, ignored\n", int(kLongestLine));
    pending_.clear();
  }
  qsizetype end;
  while ((end = pending_.indexOf('\n')) >= 0) {
    const QByteArray line = pending_.left(end);
    pending_.remove(0, end + 1);
    const std::optional<FrameHits> hits = parseHitsLine(line);
    if (!hits) {
      std::fprintf(stderr, "carom-sound: not a frame: %s\n", line.left(80).constData());
      continue;
    }
    board_->play(*hits);
    say(countsLine({board_->playedCount(), board_->droppedCount()}));
  }
}

void SoundPlayer::say(const QByteArray& line) {
  std::fwrite(line.constData(), 1, static_cast<size_t>(line.size()), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

}  // namespace carom::sound
