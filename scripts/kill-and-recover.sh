#!/usr/bin/env bash
# The real desktop app under Xvfb loses no work to a kill: it places a particle in an
# open scene (keyboard and a click, with xdotool), is killed with SIGKILL after the
# autosave interval, and the copy in its data directory holds the new particle; started
# again, it offers to recover the work.
# Needs: xvfb, xdotool, the Mesa GL drivers (installed by .ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
data=$(mktemp -d)
app=
log=$data.log
xvfb=
cleanup() { if [ -n "$app" ]; then kill -9 "$app" 2>/dev/null || true; wait "$app" 2>/dev/null || true; fi; [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true; rm -rf "$data" "$log"; }
# On failure, show what the app printed: a bare exit code says nothing on a CI log.
failed() { echo "kill-and-recover failed; the app printed:"; cat "$log" 2>/dev/null; }
trap failed ERR
trap cleanup EXIT
# shellcheck source=scripts/xvfb.sh
. scripts/xvfb.sh
start_xvfb :96
export NEWTONLAB_DATA_DIR=$data
target/release/newtonlab app example:collision >"$log" 2>&1 &
app=$!
sleep 4
xdotool mousemove 97 37 click 1     # the Particle tool (no window manager: no key focus)
sleep 0.5
xdotool mousemove 620 300 click 1   # place a particle
sleep 7                             # longer than the autosave interval (5 s)
kill -9 "$app"
wait "$app" 2>/dev/null || true     # reaps it quietly: no "Killed" line from bash
app=
count=$(grep -c '^\[\[particle\]\]' "$data/autosave.toml" || true)
echo "after SIGKILL the autosave holds $count particles"
test "$count" -eq 3
# Started again, the app must stay up with the recovery prompt. An early exit is shown
# with what the app printed; it is tried once more only so that one flake of the display
# server (see scripts/xvfb.sh) is told apart from an app that cannot start.
restart() {
    target/release/newtonlab app >"$log" 2>&1 &
    app=$!
    sleep 4
    kill -0 "$app" 2>/dev/null && return 0
    local status=0
    wait "$app" || status=$?
    app=
    echo "the restarted app exited with status $status; it printed:"
    cat "$log"
    return 1
}
restart || { echo "trying once more"; restart; }
test -f "$data/autosave.toml"   # still there until the user answers the prompt
echo "restarted: the recovery prompt is up and the copy is kept"
