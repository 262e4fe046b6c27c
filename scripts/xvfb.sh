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
    for _ in $(seq 50); do
        [ -S "$socket" ] && return 0
        sleep 0.1
    done
    echo "Xvfb did not start on $display"
    return 1
}
