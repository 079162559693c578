#!/usr/bin/env bash
# Builds the Debian package from an already built tree (BUILD_DIR, default build) with CPack,
# installs it on this machine (with sudo when not root) and checks the installed files as a user
# would meet them: carom-cli runs and validates an installed example, carom answers --version
# with no display and takes a screenshot of an installed example under Xvfb, the desktop entry,
# the metainfo and the MIME type pass their validators, .carom files are of Carom's type and
# open with it, and the man pages render without warnings. The package stays installed.
# Usage: scripts/package.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
app_id=io.github.carom_sim.Carom
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() {
  echo "package: $*" >&2
  exit 1
}

echo "== building the package"
rm -rf "$build/package"
# CPack installs from the tree as it is: `all` is up to date after scripts/build.sh, so this
# rebuilds nothing but checks that.
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$build/package" >"$work/cpack.log" ||
  { cat "$work/cpack.log"; fail "cpack failed"; }
debs=("$build"/package/carom_*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "expected one carom_*.deb in $build/package"
deb=${debs[0]}
echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) KiB"
dpkg-deb --field "$deb" Package Version Section Maintainer Homepage Depends Suggests
version=$(dpkg-deb --field "$deb" Version)
# What dpkg-shlibdeps found, and what it cannot: the Qt, Mesa and translation packages.
depends=$(dpkg-deb --field "$deb" Depends)
for dependency in libqt6widgets6 libqt6multimedia6 libgl1-mesa-dri qt6-translations-l10n; do
  grep -q "\b$dependency\b" <<<"$depends" || fail "Depends lacks $dependency"
done

echo "== installing it"
# --reinstall: a rebuilt package of the same version replaces the one installed before.
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --reinstall \
  --no-install-recommends "$deb" >"$work/apt.log" 2>&1 || { cat "$work/apt.log"; fail "apt-get failed"; }
[ "$(dpkg-query -W -f='${Version}' carom)" = "$version" ] || fail "carom $version is not installed"
desktop=/usr/share/applications/$app_id.desktop
metainfo=/usr/share/metainfo/$app_id.metainfo.xml
mime=/usr/share/mime/packages/carom.xml
scenes=/usr/share/carom/scenes
for file in /usr/bin/carom /usr/bin/carom-cli /usr/libexec/carom/carom-sound "$desktop" "$metainfo" "$mime" \
    /usr/share/icons/hicolor/scalable/apps/$app_id.svg \
    /usr/share/man/man1/carom.1.gz /usr/share/man/man1/carom-cli.1.gz; do
  [ -f "$file" ] || fail "$file was not installed"
done
for size in 16 24 32 48 64 128 256; do
  [ -f "/usr/share/icons/hicolor/${size}x$size/apps/$app_id.png" ] || fail "no ${size}px icon"
done

echo "== carom-cli"
[ "$(/usr/bin/carom-cli --version)" = "carom-cli $version" ] || fail "carom-cli --version"
scene_count=0
for scene in "$scenes"/*.json; do
  [ "$(/usr/bin/carom-cli validate "$scene")" = ok ] || fail "carom-cli validate $scene"
  scene_count=$((scene_count + 1))
done
[ "$scene_count" -ge 5 ] || fail "only $scene_count example scenes in $scenes"
/usr/bin/carom-cli run "$scenes/newtons-cradle.json" --duration 1 --json >"$work/run.json" ||
  fail "carom-cli run"
echo "carom-cli $version: $scene_count installed examples validate, a run works"

echo "== carom"
# A settings and data folder of its own (no saved language, no recovery prompt), and no sound
# server to find, which the program reports and runs on.
export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config" XDG_DATA_HOME="$work/home/.local/share"
mkdir -p "$HOME"
out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM /usr/bin/carom --version) ||
  fail "carom --version without a display"
[ "$out" = "Carom $version" ] || fail "carom --version printed '$out'"
out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM /usr/bin/carom --help) ||
  fail "carom --help without a display"
grep -q -- "--screenshot <file.png>" <<<"$out" || fail "carom --help printed '$out'"
screenshot="$work/galton-board.png"
PULSE_SERVER=unix:/nonexistent/carom-no-audio xvfb-run -a -s "-screen 0 1280x1024x24" \
  /usr/bin/carom "$scenes/galton-board.json" --run-for 1 --screenshot "$screenshot" \
  2>"$work/carom.log" || { cat "$work/carom.log"; fail "carom --screenshot failed"; }
# The window's sound player is found where it was installed (ui/sound_thread.cpp).
! grep -q "no sound: .* not found" "$work/carom.log" || fail "$(cat "$work/carom.log")"
# Non-trivial: a window's size, and more than a blank or one-coloured picture compresses to.
python3 - "$screenshot" <<'EOF' || fail "the screenshot is not a picture of the window"
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
width, height = struct.unpack(">II", data[16:24])
pixels, offset = b"", 8
while offset < len(data):
    length, kind = struct.unpack(">I4s", data[offset:offset + 8])
    if kind == b"IDAT":
        pixels += data[offset + 8:offset + 8 + length]
    offset += 12 + length
levels = len(set(zlib.decompress(pixels)))
print(f"screenshot: {width}x{height}, {len(data) // 1024} KiB, {levels} distinct byte values")
sys.exit(0 if width >= 640 and height >= 400 and len(data) > 20000 and levels > 64 else 1)
EOF

echo "== desktop entry, metainfo, MIME type"
desktop-file-validate "$desktop"
appstreamcli validate --no-net "$metainfo"
# The XML on its own, then as the installed database holds it (dpkg's triggers ran
# update-mime-database and update-desktop-database during the install).
mkdir -p "$work/mime/packages"
cp "$mime" /usr/share/mime/packages/freedesktop.org.xml "$work/mime/packages/"
XDG_DATA_DIRS="$work" update-mime-database "$work/mime" >"$work/mime.log" 2>&1
[ ! -s "$work/mime.log" ] || { cat "$work/mime.log"; fail "update-mime-database complained"; }
[ -f "$work/mime/application/x-carom-scene.xml" ] || fail "update-mime-database dropped the type"
cp "$scenes/magic-room.json" "$work/room.carom"
# As a GNOME file manager asks (GIO reads the shared-mime-info database).
type=$(XDG_CURRENT_DESKTOP=GNOME xdg-mime query filetype "$work/room.carom")
[ "$type" = application/x-carom-scene ] || fail "a .carom file is of type '$type'"
handler=$(xdg-mime query default application/x-carom-scene)
[ "$handler" = "$app_id.desktop" ] || fail ".carom files open with '$handler'"
echo "room.carom: $type, opened by $handler"

echo "== man pages"
for page in carom carom-cli; do
  [ "$(man -w "$page")" = "/usr/share/man/man1/$page.1.gz" ] || fail "man cannot find $page"
  warnings=$(zcat "/usr/share/man/man1/$page.1.gz" | groff -man -Tutf8 -ww -z 2>&1)
  [ -z "$warnings" ] || fail "$page.1: $warnings"
  lines=$(MANWIDTH=80 man -l "/usr/share/man/man1/$page.1.gz" 2>/dev/null | wc -l)
  [ "$lines" -gt 40 ] || fail "$page.1 renders to $lines lines"
  echo "$page(1): $lines lines, no warnings"
done
echo "package: $(basename "$deb") installed and checked"
