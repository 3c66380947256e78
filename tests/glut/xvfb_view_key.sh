#!/bin/sh
# Ctrl+Alt+V in a real X window (Xvfb): real key presses (xdotool, through the X server and SDL)
# step Listing 5's window through glass's views; the window's content (xwd) must be the picture
# GLASS_VIEW gives off-screen, the title must name the view, and off again the program's picture
# and title come back. A screenshot of the whole screen is left in WORK_DIR/screen.png.
#   xvfb_view_key.sh BIN_DIR WORK_DIR     (run inside xvfb-run, which sets DISPLAY)
set -eu
bin=$1
work=$2
. "$(dirname "$0")/xvfb_common.sh"

# Whether the window shows the picture of FILE now.
shows() { screenshot shot.png && "$bin/glut_png_probe" shot.png same "$1"; }

titled() { [ "$(xdotool getwindowname "$window")" = "$1" ]; }

"$bin/glut_listing5_offscreen" 4 step4.png
for view in depth overdraw; do
  GLASS_VIEW=$view "$bin/glut_listing5_offscreen" 4 "$view.png" 2>/dev/null
done
start_listing5_at_step4
await shows step4.png
titled "Sierpinski triangle" || fail "title before: $(xdotool getwindowname "$window")"

xdotool windowfocus --sync "$window"
xdotool key ctrl+alt+v
await titled "Sierpinski triangle [glass: depth]"
await shows depth.png
xdotool key ctrl+alt+v
await titled "Sierpinski triangle [glass: overdraw]"
await shows overdraw.png
xwd -root -silent >screen.xwd
convert xwd:screen.xwd png:screen.png

# wireframe, normals, mipmap, then off: the program's title and picture again.
xdotool key ctrl+alt+v ctrl+alt+v ctrl+alt+v ctrl+alt+v
await titled "Sierpinski triangle"
await shows step4.png
# The program saw no key but those of the events file: a space would have drawn step 5.
xdotool key Escape
status=0
wait "$pid" || status=$?
[ "$status" -eq 1 ] || fail "Escape: the program exited with $status, not 1 (exit(1) in Listing 5)"
echo "ok: Ctrl+Alt+V showed depth and overdraw as GLASS_VIEW does, titled, and off again"
