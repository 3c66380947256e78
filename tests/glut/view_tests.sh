#!/bin/sh
# `glass view`, headless (SDL_VIDEODRIVER=dummy) or, for live reload, in a real window under
# Xvfb (real time):
#   view_tests.sh CASE GLASS PROBE SCENE WORK_DIR
set -eu
case_name=$1
glass=$2
probe=$3
scene=$4
work=$5
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

view() {  # EVENTS-TEXT SNAPSHOT [SCENE]
  printf '%s' "$1" >events.txt
  "$glass" view "${3:-$scene}" --snapshot "$2" --events events.txt
}

case $case_name in
viewpoints)
  # Viewpoint 1 is the scene's own camera: the picture `glass render` makes. Viewpoint 3 looks
  # from elsewhere; key 1 comes back; the orthographic key changes the picture.
  "$glass" render "$scene" -o render.png
  view "" first.png
  "$probe" first.png same render.png || fail "the first frame is not the scene's picture"
  view "key 3
snapshot three.png
key 1
snapshot one.png
key o
" ortho.png
  "$probe" three.png differ render.png || fail "viewpoint 3 shows the scene's view"
  "$probe" one.png same render.png || fail "key 1 does not bring back the scene's camera"
  "$probe" ortho.png differ render.png || fail "the orthographic projection changed nothing"
  # Walk mode looks level from the eye; the arrows move and turn it.
  view "key w
snapshot start.png
special up
snapshot walked.png
special left
" turned.png
  "$probe" start.png differ render.png || fail "walk mode does not look level"
  "$probe" walked.png differ start.png || fail "walking forward changed nothing"
  "$probe" turned.png differ walked.png || fail "turning changed nothing"
  ;;
menu)
  # The right-button menu's View > Depth entry shows what `glass render --view depth` draws;
  # the pop-up is drawn over the picture.
  "$glass" render "$scene" -o depth_render.png --view depth
  view "mouse right down 60 60
snapshot open.png
mouse right up 60 60
menu 5 2
" depth.png
  "$probe" depth.png same depth_render.png || fail "View > Depth is not the depth view"
  "$probe" open.png count 178 178 178 2000 100000 || fail "no pop-up drawn"
  ;;
reload)
  # Live reload in a real window (real time): an edit that breaks the scene is reported with
  # file:line:col and the last good picture stays; an edit that mends it is shown.
  # A copy of the scene's directory, for the files it includes and loads.
  cp -r "$(dirname "$scene")" scenes
  cd scenes
  cp "$scene" live.scene
  sed 's/^clear_color .*/clear_color 0.9 0.2 0.1/' "$scene" >edited.scene
  grep -q '^clear_color 0.9 0.2 0.1' edited.scene || fail "the scene has no clear_color line to edit"
  "$glass" render edited.scene -o edited_render.png
  printf 'snapshot before.png\nwait 3000\nsnapshot broken.png\nwait 3000\nsnapshot after.png\n' >events.txt
  unset SDL_VIDEODRIVER
  GLASS_GLUT_EVENTS=events.txt GLASS_GLUT_SNAPSHOT=final.png "$glass" view live.scene \
    >out.txt 2>err.txt &
  pid=$!
  tries=0
  until [ -s before.png ]; do
    tries=$((tries + 1)); [ "$tries" -lt 300 ] || fail "no first picture"; sleep 0.1
  done
  printf 'size 640 480\nclear_color 1 2\n' >live.scene
  tries=0
  until [ -s broken.png ]; do
    tries=$((tries + 1)); [ "$tries" -lt 300 ] || fail "no second picture"; sleep 0.1
  done
  cp edited.scene live.scene
  wait "$pid" || fail "glass view exited with $?"
  cat err.txt >&2
  grep -q 'live.scene:2:' err.txt || fail "the broken scene was not reported with file:line:col"
  "$probe" broken.png same before.png || fail "the last good picture did not stay"
  "$probe" after.png same edited_render.png || fail "the edit was not shown"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "ok: view $case_name"
