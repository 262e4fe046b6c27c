# Sourced by the scripts that run the real app: starts Xvfb on display $1 and waits until
# it accepts connections. Sets DISPLAY and $xvfb (its pid).
#
# `-noreset`: by default Xvfb resets itself when its last client leaves. A script that
# kills the app and starts it again would then race the reset, and the second app can
# find no display and exit at once. (That flaked CI once: the restarted app was gone
# within four seconds.)
start_xvfb() {
    local display=$1 socket=/tmp/.X11-unix/X${1#:}
    Xvfb "$display" -screen 0 1280x800x24 -noreset >/dev/null 2>&1 &
    xvfb=$!
    export DISPLAY=$display
    # Ready means: the socket is there and, where xdotool is installed (.ci/run installs
    # it), the server answers a request. A socket alone can be a stale one, or the server
    # can still be loading its keymaps.
    for _ in $(seq 100); do
        kill -0 "$xvfb" 2>/dev/null || { echo "Xvfb exited at start on $display"; return 1; }
        if [ -S "$socket" ]; then
            if ! command -v xdotool >/dev/null 2>&1 || xdotool getdisplaygeometry >/dev/null 2>&1; then
                return 0
            fi
        fi
        sleep 0.1
    done
    echo "Xvfb did not start on $display"
    return 1
}
