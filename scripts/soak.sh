#!/usr/bin/env bash
# A soak: the real app plays a scene under Xvfb for a long time (default the 1,000-ball
# pit for one hour at 30 frames per second), printing the mean frame time of every 1,800
# frames and, each minute, the process's resident memory. Frame time or memory that grows
# from the first lines to the last would show a leak or a slowdown.
#   scripts/soak.sh [SCENE] [FRAMES]        e.g. scripts/soak.sh example:ball-pit 108000
# Needs: xvfb and the Mesa GL drivers (installed by .ci/run); run after a release build.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-example:ball-pit}
frames=${2:-108000}
app=
xvfb=
cleanup() { [ -z "$app" ] || kill "$app" 2>/dev/null || true; [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true; }
trap cleanup EXIT
# shellcheck source=scripts/xvfb.sh
. scripts/xvfb.sh
start_xvfb :95
NEWTONLAB_DATA_DIR=$(mktemp -d) target/release/newtonlab app "$scene" \
    --measure-frames "$frames" --report-every 1800 &
app=$!
start=$(date +%s)
while kill -0 "$app" 2>/dev/null; do
    rss=$(awk '/VmRSS/ {print $2}' "/proc/$app/status" 2>/dev/null || true)
    [ -n "$rss" ] && echo "$(( $(date +%s) - start )) s: resident $(( rss / 1024 )) MiB"
    sleep 60
done
wait "$app"
