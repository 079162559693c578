#!/usr/bin/env bash
# Installs the Debian 12 packages Carom needs to build and test; installs nothing already present.
set -euo pipefail
packages=(cmake ninja-build g++ qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-tools-dev qt6-l10n-tools qt6-translations-l10n
  qt6-tools-dev-tools libeigen3-dev
  qt6-multimedia-dev pulseaudio pulseaudio-utils xvfb xauth xdotool libgl1-mesa-dri libglx-mesa0
  clang libclang-rt-14-dev libtsan2 python3 ffmpeg
  dpkg-dev desktop-file-utils appstream shared-mime-info xdg-utils libglib2.0-bin groff-base man-db)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
