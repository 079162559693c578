#!/usr/bin/env bash
# Long runs of the exact method: the magic room and a gas of 1,000 balls, each for EVENTS events
# (default 10 million). Checks that every ball's final state is finite, none escaped, the energy
# drifted less than 1e-9 of itself, and the memory stayed flat (sampled every tenth of a second;
# the last sample within 10 % + 4 MiB of the one a fifth of the way in). Needs ./build and
# python3.
set -euo pipefail
cd "$(dirname "$0")/.."
events="${1:-10000000}"
cli=./build/app/carom-cli
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A 10 x 10 x 10 lattice of balls of radius 0.05 m, 0.2 m apart, in a box of six walls, with
# velocities of up to 1 m/s in each direction and no gravity.
awk 'BEGIN {
  srand(2007);
  printf "{\"format\": \"carom-scene\", \"version\": 1,\n";
  printf " \"world\": {\"gravity\": [0, 0, 0], \"method\": \"exact\"},\n";
  printf " \"planes\": [{\"point\": [0, 0, 0], \"normal\": [1, 0, 0]}, {\"point\": [2, 0, 0], \"normal\": [-1, 0, 0]},\n";
  printf "  {\"point\": [0, 0, 0], \"normal\": [0, 1, 0]}, {\"point\": [0, 2, 0], \"normal\": [0, -1, 0]},\n";
  printf "  {\"point\": [0, 0, 0], \"normal\": [0, 0, 1]}, {\"point\": [0, 0, 2], \"normal\": [0, 0, -1]}],\n";
  printf " \"balls\": [";
  n = 0;
  for (i = 0; i < 10; ++i) for (j = 0; j < 10; ++j) for (k = 0; k < 10; ++k) {
    printf "%s\n  {\"position\": [%g, %g, %g], \"velocity\": [%g, %g, %g], \"radius\": 0.05}",
      (n++ ? "," : ""), 0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.1 + 0.2 * k,
      2 * rand() - 1, 2 * rand() - 1, 2 * rand() - 1;
  }
  printf "]}\n";
}' > "$work/gas-1000.json"

status=0
soak() {  # soak NAME SCENE
  local name=$1 scene=$2
  # Simulated seconds for the events asked, from a short run's rate.
  local rate
  rate=$("$cli" run "$scene" --duration 10 --json |
    python3 -c 'import json, sys; r = json.load(sys.stdin); print(r["events"] / r["simulatedTime"])')
  local duration
  duration=$(python3 -c "print($events / $rate)")
  "$cli" run "$scene" --duration "$duration" --json > "$work/$name.report.json" &
  local pid=$! samples=()
  while kill -0 "$pid" 2>/dev/null; do
    sleep 0.1
    samples+=("$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)")
  done
  wait "$pid"
  printf '%s\n' "${samples[@]}" | grep -v '^$' > "$work/$name.rss" || true
  python3 - "$name" "$work/$name.report.json" "$work/$name.rss" "$events" <<'EOF' || status=1
import json, math, sys
name, report_file, rss_file, target = sys.argv[1:5]
target = int(target)
r = json.load(open(report_file))
rss = [int(x) for x in open(rss_file).read().split()]
values = [x for b in r["balls"] for key in ("position", "velocity") for x in b[key]]
finite = all(isinstance(x, (int, float)) and math.isfinite(x) for x in values)
e0, e1 = r["energy"]["initial"], r["energy"]["final"]
drift = abs(e1 - e0) / abs(e0)
# After the first fifth of the run (loading, the event queue filling), memory stays put.
settled = rss[len(rss) // 5] if rss else 0
flat = len(rss) >= 5 and rss[-1] <= settled * 1.10 + 4096
print(f"{name}: {r['events']:,} events in {r['wallSeconds']:.1f} s "
      f"({r['simulatedTime']:.0f} simulated s), collisions {sum(r['collisions'].values()):,}; "
      f"finite {finite}, escaped {r['escaped']}, deepest penetration {r['maxPenetration']:.2g} m, "
      f"energy drift {drift:.2g}; memory {settled // 1024} MiB after a fifth of the run, "
      f"{rss[-1] // 1024 if rss else 0} MiB at the end, {max(rss, default=0) // 1024} MiB at most "
      f"({len(rss)} samples)")
enough = r["events"] >= 0.95 * target
sys.exit(0 if enough and finite and r["escaped"] == 0 and drift < 1e-9 and flat else 1)
EOF
}
soak magic-room resources/scenes/magic-room.json
soak gas-1000 "$work/gas-1000.json"
exit $status
