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
  "$probe" alone.png count 217 217 204 100 57600 || fail "the cloud alone shows too few points"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: ifs3d view $case_name"
