#!/usr/bin/env bash
# Runs COMMAND with a private PulseAudio server whose default sink is a null sink named "ci",
# so sound tests have an output (and its monitor, ci.monitor, to record) with no sound card,
# no user session and no stdin, as root in CI too. Exits with COMMAND's code.
# Usage: scripts/with-pulseaudio.sh COMMAND [ARG...]
#        scripts/with-pulseaudio.sh --kill|--start DIR
# COMMAND finds the server's folder in CAROM_PULSE_DIR and this script in CAROM_PULSE_CONTROL.
# `--kill DIR` kills that server outright (SIGKILL, as a crash would) and `--start DIR` starts
# it again on the same socket with the same null sink: a test can take its own server away and
# bring it back without touching any other PulseAudio on the machine.
set -euo pipefail
if [ $# -eq 0 ]; then
  echo "usage: $0 COMMAND [ARG...] | --kill DIR | --start DIR" >&2
  exit 2
fi
for tool in pulseaudio pactl; do
  command -v "$tool" >/dev/null || { echo "$0: $tool not found (scripts/setup-debian.sh)" >&2; exit 2; }
done

# The server's pid is kept in DIR/pulse.pid, so that whoever stops it (this script's exit, the
# watcher below, --kill) stops the one running now, also after a restart.
server_pid() { cat "$1/pulse.pid" 2>/dev/null || true; }
# A killed daemon may stay a zombie for a while (or for good, under a PID 1 that reaps nothing).
alive() {
  [ -r "/proc/$1/stat" ] && [ "$(sed 's/.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" != Z ]
}

# pactl, to the server of folder $dir.
ask() { PULSE_SERVER="unix:$dir/run/native" PULSE_CLIENTCONFIG="$dir/client.conf" pactl "$@"; }

# Starts the server of folder $1 and waits until it answers; fails with its log otherwise.
start_server() {
  local dir=$1 socket=$1/run/native pid
  # The daemon gets its own HOME and runtime dir so it touches no user state and does not clash
  # with a desktop session's server. -n skips default.pa (no hardware probing, no D-Bus);
  # anonymous auth avoids sharing a cookie; no realtime or pid file, which need privileges or a
  # session. As root PulseAudio only warns, unless --system is asked for.
  HOME="$dir/home" XDG_CONFIG_HOME="$dir/home/.config" XDG_RUNTIME_DIR="$dir/run" \
    pulseaudio -n --daemonize=no --system=false --exit-idle-time=-1 --disallow-exit \
    --use-pid-file=no --realtime=no --high-priority=no --log-target=stderr --log-level=error \
    -L "module-native-protocol-unix auth-anonymous=1 socket=$socket" \
    -L "module-null-sink sink_name=ci rate=44100" \
    </dev/null >>"$dir/pulseaudio.log" 2>&1 &
  pid=$!
  disown "$pid"  # its end is no job of this shell's to report ("Killed")
  echo "$pid" >"$dir/pulse.pid"
  for _ in $(seq 100); do
    if ask info >/dev/null 2>&1; then
      ask set-default-sink ci
      ask set-default-source ci.monitor
      return 0
    fi
    alive "$pid" || break
    sleep 0.1
  done
  echo "$0: PulseAudio did not start:" >&2
  cat "$dir/pulseaudio.log" >&2
  return 1
}

# Stops the server of folder $1 with signal $2 and waits until it is gone.
stop_server() {
  local pid
  pid=$(server_pid "$1")
  [ -n "$pid" ] || return 0
  kill "-$2" "$pid" 2>/dev/null || true
  while alive "$pid"; do sleep 0.05; done
  rm -f "$1/pulse.pid"
}

case "$1" in
  --kill | --start)
    if [ $# -ne 2 ] || [ ! -f "$2/client.conf" ]; then
      echo "$0: $1 needs a folder this script made" >&2
      exit 2
    fi
    if [ "$1" = --kill ]; then
      stop_server "$2" KILL
    else
      [ -z "$(server_pid "$2")" ] || { echo "$0: the server of $2 is running" >&2; exit 1; }
      start_server "$2"
    fi
    exit 0
    ;;
esac

dir=$(mktemp -d "${TMPDIR:-/tmp}/carom-pulse.XXXXXX")
watch_pid=""
cleanup() {
  if [ -n "$watch_pid" ]; then
    kill "$watch_pid" 2>/dev/null || true
    wait "$watch_pid" 2>/dev/null || true
  fi
  stop_server "$dir" TERM
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

mkdir -m 700 "$dir/home" "$dir/run"
# Clients never start a server of their own, whatever the user's setup says.
printf 'autospawn = no\n' >"$dir/client.conf"
start_server "$dir"
# The daemon never exits on its own (--exit-idle-time=-1): if this script is killed outright
# (a test timeout), this watcher still takes the daemon down with it, restarted or not.
wrapper_pid=$$
(
  while kill -0 "$wrapper_pid" 2>/dev/null; do sleep 1; done
  pid=$(server_pid "$dir")
  [ -z "$pid" ] || kill "$pid" 2>/dev/null
) </dev/null >/dev/null 2>&1 &
watch_pid=$!

export PULSE_SERVER="unix:$dir/run/native"
export PULSE_CLIENTCONFIG="$dir/client.conf"
export CAROM_PULSE_DIR="$dir"
CAROM_PULSE_CONTROL="$(cd "$(dirname "$0")" && pwd)/$(basename "$0")"
export CAROM_PULSE_CONTROL

status=0
"$@" </dev/null || status=$?
exit "$status"
