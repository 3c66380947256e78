#!/bin/sh
# Real X input (xdotool under Xvfb) to a GLUT program that logs its callbacks
# (programs/event_log.c); the log must be the one the same program writes on freeglut for the
# same events (expected/event_log.txt, recorded with freeglut 3.4 under Xvfb without a window
# manager, by this script with BIN_DIR holding the program built against freeglut). It checks
# the first reshape before visibility and display, the modifiers of modifier keys (the state
# before the event), Caps Lock as Shift, the character of a key's release, the keypad's keys
# with Num Lock off, Ctrl with symbols, the vertical wheel to
# the wheel callback and the horizontal one to the mouse callback, and a move the program asks
# for: its position callback, and the pointer's coordinates in the moved window.
#   xvfb_events.sh BIN_DIR WORK_DIR EXPECTED     (run inside xvfb-run, which sets DISPLAY)
set -eu
bin=$1
work=$2
expected=$3
. "$(dirname "$0")/xvfb_common.sh"

unset SDL_VIDEODRIVER
"$bin/glut_event_log" >out.txt 2>err.txt &
pid=$!
await grep -q "display 1" out.txt
window=$(xdotool search --sync --name "^event log$" | head -n 1)
[ -n "$window" ] || fail "no window named event log"
xdotool windowfocus --sync "$window"
xdotool mousemove --window "$window" 50 60
await grep -q "passive motion 50 60" out.txt
xdotool key a
xdotool key shift+b
xdotool key F1 Left
xdotool mousedown 1
xdotool mousemove --window "$window" 70 80
await grep -q "motion 70 80" out.txt
xdotool mouseup 1
xdotool click 3
xdotool click 4 click 5 click 6 click 7
xdotool keydown ctrl click 1
xdotool keyup ctrl
xdotool key ctrl+g
xdotool keydown ctrl keydown g keyup ctrl keyup g
xdotool keydown shift keydown 1 keyup shift keyup 1
xdotool key alt+x
xdotool key Caps_Lock c shift+c Caps_Lock
xdotool key Escape Return BackSpace Tab Delete
# The keypad with Num Lock off: arrows, Home, End, Page Up, Page Down, Insert, Delete, Begin.
xdotool key KP_Up KP_Down KP_Left KP_Right KP_Home KP_End KP_Prior KP_Next KP_Insert KP_Delete KP_Begin
# Ctrl with symbols, as XLookupString maps them (27, 0, 0, 127, 31), and Ctrl+1 once.
xdotool key ctrl+bracketleft ctrl+space ctrl+2 ctrl+8 ctrl+slash ctrl+1
# The window moved by the program under the pointer: a key now reports it 30, 40 nearer.
xdotool key m
await grep -q "position 30 40" out.txt
xdotool key a
xdotool key q
status=0
wait "$pid" || status=$?
[ "$status" -eq 0 ] || fail "the program exited with $status"
if ! diff -u "$expected" out.txt >diff.txt; then
  cat diff.txt >&2
  fail "the callbacks differ from freeglut's"
fi
echo "ok: $(wc -l <out.txt) callbacks as freeglut makes them"
