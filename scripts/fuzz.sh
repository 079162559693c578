#!/usr/bin/env bash
# Fuzzes the scene loader, carom-cli's argument parsing and the running of valid scenes with
# libFuzzer (clang, with AddressSanitizer and UndefinedBehaviorSanitizer) for SECONDS each
# (default 60), seeded with the bundled scenes, the bad-input files and earlier findings.
# Prints each target's executions; fails when a target finds a crash, a hang or an unbounded
# allocation, leaving the input in build-fuzz/findings/ (keep it in
# tests/fuzz/regressions/TARGET/ once fixed).
#
# The random seed is FUZZ_SEED (default 1; 0 lets libFuzzer choose): from a fresh clone every
# run tries the same inputs in the same order, a slower machine only fewer of them, so that the
# CI fails for a finding of the change it checks and not by chance. Longer runs here, and other
# seeds, look further.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
seed="${FUZZ_SEED:-1}"
[ -f build-fuzz/build.ninja ] ||
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCAROM_SANITIZE=fuzzer-no-link,address,undefined -DCAROM_FUZZ=ON
cmake --build build-fuzz -j2 --target fuzz_scene_loader fuzz_cli_arguments fuzz_valid_scenes
mkdir -p build-fuzz/findings
status=0
for target in fuzz_scene_loader fuzz_cli_arguments fuzz_valid_scenes; do
  corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus"
  seeds=(tests/fuzz/seeds/"$target" tests/fuzz/regressions/"$target")
  [ "$target" = fuzz_scene_loader ] && seeds+=(resources/scenes)
  for dir in "${seeds[@]}"; do [ -d "$dir" ] && cp -n "$dir"/* "$corpus"/ 2>/dev/null || true; done
  echo "== $target, $seconds s"
  # A valid scene may rightly take long here: the limit of ten million reflections in one
  # event (rule 6 of "Resting contact" in docs/physics.md) takes 0.1 s in a release build and
  # 5 s under the sanitizers and libFuzzer's coverage, and a wedge of three planes can reach it
  # a few dozen times in a run (2.5 s in a release build).
  timeout=10
  [ "$target" = fuzz_valid_scenes ] && timeout=60
  if ! ASAN_OPTIONS="detect_leaks=0" "build-fuzz/tests/fuzz/$target" "$corpus" \
      -seed="$seed" -max_total_time="$seconds" -max_len=65536 -timeout="$timeout" -rss_limit_mb=2048 \
      -malloc_limit_mb=1024 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/findings/$target-" 2>"build-fuzz/$target.log"; then
    status=1
    tail -n 40 "build-fuzz/$target.log"
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "build-fuzz/$target.log" || true
done
ls build-fuzz/findings
exit $status
