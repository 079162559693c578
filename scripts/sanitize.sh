#!/usr/bin/env bash
# Builds everything with AddressSanitizer, and the physics, scene files and carom-cli (sim/,
# app/cli/) with UndefinedBehaviorSanitizer too, in ./build-asan, and runs the whole test suite
# there; any report fails the run. Leaks are checked outside the GUI tests.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build-asan/build.ninja ] ||
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAROM_SANITIZE=address \
    -DCAROM_SANITIZE_CORE=undefined
cmake --build build-asan -j2
export ASAN_OPTIONS="abort_on_error=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# Instrumented code runs several times slower than QtTest's five minutes per program allow.
export QTEST_FUNCTION_TIMEOUT=1800000
# Cases that only repeat one path over thousands of simulated seconds skip themselves here (they
# run in the plain suite): test_rest's took 300 of the 907 s this stage's tests took. So does a
# margin between measured costs, which instrumentation distorts (test_method_choice).
export CAROM_SANITIZER_RUN=1
# One run for all: the GUI tests, one at a time on the X server and without LeakSanitizer
# (tests/CMakeLists.txt), share the second job with the others.
ctest --test-dir build-asan --output-on-failure -j2
