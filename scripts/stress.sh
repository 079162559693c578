#!/usr/bin/env bash
# GUI stress run: `carom --bench-stress SECONDS` (default 300), a gas at about 10,000 collisions
# a second with explosions and sound on, in Xvfb with a null-sink PulseAudio server whose
# monitor is recorded. Prints the benchmark's report and fails unless memory stayed flat,
# explosions were shown, every 10 s report started sounds, and the recording has no silence
# longer than 3 s while the run lasted. Needs ./build, xvfb-run, parec and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-300}"

if [ "${2:-}" != "--inside" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1200x24" scripts/with-pulseaudio.sh "$0" "$seconds" --inside
fi

work=$(mktemp -d)
parec_pid=""
cleanup() {
  [ -n "$parec_pid" ] && kill "$parec_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

parec -d ci.monitor --format=s16le --rate=8000 --channels=1 --raw >"$work/monitor.raw" &
parec_pid=$!
./build/app/carom --bench-stress "$seconds" 2>"$work/stderr" | tee "$work/report"
kill "$parec_pid" 2>/dev/null || true
wait "$parec_pid" 2>/dev/null || true
parec_pid=""

python3 - "$work/report" "$work/monitor.raw" <<'PY'
import array, re, sys
report = open(sys.argv[1]).read()
data = open(sys.argv[2], "rb").read()
samples = array.array("h", data[: len(data) // 2 * 2])
rate = 8000
problems = []
if "sound on" not in report:
    problems.append("no sound output (is the PulseAudio server up?)")
if "memory flat: yes" not in report:
    problems.append("memory grew")
explosions = re.search(r"most live explosions: (\d+)", report)
if not explosions or int(explosions.group(1)) == 0:
    problems.append("no explosions were shown")
rows = re.findall(r"^\s*\d+\s+\d+\s+[\d.]+\s+[\d.]+\s+[\d.]+\s+[\d.]+\s+\d+\s+(\d+)\s+\d+\s*$", report, re.M)
if not rows or any(int(played) == 0 for played in rows):
    problems.append(f"some 10 s reports started no sounds: {rows}")
# Quarter-second blocks of the recording: loud when any sample is above -40 dBFS.
block = rate // 4
loud = [max(map(abs, samples[i:i + block]), default=0) > 327 for i in range(0, len(samples), block)]
if True in loud:
    first, last = loud.index(True), len(loud) - 1 - loud[::-1].index(True)
    longest = gap = 0
    longest_end = first
    for index in range(first, last + 1):
        gap = 0 if loud[index] else gap + 1
        if gap > longest:
            longest, longest_end = gap, index
    print(f"recording: {len(samples) / rate:.1f} s, sound from {first / 4:.2f} s to {last / 4:.2f} s, "
          f"longest silence {longest / 4:.2f} s (ending at {longest_end / 4 + 0.25:.2f} s)")
    if longest / 4 > 3:
        problems.append(f"the sound stopped for {longest / 4:.2f} s")
    if (last - first) / 4 < 0.9 * float(re.search(r"stress: \d+ balls, (\d+) s", report).group(1)):
        problems.append("the sound did not last the whole run")
else:
    problems.append("the recording is silent")
for p in problems:
    print("stress: " + p)
sys.exit(1 if problems else 0)
PY
