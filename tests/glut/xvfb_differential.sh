#!/bin/sh
# A differential test of textbook GLUT programs (programs/spin_menu.c, drag_teapot.c,
# timer_window.c, key_repeat.c): the same real X input (xdotool: keys, held keys, drags with
# modifiers, a right-button menu with submenus) to the program built against glass and against
# freeglut 3.4 with Mesa (llvmpipe), under Xvfb without a window manager. The program prints every callback's arguments and what
# glutGet says; this script adds the window's title and geometry as X sees them (driver.txt) and
# takes a screenshot of the window (xwd) at fixed points. Every step waits for the program's line
# that says the step was handled, and the animation moves by timer ticks and idle calls counted
# to a target, never by wall time, so the logs are the same from run to run.
#
#   xvfb_differential.sh BIN_DIR WORK_DIR CASE [EXPECTED_DIR]   (inside xvfb-run, 800x600x24)
#
# BIN_DIR holds glut_CASE. Without EXPECTED_DIR it only runs (tools/record-glut-references.sh
# records freeglut's run so); with it, out.txt and driver.txt must equal the expected ones line by
# line (freeglut's log with a line repeated at once kept once: the recording script says why),
# and each screenshot must match the expected one within the tolerance below.
set -eu
bin=$1
work=$2
case=$3
expected=${4:-}
. "$(dirname "$0")/xvfb_common.sh"

# Pictures: glass and Mesa rasterize and light the same calls a little differently (the last bit
# of a colour where lighting is computed per vertex in floats, and pixels on an edge that falls
# exactly between two pixel centres: Mesa's llvmpipe snaps vertices to 8 sub-pixel bits too, but
# rounds some of them the other way), so a pixel counts as different only when a channel is off
# by more than 8% (about 20/255), and at most 0.5% of the window's pixels may be. The bitmap text
# is masked out before comparing (glass draws its own glyphs, freeglut the X server's fonts; both
# put them in the same places), as is nothing else.
fuzz=8%
max_share_per_mille=5

program="$bin/glut_$case"
[ -x "$program" ] || fail "no program $program"

mark=0
since_mark() { tail -n "+$((mark + 1))" out.txt | grep -q -- "$1"; }
# Sends the rest of the arguments to xdotool and waits for a line of the program matching $1.
act() {
  pattern=$1
  shift
  mark=$(wc -l <out.txt)
  xdotool "$@"
  await since_mark "$pattern"
}
note() { echo "$*" >>driver.txt; }
geometry() {
  note "title: $(xdotool getwindowname "$window")"
  note "geometry: $(xdotool getwindowgeometry "$window" |
    sed -n 's/.*Position: \([-0-9]*,[-0-9]*\).*/\1/p; s/.*Geometry: //p' | tr '\n' ' ')"
}
# Pictures without the time they were made, so that recording again gives the same files.
png_options="-strip -define png:exclude-chunks=date,time"
# A screenshot of the window once it has stopped changing (the last display may still be on
# its way to the screen when its line is printed): shot_NAME.png.
shot() {
  xwd -id "$window" -silent | convert xwd:- $png_options "png:shot_$1.png"
  tries=0
  while :; do
    sleep 0.2
    xwd -id "$window" -silent | convert xwd:- $png_options png:again.png
    if [ "$(compare -metric AE "shot_$1.png" again.png null: 2>&1 || true)" = 0 ]; then break; fi
    mv again.png "shot_$1.png"
    tries=$((tries + 1))
    [ "$tries" -lt 25 ] || fail "the window did not settle for shot $1"
  done
  [ -z "$masks" ] || echo "$masks" >"mask_$1.txt"
  note "shot $1"
}
# Opens the right-button menu with a click at (x, y) of the window, moves the pointer through the
# points given (x y x y ...; a submenu opens when the pointer rests on its entry) and clicks the
# left button at the last. (Not a drag from the press to the entry, released there: freeglut 3.4
# on X11 gets that release in the program's window, where it finds the entry from the pointer's
# position in the window as if it were the position on the screen, and for a submenu's entry
# looks at the main menu's highlighted entry, the submenu's, and chooses nothing.)
menu_pick() {
  mark=$(wc -l <out.txt)
  xdotool mousemove --window "$window" "$1" "$2" click 3
  await since_mark "menu status 1"
  shift 2
  while [ $# -ge 2 ]; do
    xdotool mousemove --window "$window" "$1" "$2"
    sleep 0.3
    shift 2
  done
  xdotool click 1
}

unset SDL_VIDEODRIVER
: >driver.txt
"$program" >out.txt 2>err.txt &
pid=$!
await grep -q "^display" out.txt
window=$(xdotool search --sync --name "^$(echo "$case" | tr _ ' ')" | head -n 1)
[ -n "$window" ] || fail "no window of $case"
xdotool windowfocus --sync "$window"

case $case in
  spin_menu)
    # Text-free pictures: nothing to mask.
    masks=""
    geometry
    shot start
    act "idle stopped at 90" key s
    await since_mark "display angle 90"
    shot spun
    # Colour > Green: the main menu at (30, 30), entries 24 pixels tall from y 32; the colour
    # submenu opens beside the "Colour" entry, its "Green" 24 pixels below.
    menu_pick 30 30  60 68  150 68  150 92
    await since_mark "display angle 90 colour 11"
    shot green
    # Shape > Teapot.
    menu_pick 30 30  60 92  150 92  150 116
    await since_mark "display angle 90 colour 11 shape 21"
    shot teapot
    # Wireframe (the label becomes "Solid"), then Spin, from the menu.
    menu_pick 30 30  60 116
    await since_mark "wire 1"
    shot wire
    menu_pick 30 30  60 44
    await since_mark "idle stopped at 180"
    await since_mark "display angle 180"
    shot menu_spin
    # Opened and let go outside it: nothing chosen.
    menu_pick 30 30  250 200
    await since_mark "menu status 0"
    act "key s" key s
    await since_mark "display angle 270"
    shot spun_again
    ;;
  drag_teapot)
    # The overlay's line of text, at the bottom left.
    masks="0,245 359,269"
    geometry
    shot start
    xdotool mousemove --window "$window" 100 100
    act "mouse 0 0 at 100 100 modifiers 0" mousedown 1
    act "motion 130 110" mousemove --window "$window" 130 110
    act "display rot 45 30" mousemove --window "$window" 160 125
    act "mouse 0 1 at 160 125 modifiers 0" mouseup 1
    shot dragged
    # Shift+drag: nearer and farther.
    act "mouse 0 0 at 160 125 modifiers 1" keydown shift mousedown 1
    act "display rot 45 30 distance 75" mousemove --window "$window" 160 140
    act "mouse 0 1 at 160 140 modifiers 1" mouseup 1 keyup shift
    shot zoomed
    act "special 100 at" key Left
    act "special 101 at" key Up
    act "special 104 at" key Page_Up
    act "modifiers 2" key ctrl+Down
    await since_mark "display"
    shot keys
    act "modifiers 4" key alt+Right
    act "special 1 at" key F1
    await since_mark "display rot 20 -30 distance 60"
    act "special 106 at" key Home
    await since_mark "display"
    masks=""
    shot reset_no_text
    # A middle click with Ctrl: the mouse callback, no drag.
    act "mouse 1 1" keydown ctrl click 2 keyup ctrl
    ;;
  timer_window)
    # The overlay's line of text, at the bottom left.
    masks="0,170 200,199"
    await grep -q "display tick 12" out.txt
    act "glutGet position" key g
    geometry
    shot ticked
    act "display" key c
    act "position 60 50" key p
    act "glutGet position" key g
    geometry
    act "reshape 400 300" key r
    await since_mark "display"
    masks="0,270 200,299"
    act "glutGet position" key g
    geometry
    shot reshaped
    act "timer 12" key t
    await since_mark "display tick 12"
    geometry
    # Full screen from the screen's corner: freeglut 3.4 on X11 without a window manager moves
    # the window to minus its position (where a window manager's frame would be), so only from
    # (0, 0) does its window cover the screen, as GLUT 3.7 (4.9) says a full-screen window does.
    act "position 0 0" key o
    act "reshape 800 600" key f
    await since_mark "display"
    masks="0,570 200,599"
    act "glutGet position" key g
    geometry
    shot full_screen
    ;;
  key_repeat)
    # Held for 1.2 s: X's auto-repeat starts after 660 ms and repeats 25 times a second.
    hold() {
      xdotool keydown "$1"
      sleep 1.2
      xdotool keyup "$1"
    }
    masks=""
    await grep -q "^display 2" out.txt
    act "ignore key repeat" key g
    hold a
    hold Left
    act "counted" key p
    act "ignore key repeat 1" key i
    hold b
    act "counted" key p
    act "ignore key repeat 0" key i
    act "key repeat 0" key r
    hold c
    act "counted" key p
    act "key repeat 1" key R
    hold d
    act "counted" key p
    geometry
    shot end
    ;;
  *) fail "no case $case" ;;
esac

xdotool key q
status=0
wait "$pid" || status=$?
[ "$status" -eq 0 ] || fail "the program exited with $status"
[ -n "$expected" ] || exit 0

failures=0
for log in out.txt driver.txt; do
  if ! diff -u "$expected/$log" "$log" >"diff_$log"; then
    cat "diff_$log" >&2
    echo "FAIL: $log differs from freeglut's" >&2
    failures=$((failures + 1))
  fi
done
for picture in "$expected"/shot_*.png; do
  name=$(basename "$picture")
  [ -f "$name" ] || { echo "FAIL: no $name" >&2; failures=$((failures + 1)); continue; }
  size=$(identify -format "%wx%h" "$name")
  [ "$size" = "$(identify -format "%wx%h" "$picture")" ] || {
    echo "FAIL: $name is $size, freeglut's $(identify -format "%wx%h" "$picture")" >&2
    failures=$((failures + 1))
    continue
  }
  # The shot's mask (shot_NAME.png's in mask_NAME.txt) beside the expected picture.
  mask="$expected/mask_${name#shot_}"
  mask="${mask%.png}.txt"
  draw=""
  [ ! -s "$mask" ] || draw="rectangle $(cat "$mask")"
  if [ -n "$draw" ]; then
    convert "$name" -fill black -draw "$draw" masked_glass.png
    convert "$picture" -fill black -draw "$draw" masked_freeglut.png
  else
    cp "$name" masked_glass.png
    cp "$picture" masked_freeglut.png
  fi
  off=$(compare -metric AE -fuzz "$fuzz" masked_glass.png masked_freeglut.png "diff_$name" 2>&1 ||
    true)
  psnr=$(compare -metric PSNR masked_glass.png masked_freeglut.png null: 2>&1 || true)
  pixels=$(identify -format "%[fx:w*h]" "$name")
  echo "$name: $off of $pixels pixels off by more than $fuzz, PSNR $psnr dB"
  if [ "$((off * 1000))" -gt "$((pixels * max_share_per_mille))" ]; then
    echo "FAIL: $name differs from freeglut's in $off pixels (diff_$name)" >&2
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] || fail "$failures differences from freeglut in $case"
echo "ok: $case's callbacks, window and pictures as with freeglut"
