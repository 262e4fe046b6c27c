#!/usr/bin/env bash
# Starts the real desktop app under Xvfb, takes a screenshot of the screen and checks that
# it is not blank (a blank or single-colour image has very few colours). Then measures
# the frame rate with 1,000 colliding balls (software rendering, as on a server).
# Needs: xvfb, the Mesa GL drivers, imagemagick (installed by .ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/screenshot.png}
app=
xvfb=
log=
cleanup() { [ -z "$app" ] || kill "$app" 2>/dev/null || true; [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true; [ -z "$log" ] || rm -f "$log"; }
trap cleanup EXIT
# shellcheck source=scripts/xvfb.sh
. scripts/xvfb.sh
start_xvfb :97
log=$(mktemp)
# Starts the app and gives it six seconds to draw; says so if it has exited by then.
start_app() {
    target/release/newtonlab app example:marble-run --play >"$log" 2>&1 &
    app=$!
    sleep 6
    kill -0 "$app" 2>/dev/null
}
# One retry: a CI run once lost the app within six seconds of a fresh Xvfb with nothing in
# the log to show for it (the output went to /dev/null then). The log is printed either
# way, so a real crash shows its message and fails on the second try.
if ! start_app; then
    wait "$app" && status=0 || status=$?
    echo "the app exited before the screenshot (exit status $status); its output:"
    cat "$log"
    app=
    start_app || {
        wait "$app" && status=0 || status=$?
        echo "the app exited again (exit status $status); its output:"
        cat "$log"
        app=
        exit 1
    }
fi
import -window root "$out"
colours=$(convert "$out" -format %k info:)
echo "screenshot $out: $colours colours"
if [ "$colours" -lt 64 ]; then
    echo "the screenshot looks blank"
    exit 1
fi
kill "$app"
app=
timeout 120 target/release/newtonlab app example:ball-pit --measure-frames 300
# Drawing at scale: the same pit with trails on, and a 60 x 60 cloth (3,600 particles,
# 7,080 springs). Figures for the log, not a pass mark: the machine is shared.
scenes=$(mktemp -d)
# As a teacher's second run finds it: the Getting started window closed.
echo "welcomed = true" >"$scenes/settings.toml"
export NEWTONLAB_DATA_DIR=$scenes
target/release/newtonlab run example:ball-pit --until 0 --save-state "$scenes/pit-trails.toml" >/dev/null
sed -i 's/^\[view\]$/[view]\ntrails = true/' "$scenes/pit-trails.toml"
python3 benches/scenes/cloth.py 60 >"$scenes/cloth-60.toml"
timeout 120 target/release/newtonlab app "$scenes/pit-trails.toml" --measure-frames 300
timeout 120 target/release/newtonlab app "$scenes/cloth-60.toml" --measure-frames 300
rm -rf "$scenes"
