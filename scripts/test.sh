#!/usr/bin/env bash
# Every test: the suite in ./build, the Debian package built from it, installed and checked
# (scripts/package.sh), the soak runs (10 million events each), a GUI stress run
# (STRESS_SECONDS, default 60), the faults of issue 33 replayed against the built programs
# (scripts/faults.sh), a short fuzzing pass (FUZZ_SECONDS per target, default 30), the
# suite again built with AddressSanitizer (and UndefinedBehaviorSanitizer over sim/ and
# app/cli/), and the tests of the threaded parts built with ThreadSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage says how long it took, and the whole run at the end.
started=$SECONDS
stage() {
  local name=$1 start=$SECONDS
  shift
  echo "=== stage: $name"
  "$@"
  echo "=== stage: $name took $((SECONDS - start)) s (all stages so far: $((SECONDS - started)) s)"
}
stage suite ctest --test-dir build --output-on-failure -j2
stage package ./scripts/package.sh
stage soak ./scripts/soak.sh
stage stress ./scripts/stress.sh "${STRESS_SECONDS:-60}"
stage faults ./scripts/faults.sh
stage fuzz ./scripts/fuzz.sh "${FUZZ_SECONDS:-30}"
stage sanitize ./scripts/sanitize.sh
stage tsan ./scripts/tsan.sh
