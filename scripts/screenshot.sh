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
cleanup() { [ -z "$app" ] || kill "$app" 2>/dev/null || true; [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true; }
trap cleanup EXIT
# shellcheck source=scripts/xvfb.sh
. scripts/xvfb.sh
start_xvfb :97
target/release/newtonlab app example:marble-run --play >/dev/null 2>&1 &
app=$!
sleep 6
kill -0 "$app" || { echo "the app exited before the screenshot"; exit 1; }
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
