#!/bin/sh
# The on-screen path: Listing 5 in a real X window (Xvfb), its content captured with xwd and
# compared with the snapshot glass wrote of the same frame and with the off-screen picture; then
# real key presses (xdotool, through the X server and SDL) step the fractal on and Escape ends it.
#   xvfb_window.sh BIN_DIR WORK_DIR     (run inside xvfb-run, which sets DISPLAY)
set -eu
bin=$1
work=$2
. "$(dirname "$0")/xvfb_common.sh"

"$bin/glut_listing5_offscreen" 4 step4.png
"$bin/glut_listing5_offscreen" 5 step5.png
start_listing5_at_step4

screenshot screen_step4.png
"$bin/glut_png_probe" snapshot.png same step4.png || fail "the snapshot is not step 4"
"$bin/glut_png_probe" screen_step4.png same snapshot.png || fail "the screen differs from the snapshot"

xdotool windowfocus --sync "$window"
xdotool key space
await sh -c "xwd -id $window -silent | convert xwd:- png:screen_step5.png && \
  '$bin/glut_png_probe' screen_step5.png same step5.png"

xdotool key Escape
status=0
wait "$pid" || status=$?
[ "$status" -eq 1 ] || fail "Escape: the program exited with $status, not 1 (exit(1) in Listing 5)"
echo "ok: the window showed steps 4 and 5 as glass draws them off-screen"
