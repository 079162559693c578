#pragma once
// Benchmarks of the whole program in its real window, for `carom --bench-render`,
// `--bench-stress` and `--bench-open`. Each prints its figures to stdout and returns an exit
// code.

#include <QString>

namespace carom::app {

// A gas of `ballCount` balls running with the view at 1280x720: frame intervals and the longest
// stall of the GUI thread over 5 s, first for the same window and box without balls (the floor
// that composing the window costs), then with them, each figure also as a ratio to the floor.
int benchmarkRender(int ballCount);

// A gas hot enough for about 10,000 collisions a second, run for `seconds` with explosions and
// sound on: every 10 s the collision rate, frame rate, the GUI thread's longest stall, resident
// memory, live explosions and sounds played; then whether memory stayed flat.
int benchmarkStress(int seconds);

// Opens a scene file as File > Open does and reports how long until it is shown, how soon a run
// shows its first step and how far it gets in 5 s with the GUI's longest stall, how long the
// outline takes to open its balls and select the last one, and resident memory.
int benchmarkOpen(const QString& fileName);

}  // namespace carom::app
