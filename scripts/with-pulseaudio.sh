#!/usr/bin/env bash
# Runs COMMAND with a private PulseAudio server whose default sink is a null sink named "ci",
# so sound tests have an output (and its monitor, ci.monitor, to record) with no sound card,
# no user session and no stdin, as root in CI too. Exits with COMMAND's code.
# Usage: scripts/with-pulseaudio.sh COMMAND [ARG...]
set -euo pipefail
if [ $# -eq 0 ]; then
  echo "usage: $0 COMMAND [ARG...]" >&2
  exit 2
fi
for tool in pulseaudio pactl; do
  command -v "$tool" >/dev/null || { echo "$0: $tool not found (scripts/setup-debian.sh)" >&2; exit 2; }
done

dir=$(mktemp -d "${TMPDIR:-/tmp}/carom-pulse.XXXXXX")
pulse_pid=""
watch_pid=""
cleanup() {
  if [ -n "$watch_pid" ]; then
    kill "$watch_pid" 2>/dev/null || true
    wait "$watch_pid" 2>/dev/null || true
  fi
  if [ -n "$pulse_pid" ]; then
    kill "$pulse_pid" 2>/dev/null || true
    wait "$pulse_pid" 2>/dev/null || true
  fi
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

mkdir -m 700 "$dir/home" "$dir/run"
socket="$dir/run/native"
# Clients never start a server of their own, whatever the user's setup says.
printf 'autospawn = no\n' >"$dir/client.conf"

# The daemon gets its own HOME and runtime dir so it touches no user state and does not clash
# with a desktop session's server. -n skips default.pa (no hardware probing, no D-Bus);
# anonymous auth avoids sharing a cookie; no realtime or pid file, which need privileges or a
# session. As root PulseAudio only warns, unless --system is asked for.
HOME="$dir/home" XDG_CONFIG_HOME="$dir/home/.config" XDG_RUNTIME_DIR="$dir/run" \
  pulseaudio -n --daemonize=no --system=false --exit-idle-time=-1 --disallow-exit \
  --use-pid-file=no --realtime=no --high-priority=no --log-target=stderr --log-level=error \
  -L "module-native-protocol-unix auth-anonymous=1 socket=$socket" \
  -L "module-null-sink sink_name=ci rate=44100" \
  </dev/null 2>"$dir/pulseaudio.log" &
pulse_pid=$!
# The daemon never exits on its own (--exit-idle-time=-1): if this script is killed outright
# (a test timeout), this watcher still takes the daemon down with it.
wrapper_pid=$$
(
  while kill -0 "$wrapper_pid" 2>/dev/null; do sleep 1; done
  kill "$pulse_pid" 2>/dev/null
) </dev/null >/dev/null 2>&1 &
watch_pid=$!

export PULSE_SERVER="unix:$socket"
export PULSE_CLIENTCONFIG="$dir/client.conf"
ready=0
for _ in $(seq 100); do
  if pactl info >/dev/null 2>&1; then ready=1; break; fi
  kill -0 "$pulse_pid" 2>/dev/null || break
  sleep 0.1
done
if [ "$ready" -ne 1 ]; then
  echo "$0: PulseAudio did not start:" >&2
  cat "$dir/pulseaudio.log" >&2
  exit 1
fi
pactl set-default-sink ci
pactl set-default-source ci.monitor

status=0
"$@" </dev/null || status=$?
exit "$status"
