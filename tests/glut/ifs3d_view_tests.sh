#!/bin/sh
# `glass ifs3d view`, headless (SDL_VIDEODRIVER=dummy), checked against `glass ifs3d render`:
#   ifs3d_view_tests.sh CASE GLASS PROBE IFS3_FILE WORK_DIR
set -eu
case_name=$1
glass=$2
probe=$3
ifs=$4
work=$5
. "$(dirname "$0")/../shell_test_support.sh"

size=240x240
view() {  # EVENTS-TEXT SNAPSHOT [OPTIONS...]
  printf '%s' "$1" >events.txt
  snapshot=$2
  shift 2
  "$glass" ifs3d view "$ifs" --size $size --points 20000 --snapshot "$snapshot" --events events.txt "$@"
}
render() {  # OUTPUT [OPTIONS...]
  output=$1
  shift
  "$glass" ifs3d render "$ifs" --size $size -o "$output" "$@" >/dev/null
}

case $case_name in
switch)
  # The window starts on the cloud; `a` shows the attractor, which is the picture `glass ifs3d
  # render` makes of the same file off-screen, byte for byte; + and - change its depth as
  # --depth does; b puts the cloud and the attractor side by side; m adds the maps' boxes;
  # c comes back to the cloud.
  render render3.png
  render render4.png --depth 4
  render render2.png --depth 2
  view "snapshot cloud.png
key a
snapshot attractor.png
key +
snapshot depth4.png
key -
key -
snapshot depth2.png
key +
key b
snapshot both.png
key a
key m
snapshot boxes.png
key m
key c
" cloud_again.png
  "$probe" cloud.png size 240 240 || fail "the window is not 240 x 240"
  "$probe" attractor.png same render3.png || fail "key a: the attractor is not glass ifs3d render's picture"
  "$probe" cloud.png differ attractor.png || fail "the cloud looks like the attractor"
  # The cloud's points in map 1's colour (scenes/ifs/homework3.ifs3: 0.9 0.25 0.2, unlit).
  "$probe" cloud.png count 230 64 51 200 57600 || fail "the cloud has too few points of map 1's colour"
  "$probe" depth4.png same render4.png || fail "key +: not the picture of depth 4"
  "$probe" depth2.png same render2.png || fail "key - twice: not the picture of depth 2"
  "$probe" both.png differ attractor.png || fail "key b: the side-by-side view is the attractor alone"
  "$probe" both.png differ cloud.png || fail "key b: the side-by-side view is the cloud alone"
  "$probe" both.png count 230 64 51 100 57600 || fail "key b: no cloud in the side-by-side view"
  "$probe" boxes.png differ attractor.png || fail "key m: no boxes"
  "$probe" cloud_again.png same cloud.png || fail "key c: the cloud does not come back as it was"
  ;;
trackball)
  # Seen level (elevation 0), a drag from the centre to the right by half the ball's radius
  # turns the fractal by 30 degrees about the vertical axis, bringing its right side to the
  # front: what the camera sees from 30 degrees further left (azimuth 35 - 30), light included,
  # since the light stays with the viewer. Measured: the same bytes, though the two reach it by
  # other matrices (a turn on the stack, another eye); required: 40 dB (5 degrees off gives
  # 21 dB, the turn the wrong way 17 dB). `r` turns it back exactly.
  render level.png --view 35,0
  render turned.png --view 5,0
  view "key a
snapshot start.png
mouse left down 120 120
motion 150 120
motion 180 120
mouse left up 180 120
snapshot dragged.png
key r
" reset.png --view 35,0
  "$probe" start.png same level.png || fail "the level view is not glass ifs3d render's picture"
  "$probe" dragged.png differ start.png || fail "the drag did not turn the fractal"
  "$glass" compare dragged.png turned.png --fail-psnr 40 --fail-percent 0.5 ||
    fail "a drag of half the radius to the right is not a turn of 30 degrees about the vertical"
  "$probe" reset.png same level.png || fail "key r does not bring back the first orientation"
  ;;
errors)
  # A file that cannot be read, a bad option, and the attractor asked for without maps.
  status=0
  "$glass" ifs3d view missing.ifs3 --snapshot x.png 2>err.txt || status=$?
  [ "$status" -eq 1 ] || fail "a missing .ifs3 file: status $status, not 1"
  grep -q "cannot read missing.ifs3" err.txt || fail "a missing .ifs3 file is not named"
  status=0
  "$glass" ifs3d view "$ifs" --show sideways 2>err.txt || status=$?
  [ "$status" -eq 2 ] || fail "--show sideways: status $status, not 2"
  printf '0 0 0\n1 1 1\n0.5 0.5 x\n' >bad_cloud.txt
  status=0
  "$glass" ifs3d view bad_cloud.txt --snapshot x.png 2>err.txt || status=$?
  [ "$status" -eq 1 ] || fail "a bad cloud: status $status, not 1"
  grep -q "^bad_cloud.txt:3:" err.txt || fail "the bad cloud line is not named as file:line"
  "$glass" ifs3d points "$ifs" -n 3000 -o cloud.txt >/dev/null
  status=0
  "$glass" ifs3d view cloud.txt --show attractor 2>err.txt || status=$?
  [ "$status" -eq 2 ] || fail "--show attractor without maps: status $status, not 2"
  # A cloud alone is shown; `a` says there are no maps and the cloud stays.
  printf 'key a\n' >events.txt
  "$glass" ifs3d view cloud.txt --size $size --snapshot alone.png --events events.txt 2>err.txt ||
    fail "a cloud alone cannot be shown"
  grep -q "no maps" err.txt || fail "key a without maps says nothing"
  # Without maps the cloud is coloured by height, never in one colour.
  "$probe" alone.png count 217 217 204 0 0 || fail "the cloud alone is drawn in the old single colour"
  printf 'key h\n' >events.txt
  "$glass" ifs3d view cloud.txt --size $size --snapshot alone_h.png --events events.txt 2>err.txt ||
    fail "key h on a cloud alone failed"
  grep -q "no maps" err.txt || fail "key h without maps says nothing"
  "$probe" alone_h.png same alone.png || fail "key h without maps changed the picture"
  ;;
colors)
  # A cloud file shown with its maps: each point in the colour of the map whose image passes
  # nearest. The file holds the chaos game's points (same seed and count as the window's own
  # cloud), so the picture is nearly the one of the chaos-game cloud, coloured by the map that
  # made each point: measured the same bytes (most points are exactly the image of the point
  # before them), required at most 0.5% of the pixels off.
  "$glass" ifs3d points "$ifs" -n 20000 -o cloud.txt >/dev/null
  view "key h
snapshot height.png
key h
" parts.png cloud.txt
  view "" game.png
  "$probe" parts.png count 230 64 51 200 57600 || fail "the file's cloud has too few points of map 1's colour"
  "$glass" compare parts.png game.png --fail-percent 0.5 >/dev/null ||
    fail "the file's cloud is not coloured by the parts the chaos game made"
  # Key h: the height ramp (its reds have full red, so no pixel has map 1's colour).
  "$probe" height.png differ parts.png || fail "key h did not change the colours"
  "$probe" height.png count 230 64 51 0 0 || fail "key h: map 1's colour is left"
  # Without maps: the ramp over the height, blue at the lowest points, red at the highest. Two
  # layers of 1500 points, at y = 0 and y = 1, are all the ramp's first and last colour.
  awk 'BEGIN { srand(7); for (i = 0; i < 1500; i++) { print rand(), 0, rand(); print rand(), 1, rand() } }' >layers.txt
  printf '' >events.txt
  "$glass" ifs3d view layers.txt --size $size --snapshot layers.png --events events.txt 2>err.txt ||
    fail "the two layers cannot be shown"
  "$probe" layers.png count 64 115 255 300 57600 || fail "the lowest layer is not the ramp's blue"
  "$probe" layers.png count 255 89 51 300 57600 || fail "the highest layer is not the ramp's red"
  ;;
menu)
  # The right button's menu has the keys' choices, in the help's order: each entry gives the
  # picture its key gives.
  view "key a
snapshot k_attractor.png
key +
snapshot k_depth4.png
key b
snapshot k_both.png
key a
key m
snapshot k_boxes.png
key m
key c
key h
snapshot k_height.png
mouse left down 120 120
motion 180 120
mouse left up 180 120
snapshot k_turned.png
" k_end.png
  view "menu 2
snapshot m_attractor.png
menu 4
snapshot m_depth4.png
menu 5
menu 5
snapshot m_depth2.png
menu 4
menu 4
menu 3
snapshot m_both.png
menu 2
menu 6
snapshot m_boxes.png
menu 6
menu 1
menu 7
snapshot m_height.png
mouse left down 120 120
motion 180 120
mouse left up 180 120
snapshot m_turned.png
menu 8
" m_reset.png
  render render2.png --depth 2
  "$probe" m_attractor.png same k_attractor.png || fail "menu entry 2 is not key a"
  "$probe" m_depth4.png same k_depth4.png || fail "menu entry 4 is not key +"
  "$probe" m_depth2.png same render2.png || fail "menu entry 5 twice is not depth 2"
  "$probe" m_both.png same k_both.png || fail "menu entry 3 is not key b"
  "$probe" m_boxes.png same k_boxes.png || fail "menu entry 6 is not key m"
  "$probe" m_height.png same k_height.png || fail "menu entry 7 is not key h"
  "$probe" m_turned.png same k_turned.png || fail "the drag after the menu turns otherwise"
  view "" start.png
  "$probe" m_height.png differ start.png || fail "menu entry 7 changed nothing"
  "$probe" m_reset.png same k_height.png || fail "menu entry 8 does not turn the cloud back"
  # Entry 9 quits: the program ends with status 0 before the events run out, so the snapshot
  # that would follow them is never written.
  status=0
  view "menu 9
key a
" quit.png || status=$?
  [ "$status" -eq 0 ] || fail "menu entry 9: status $status, not 0"
  [ ! -e quit.png ] || fail "menu entry 9 did not quit: the events ran on to the snapshot"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: ifs3d view $case_name"
