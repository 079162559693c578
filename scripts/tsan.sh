#!/usr/bin/env bash
# Builds the tests of Carom's threaded parts with ThreadSanitizer in ./build-tsan and runs them;
# any report fails the run. They are the physics worker's hand-over (the snapshot exchange and
# the call queue under contention in test_handover; running, stepping, live settings, the busy
# physics thread and the speed vs accuracy study's thread pool in test_main_window), editing
# while the simulation runs (test_editor), restarts while snapshots are in flight
# (test_run_session), huge scenes' restarts made on a thread of their own
# (test_simulation_sync) and the sound thread (test_sound); the rest of the
# suite runs on one thread. Debian's Qt, Mesa and PulseAudio are not built with TSan: tests/tsan.supp lists the
# false reports that follow from that, each with its reason, and none of Carom's own code.
#
# That the suppressions hide no race of Carom's was checked by putting two in by hand (a call
# made on the worker directly from the GUI thread, and CallQueue::post() reading its queue
# outside the lock): each failed test_main_window with the race's two stacks.
set -euo pipefail
cd "$(dirname "$0")/.."
tests=(test_handover test_run_session test_simulation_sync test_main_window test_editor test_sound)
# The video export's hand-over (the worker replaying the run into ui/run/video_frames.h's queue,
# the GUI draining it, Cancel, and abandoning on Reset) is checked by test_video_export's cases
# that start no child process. The MP4 cases start ffmpeg while the physics and sound threads
# run, and TSan then reports Qt-mediated hand-overs (queued-call slot objects, the sound board)
# at the window's teardown, with the GUI thread holding a lock of libxcb that it released long
# before: TSan has lost track of that thread's state. The same tests are clean when no child is
# started, and the ASan run and the plain suite run the MP4 cases.
video_cases=(framesAreTheRecordedOnesAtOrBefore pngFramesOfTheRecordedRun explosionsAreTheRunsCollisions
             cancelLeavesThePngsWritten badInputsAreRefused menuPausesAsksAndExports
             mp4IsDisabledWithoutFfmpeg)
# ASan and TSan cannot share a program, hence a build of its own (-O1 -g1, as for ASan).
[ -f build-tsan/build.ninja ] ||
  cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAROM_SANITIZE=thread
cmake --build build-tsan -j2 --target "${tests[@]}" test_video_export
# halt_on_error: the first report ends the program with TSan's exit code (66), so CTest fails
# it. die_after_fork=0: QProcess (test_sound's parec and its child run) starts its children in
# a way that TSan takes for a fork of this multi-threaded process, after which it would refuse
# every new thread; the children exec at once, so there is nothing for it to guard.
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:history_size=4:die_after_fork=0:suppressions=$PWD/tests/tsan.supp"
# Instrumented code runs several times slower than QtTest's five minutes per program allow.
export QTEST_FUNCTION_TIMEOUT=1800000
ctest --test-dir build-tsan --output-on-failure -j2 -R "^($(IFS='|'; echo "${tests[*]}"))\$"
CAROM_SOURCE_DIR=$PWD PULSE_SERVER=unix:/nonexistent/carom-no-audio \
  xvfb-run -a -s "-screen 0 1280x1024x24" build-tsan/tests/test_video_export "${video_cases[@]}"
