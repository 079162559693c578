#!/usr/bin/env bash
# Renders the PNG sizes of the hicolor theme from resources/icons/io.github.carom_sim.Carom.svg
# into resources/icons/NxN/. Run after changing the SVG and commit the PNGs: rendered once here
# rather than at build time, so that neither the build nor CI needs librsvg, and the window
# program embeds the same files. Needs rsvg-convert (Debian: librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")/../resources/icons"
id=io.github.carom_sim.Carom
for size in 16 24 32 48 64 128 256; do
  mkdir -p "${size}x${size}"
  rsvg-convert -w "$size" -h "$size" "$id.svg" -o "${size}x${size}/$id.png"
done
