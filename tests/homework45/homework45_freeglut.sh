#!/bin/sh
# Homework 4-5's program on glass (its snapshot, headless) against the same source on freeglut and
# Mesa in an X window (run inside xvfb-run, which sets DISPLAY), captured with xwd:
#   homework45_freeglut.sh GLASS_PROGRAM FREEGLUT_PROGRAM GLASS WORK_DIR
# The freeglut window is placed at +0+0 with -geometry: by default freeglut asks for position
# (-1, -1), and with no window manager X puts the window there, one pixel off the screen, so xwd
# then captures only 399 x 299 of it, starting at its pixel (1, 1).
set -eu
glass_program=$1
freeglut_program=$2
glass=$3
work=$4
. "$(dirname "$0")/../shell_test_support.sh"

SDL_VIDEODRIVER=dummy GLASS_GLUT_SNAPSHOT=glass.png "$glass_program" >glass_out.txt 2>&1 ||
  fail "the glass program wrote no snapshot"

"$freeglut_program" -geometry 400x300+0+0 >freeglut_out.txt 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
# Polls (up to 20 s) until the window has been drawn: the capture is no longer one colour.
tries=0
while :; do
  window=$(xdotool search --name "Homework 4-5" 2>/dev/null | head -n 1)
  if [ -n "$window" ] && xwd -id "$window" -silent 2>/dev/null | convert xwd:- png:freeglut.png 2>/dev/null &&
     [ "$(convert freeglut.png -format '%k' info:)" -gt 100 ]; then
    break
  fi
  tries=$((tries + 1))
  [ "$tries" -lt 200 ] || fail "the freeglut program showed no picture"
  sleep 0.1
done
sleep 1  # a second expose may redraw it; take the settled picture
xwd -id "$window" -silent | convert xwd:- png:freeglut.png

# Measured: 71.0 dB, no pixel off by more than 8/255 (the largest difference 2/255).
"$glass" compare glass.png freeglut.png --fail-psnr 60 --fail-percent 0 --diff diff.png ||
  fail "glass's homework45 is not freeglut and Mesa's picture"
echo "ok: homework45 on glass and on freeglut with Mesa draw the same room"
