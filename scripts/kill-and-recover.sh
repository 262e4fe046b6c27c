#!/usr/bin/env bash
# The real desktop app under Xvfb loses no work to a kill: it places a particle in an
# open scene (keyboard and a click, with xdotool), is killed with SIGKILL after the
# autosave interval, and the copy in its data directory holds the new particle; started
# again, it offers to recover the work.
# Needs: xvfb, xdotool, the Mesa GL drivers (installed by .ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
display=:96
data=$(mktemp -d)
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
app=
cleanup() { [ -n "$app" ] && kill -9 "$app" 2>/dev/null; kill "$xvfb" 2>/dev/null; rm -rf "$data"; true; }
trap cleanup EXIT
sleep 1
export DISPLAY=$display NEWTONLAB_DATA_DIR=$data
target/release/newtonlab app example:collision >/dev/null 2>&1 &
app=$!
sleep 4
xdotool mousemove 97 37 click 1     # the Particle tool (no window manager: no key focus)
sleep 0.5
xdotool mousemove 620 300 click 1   # place a particle
sleep 7                             # longer than the autosave interval (5 s)
kill -9 "$app"
app=
count=$(grep -c '^\[\[particle\]\]' "$data/autosave.toml" || true)
echo "after SIGKILL the autosave holds $count particles"
test "$count" -eq 3
target/release/newtonlab app >/dev/null 2>&1 &
app=$!
sleep 4
kill -0 "$app"
test -f "$data/autosave.toml"   # still there until the user answers the prompt
echo "restarted: the recovery prompt is up and the copy is kept"
