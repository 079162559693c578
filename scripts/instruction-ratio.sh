#!/usr/bin/env bash
# What one carom-cli costs against another on the same frictionless runs, in instructions
# counted by valgrind's callgrind: the same count for the same binary and input whatever else the
# machine does, so a change of a few per cent shows where wall times vary by twenty.
#   scripts/instruction-ratio.sh BEFORE_CLI AFTER_CLI
# Runs gases of 1,000 balls, of 200 under gravity and of 2,000 in two sizes (every method), and
# the bundled gas box and magic room (exact), each whole process under both; checks that both
# made the same collisions; prints a Markdown table of the counts and their ratio. Needs
# valgrind and python3; a few minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { echo "usage: $0 BEFORE_CLI AFTER_CLI" >&2; exit 2; }
before=$(realpath "$1")
after=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Balls on a cubic lattice in a box of six walls at a tenth of its volume, Gaussian velocities
# of unit spread; every second one of half the radius when mixed. Version 1 files, which every
# carom-cli reads.
python3 - "$work" <<'EOF'
import json, math, random, sys
def gas(path, n, radius, gravity, seed, mixed=False):
    rng = random.Random(seed)
    side = (n * 4 / 3 * math.pi * radius ** 3 / 0.1) ** (1 / 3)
    half, per = side / 2, math.ceil(n ** (1 / 3))
    spacing = side / per
    walls = [([0, -half, 0], [0, 1, 0]), ([0, half, 0], [0, -1, 0]), ([-half, 0, 0], [1, 0, 0]),
             ([half, 0, 0], [-1, 0, 0]), ([0, 0, -half], [0, 0, 1]), ([0, 0, half], [0, 0, -1])]
    balls = []
    for i in range(n):
        cell = (i % per, (i // per) % per, i // (per * per))
        balls.append({"position": [(c + 0.5) * spacing - half for c in cell],
                      "velocity": [rng.gauss(0, 1) for _ in range(3)],
                      "radius": radius * (0.5 if mixed and i % 2 else 1.0), "mass": 1})
    scene = {"format": "carom-scene", "version": 1,
             "units": {"length": "m", "mass": "kg", "time": "s"},
             "world": {"gravity": [0, gravity, 0], "timeStep": 0.001, "restitution": 1,
                       "method": "exact", "integrator": "symplectic-euler"},
             "planes": [{"point": p, "normal": n} for p, n in walls], "cylinders": [],
             "balls": balls}
    with open(path, "w") as f:
        json.dump(scene, f)
work = sys.argv[1]
gas(work + "/gas.json", 1000, 0.05, 0.0, 1)
gas(work + "/gravity-gas.json", 200, 0.05, -9.81, 2)
gas(work + "/mixed.json", 2000, 0.02, 0.0, 3, mixed=True)
EOF

runs=(
  "$work/gas.json exact 10" "$work/gas.json swept 1" "$work/gas.json discrete 1"
  "$work/gravity-gas.json exact 10" "$work/gravity-gas.json swept 2"
  "$work/gravity-gas.json discrete 2" "$work/mixed.json exact 1" "$work/mixed.json swept 0.2"
  "$work/mixed.json discrete 0.2" "resources/scenes/gas-box.json exact 20"
  "resources/scenes/magic-room.json exact 100"
)

instructions() {  # CLI SCENE METHOD DURATION REPORT: the process's instruction count
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" run "$2" --method "$3" \
    --duration "$4" --json 2>"$work/callgrind.err" >"$5"
  grep -o 'Collected : [0-9]*' "$work/callgrind.err" | awk '{print $3}'
}

echo "| scene | method | simulated s | before, 10⁹ instructions | after | after/before |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
for run in "${runs[@]}"; do
  read -r scene method duration <<<"$run"
  old=$(instructions "$before" "$scene" "$method" "$duration" "$work/before.json")
  new=$(instructions "$after" "$scene" "$method" "$duration" "$work/after.json")
  python3 - "$work" "$(basename "$scene" .json)" "$method" "$duration" "$old" "$new" <<'EOF'
import json, sys
work, scene, method, duration, old, new = sys.argv[1:]
counts = [json.load(open(f"{work}/{name}.json"))["collisions"] for name in ("before", "after")]
if counts[0] != counts[1]:
    sys.exit(f"{scene} {method}: the collisions differ: {counts[0]} against {counts[1]}")
old, new = int(old), int(new)
print(f"| {scene} | {method} | {duration} | {old / 1e9:.3f} | {new / 1e9:.3f} | {new / old:.3f} |")
EOF
done
