#!/usr/bin/env bash
# Every test: the suite in ./build, the Debian package built from it, installed and checked
# (scripts/package.sh), the soak runs (10 million events each), a GUI stress run
# (STRESS_SECONDS, default 60), a short fuzzing pass (FUZZ_SECONDS per target, default 30), the
# suite again built with AddressSanitizer and UndefinedBehaviorSanitizer, and the tests of the
# threaded parts built with ThreadSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
ctest --test-dir build --output-on-failure -j2
./scripts/package.sh
./scripts/soak.sh
./scripts/stress.sh "${STRESS_SECONDS:-60}"
./scripts/fuzz.sh "${FUZZ_SECONDS:-30}"
./scripts/sanitize.sh
./scripts/tsan.sh
