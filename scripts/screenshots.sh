#!/usr/bin/env bash
# Takes the screenshots of the README and the user guide of the running program under Xvfb (Mesa's OpenGL).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/screenshots
shoot() {  # shoot NAME SCENE SECONDS
  xvfb-run -a -s "-screen 0 1280x1024x24" ./build/app/carom "$2" --run-for "$3" \
    --screenshot "docs/screenshots/$1.png"
}
shoot magic-room resources/scenes/magic-room.json 3
shoot galton-board resources/scenes/galton-board.json 8
shoot inelastic-pile resources/scenes/inelastic-pile.json 2
shoot staircase resources/scenes/staircase.json 1
shoot marble-run resources/scenes/marble-run.json 2.5
# The Ball story, taken by the GUI test that checks it (two balls of the magic room, 2.5 s in).
shots=$(mktemp -d)
CAROM_SCREENSHOT_DIR="$shots" PULSE_SERVER=unix:/nonexistent/carom-no-audio \
  xvfb-run -a -s "-screen 0 1280x1024x24" ./build/tests/test_story_export screenshotOfTheMagicRoom \
  >/dev/null
cp "$shots/ball-story.png" docs/screenshots/ball-story.png
rm -r "$shots"
