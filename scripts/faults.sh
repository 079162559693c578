#!/usr/bin/env bash
# Replays the faults of issue 33 against the built programs (build/app/carom-cli and
# build/app/carom, the window driven with xdotool under Xvfb) and prints what it tried and what
# happened: a full disk under a save and a trajectory, a scene file cut short while it loads, an
# output that is the input, file names in Latin-1 bytes, a memory limit, and the sound server
# killed and restarted under a running window. Exits 1 when a promise does not hold. The full
# disk is a small tmpfs, which needs root (CI runs as root); without it those cases are skipped
# with a message.
set -uo pipefail
cd "$(dirname "$0")/.."
cli="$PWD/build/app/carom-cli"
window="$PWD/build/app/carom"
for program in "$cli" "$window"; do
  [ -x "$program" ] || { echo "faults: $program is not built (scripts/build.sh)" >&2; exit 2; }
done
for tool in xvfb-run xdotool python3; do
  command -v "$tool" >/dev/null || { echo "faults: $tool not found (scripts/setup-debian.sh)" >&2; exit 2; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/carom-faults.XXXXXX")
disk="$work/disk"
mkdir -p "$disk"
cleanup() {
  mountpoint -q "$disk" && umount -l "$disk"
  rm -rf "$work"
}
trap cleanup EXIT

failures=0
begin() { echo "== $*"; }
said() { echo "   $*"; }
holds() { echo "   ok: $*"; }
broken() {
  echo "   FAILED: $*"
  failures=$((failures + 1))
}
# Exit code of the last command, and whether a signal ended it.
describe_exit() {
  local code=$1
  if [ "$code" -gt 128 ]; then echo "killed by signal $((code - 128))"; else echo "exit $code"; fi
}

room="resources/scenes/magic-room.json"

# A scene of N balls on a lattice, written by python3 (fast, no dependency on the programs).
write_gas() {
  python3 - "$1" "$2" <<'EOF'
import sys
path, n = sys.argv[1], int(sys.argv[2])
with open(path, "w") as f:
    f.write('{"format": "carom-scene", "version": 1, "balls": [\n')
    f.write(",\n".join('{"position": [%g, %g, %g], "radius": 0.01}'
                       % (0.1 * (i % 100), 0.1 * ((i // 100) % 100), 0.1 * (i // 10000))
                       for i in range(n)))
    f.write("]}\n")
EOF
}

mounted=false
if mount -t tmpfs -o size=200k tmpfs "$disk" 2>"$work/mount.err"; then
  mounted=true
else
  echo "faults: cannot mount a tmpfs ($(cat "$work/mount.err")); the full-disk cases are skipped"
fi
fill_disk() {  # fill_disk [BYTES_LEFT]
  rm -f "$disk/.filler"
  dd if=/dev/zero of="$disk/.filler" bs=4k 2>/dev/null
  [ "${1:-0}" -gt 0 ] && truncate -s "-${1}" "$disk/.filler"
  return 0
}

# --- a full disk ---
if $mounted; then
  begin "carom-cli run --trajectory on a full disk (200 KiB tmpfs, 4 KiB left, an old trajectory there)"
  printf 'old\n' >"$disk/kept.csv"
  fill_disk 4096
  "$cli" run "$room" --duration 2 --trajectory "$disk/kept.csv" >/dev/null 2>"$work/err"
  code=$?
  said "$(describe_exit $code): $(head -c 300 "$work/err")"
  [ $code -eq 1 ] && grep -q "No space left on device" "$work/err" &&
    holds "refused with the reason" || broken "expected exit 1 and 'No space left on device'"
  [ "$(cat "$disk/kept.csv")" = "old" ] && holds "the old trajectory is whole" ||
    broken "the old trajectory changed"
  [ "$(ls "$disk")" = "kept.csv" ] && holds "no partial file left" ||
    broken "files left: $(ls "$disk" | tr '\n' ' ')"
  rm -f "$disk/.filler" "$disk/kept.csv"

  begin "the window: open a scene on the tmpfs, Ctrl+A Delete, fill the disk, Ctrl+S, Ctrl+Q"
  cp "$room" "$disk/room.json"
  cp "$disk/room.json" "$work/room-before.json"
  cat >"$work/window-save.sh" <<EOF
#!/usr/bin/env bash
set -u
export HOME="$work/home" PULSE_SERVER=unix:/nonexistent/carom-faults
mkdir -p "\$HOME"
"$window" "$disk/room.json" >"$work/window.log" 2>&1 &
pid=\$!
title() { xdotool getwindowname "\$id" 2>/dev/null; }
dialog() { xdotool search --name "\$1" 2>/dev/null | head -1; }
for i in \$(seq 100); do id=\$(dialog 'room.json'); [ -n "\$id" ] && break; sleep 0.2; done
[ -n "\$id" ] || { echo "no window"; kill \$pid; exit 1; }
sleep 1
xdotool windowfocus --sync "\$id"
xdotool key ctrl+a; sleep 0.3; xdotool key Delete; sleep 0.5
echo "edited: title '\$(title)'"
dd if=/dev/zero of="$disk/.filler" bs=4k 2>/dev/null
xdotool key ctrl+s
for i in \$(seq 50); do box=\$(dialog 'Cannot Save Scene'); [ -n "\$box" ] && break; sleep 0.2; done
echo "saved on a full disk: dialog '\$([ -n "\$box" ] && xdotool getwindowname "\$box")', title '\$(title)'"
[ -n "\$box" ] && { xdotool windowfocus --sync "\$box"; xdotool key Return; sleep 0.5; }
xdotool windowfocus --sync "\$id"
xdotool key ctrl+q
for i in \$(seq 50); do ask=\$(dialog 'Unsaved Changes'); [ -n "\$ask" ] && break; sleep 0.2; done
echo "quit: asked '\$([ -n "\$ask" ] && xdotool getwindowname "\$ask")'"
[ -n "\$ask" ] && { xdotool windowfocus --sync "\$ask"; xdotool key Escape; sleep 0.5; }
kill -0 \$pid 2>/dev/null && echo "still running after Cancel" || echo "gone after Cancel"
rm -f "$disk/.filler"
xdotool windowfocus --sync "\$id"
xdotool key ctrl+s; sleep 1
echo "saved with room: title '\$(title)'"
kill \$pid; wait \$pid 2>/dev/null
EOF
  chmod +x "$work/window-save.sh"
  timeout 120 xvfb-run -a -s "-screen 0 1280x1024x24" "$work/window-save.sh" >"$work/window-save.out" 2>&1
  sed 's/^/   /' "$work/window-save.out"
  grep -q "dialog 'Cannot Save Scene'" "$work/window-save.out" &&
    grep -q "saved on a full disk.*title 'room.json\*" "$work/window-save.out" &&
    holds "the save failed with a dialog and the title kept its *" ||
    broken "no dialog, or the title lost its *"
  grep -q "quit: asked 'Unsaved Changes'" "$work/window-save.out" &&
    grep -q "still running after Cancel" "$work/window-save.out" &&
    holds "Ctrl+Q asked about the unsaved changes" || broken "Ctrl+Q did not ask"
  grep -q "saved with room: title 'room.json —" "$work/window-save.out" &&
    "$cli" validate "$disk/room.json" >/dev/null 2>&1 &&
    ! cmp -s "$disk/room.json" "$work/room-before.json" &&
    holds "with room again the save went through whole" || broken "the save with room failed"
  rm -f "$disk"/*
fi

# --- a file cut short while it loads ---
begin "carom-cli validate on a 300,000-ball file truncated to 1,000 bytes while it loads"
write_gas "$work/gas.json" 300000
said "the file: $(stat -c %s "$work/gas.json") bytes"
for delay in 0 0.02 0.1 0.4; do
  cp "$work/gas.json" "$work/shrinking.json"
  "$cli" validate "$work/shrinking.json" >"$work/out" 2>"$work/err" &
  pid=$!
  sleep "$delay"
  truncate -s 1000 "$work/shrinking.json"
  wait $pid
  code=$?
  said "cut after ${delay} s: $(describe_exit $code): $(cat "$work/out" "$work/err" | head -c 200 | tr '\n' ' ')"
  [ $code -le 2 ] && holds "answered" || broken "crashed"
done

# --- an output that is the input ---
begin "carom-cli run x.json --trajectory x.json, and through a symbolic link"
cp "$room" "$work/x.json"
ln -s "$work/x.json" "$work/link.json"
for output in "$work/x.json" "$work/link.json"; do
  "$cli" run "$work/x.json" --duration 0.1 --trajectory "$output" >/dev/null 2>"$work/err"
  code=$?
  said "--trajectory $(basename "$output"): $(describe_exit $code): $(cat "$work/err")"
  [ $code -eq 2 ] && cmp -s "$work/x.json" "$room" && holds "refused, the scene untouched" ||
    broken "the scene was overwritten or the run not refused"
done

# --- file names in Latin-1 bytes ---
begin "file names in Latin-1 bytes: lat\\351.json"
latin=$(printf 'lat\351.json')
trajectory=$(printf 'tr\351.csv')
shot=$(printf 'shot\351.png')
cp "$room" "$work/$latin"
"$cli" validate "$work/$latin" >"$work/out" 2>&1
said "validate: $(cat "$work/out")"
[ "$(cat "$work/out")" = ok ] && holds "read by the bytes given" || broken "not found"
"$cli" run "$work/$latin" --duration 0.1 --trajectory "$work/$trajectory" >/dev/null 2>&1
[ -f "$work/$trajectory" ] && holds "trajectory written under the bytes given" ||
  broken "trajectory not written under its name: $(ls "$work" | tr '\n' ' ')"
cat >"$work/window-latin1.sh" <<EOF
#!/usr/bin/env bash
set -u
export HOME="$work/home" PULSE_SERVER=unix:/nonexistent/carom-faults
"$window" "$work/$latin" >"$work/window.log" 2>&1 &
pid=\$!
for i in \$(seq 100); do id=\$(xdotool search --name '^lat' 2>/dev/null | head -1); [ -n "\$id" ] && break; sleep 0.2; done
[ -n "\$id" ] || { echo "no window titled lat..."; kill \$pid; exit 1; }
sleep 1
refused=\$(xdotool search --name 'Cannot' 2>/dev/null | head -1)
echo "opened: \$([ -n "\$refused" ] && echo 'a dialog says it cannot' || echo 'no dialog')"
xdotool windowfocus --sync "\$id"
xdotool key ctrl+a; sleep 0.3; xdotool key Delete; sleep 0.3; xdotool key ctrl+s; sleep 1
kill \$pid; wait \$pid 2>/dev/null
EOF
chmod +x "$work/window-latin1.sh"
timeout 120 xvfb-run -a -s "-screen 0 1280x1024x24" "$work/window-latin1.sh" >"$work/out" 2>&1
sed 's/^/   carom: /' "$work/out"
grep -q "opened: no dialog" "$work/out" && ! cmp -s "$work/$latin" "$room" &&
  "$cli" validate "$work/$latin" >/dev/null 2>&1 &&
  holds "the window opened it and saved the edit under the bytes given" ||
  broken "the window could not open or save it"
PULSE_SERVER=unix:/nonexistent/carom-faults HOME="$work/home" timeout 60 \
  xvfb-run -a -s "-screen 0 1280x1024x24" "$window" --screenshot "$work/$shot" >"$work/out" 2>&1
code=$?
said "carom --screenshot shot\\351.png: $(describe_exit $code)"
[ $code -eq 0 ] && [ -s "$work/$shot" ] && holds "the picture saved under the bytes given" ||
  broken "the picture was not saved: $(tail -n 3 "$work/out")"

# --- a memory limit ---
begin "carom-cli validate under ulimit -v 1000000 on a 5,000,000-ball file"
write_gas "$work/five-million.json" 5000000
said "the file: $(stat -c %s "$work/five-million.json") bytes"
start=$(date +%s%N)
(ulimit -v 1000000; "$cli" validate "$work/five-million.json") >"$work/out" 2>"$work/err"
code=$?
said "$(describe_exit $code) after $((($(date +%s%N) - start) / 1000000)) ms: $(cat "$work/err")"
[ $code -eq 2 ] && grep -q "must have at most 1000000" "$work/err" && holds "refused by count" ||
  broken "not refused with a message"
rm -f "$work/five-million.json"

# --- the sound server killed and restarted ---
begin "the window's sound: PulseAudio killed 10 s into a run and restarted 8 s later (--bench-stress 30)"
cat >"$work/audio.sh" <<EOF
#!/usr/bin/env bash
set -u
export HOME="$work/home"
"$window" --bench-stress 30 >"$work/stress.report" 2>"$work/stress.err" & carom=\$!
sleep 10; "\$CAROM_PULSE_CONTROL" --kill "\$CAROM_PULSE_DIR"
sleep 8; "\$CAROM_PULSE_CONTROL" --start "\$CAROM_PULSE_DIR"
sleep 1
parec -d ci.monitor --format=s16le --rate=8000 --channels=1 --raw >"$work/after.raw" & rec=\$!
wait \$carom; echo "carom exit \$?"
kill \$rec 2>/dev/null; wait \$rec 2>/dev/null
EOF
chmod +x "$work/audio.sh"
timeout 120 xvfb-run -a -s "-screen 0 1920x1200x24" scripts/with-pulseaudio.sh "$work/audio.sh" \
  >"$work/audio.out" 2>&1
grep -E "^stress:|sound lost|sound back|^sounds:" "$work/stress.report" | sed 's/^/   carom: /'
sed 's/^/   /' "$work/audio.out"
peak=$(python3 -c 'import array, sys; d = open(sys.argv[1], "rb").read(); s = array.array("h", d[: len(d) // 2 * 2]); print(max(map(abs, s), default=0))' "$work/after.raw" 2>/dev/null || echo 0)
said "loudest sample recorded after the restart: $peak of 32767"
grep -q "carom exit 0" "$work/audio.out" && holds "the window ran on and ended normally" ||
  broken "the window did not end normally"
grep -q "sound lost at" "$work/stress.report" && holds "the loss was noticed" ||
  broken "the loss went unnoticed"
grep -q "sound back at" "$work/stress.report" && [ "$peak" -gt 327 ] &&
  holds "sound came back and was heard" || broken "sound did not come back"

echo
if [ $failures -eq 0 ]; then
  echo "faults: every case held"
else
  echo "faults: $failures check(s) failed"
fi
[ $failures -eq 0 ]
