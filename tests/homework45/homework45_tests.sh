#!/bin/sh
# Homework 4-5's program headless (SDL_VIDEODRIVER=dummy, set by ctest), driven by
# GLASS_GLUT_EVENTS; its snapshots compared with png_probe's same/differ.
#   homework45_tests.sh PROGRAM PNG_PROBE WORK_DIR MODEL UPRIGHTS_MODEL ALL_HARD_MODEL PARTIAL_MODEL
#                       PARTIAL_SHARP_UPRIGHTS_MODEL HALF_SIDE_MODEL TWO_LAYERS_MODEL SLAB_CUBE_MODEL
#                       NOT_CUBES_MODEL TALL_L_MODEL BLOCK_MODEL OVERHANG_HIGH_MODEL OVERHANG_LOW_MODEL
#                       TWO_LAYERS_UPRIGHTS_MODEL L_ON_SLAB_MODEL
# (UPRIGHTS_MODEL: the same L with only its uprights hard, its top's rim sharp; ALL_HARD_MODEL:
# with every edge hard, the bottom's rim too; PARTIAL_MODEL and PARTIAL_SHARP_UPRIGHTS_MODEL: the
# rims of the top and the bottom hard along some sides only, with some uprights hard or none;
# HALF_SIDE_MODEL: one side's top rim hard along half of it; TWO_LAYERS_MODEL and SLAB_CUBE_MODEL:
# objects of two layers of cubes, every edge hard; NOT_CUBES_MODEL: an object with slanted edges;
# TALL_L_MODEL and BLOCK_MODEL: objects of two layers alike, an L with its uprights hard and a
# block of 2 x 2 x 2 cubes with its top's rim and one upright hard; OVERHANG_HIGH_MODEL and
# OVERHANG_LOW_MODEL: a column with an arm along +z at x = 1, its bottom above the walker's head
# and below it; TWO_LAYERS_UPRIGHTS_MODEL: the cube on an L with only its uprights hard;
# L_ON_SLAB_MODEL: an L of three cubes on a slab of 2 x 2, every edge hard.)
set -eu
program=$1
probe=$2
work=$3
model=$4
uprights_model=$5
all_hard_model=$6
partial_model=$7
partial_sharp_model=$8
half_side_model=$9
two_layers_model=${10}
slab_cube_model=${11}
not_cubes_model=${12}
tall_l_model=${13}
block_model=${14}
overhang_high_model=${15}
overhang_low_model=${16}
two_layers_uprights_model=${17}
l_on_slab_model=${18}
ring_model=${19}
ring_on_slab_model=${20}
l_inside_slab_model=${21}
. "$(dirname "$0")/../shell_test_support.sh"

# repeat N LINE: the event line N times.
repeat() {
  n=$1
  while [ "$n" -gt 0 ]; do
    echo "$2"
    n=$((n - 1))
  done
}

# five_presses KIND FILE: FILE's snapshots KIND_sharp.png and KIND_round1..5.png, one after each
# press of R; the program must end well, report nothing, and change the picture at every press.
five_presses() {
  {
    echo "snapshot $1_sharp.png"
    for press in 1 2 3 4 5; do
      echo "key R"
      echo "snapshot $1_round$press.png"
    done
  } >$1_events.txt
  status=0
  GLASS_GLUT_SNAPSHOT=last_$1.png GLASS_GLUT_EVENTS=$1_events.txt "$program" "$2" >out.txt 2>err.txt || status=$?
  [ "$status" -eq 0 ] || fail "the program exited with $status on $2: $(cat err.txt)"
  [ ! -s err.txt ] || fail "$2 reports: $(cat err.txt)"
  previous=$1_sharp.png
  for press in 1 2 3 4 5; do
    "$probe" "$previous" differ $1_round$press.png || fail "$2: R pressed $press times did not change the picture"
    previous=$1_round$press.png
  done
}

{
  echo "snapshot sharp.png"
  for press in 1 2 3 4 5; do
    echo "key R"
    echo "snapshot round$press.png"
  done
  # 0.08 a press: the seventh reaches the largest radius, 0.5, and the eighth stays there.
  repeat 2 "key R"
  echo "snapshot largest.png"
  echo "key R"
  echo "snapshot largest_again.png"
  repeat 7 "key r"
  echo "snapshot sharp_again.png"
  # Viewpoint 2 stands beside the block looking at the back wall: 26 steps reach it.
  echo "key 2"
  echo "snapshot start.png"
  repeat 30 "special up"
  echo "snapshot at_wall.png"
  repeat 10 "special up"
  echo "snapshot still_at_wall.png"
  # Turned 15 degrees to the left, each step into the wall slides along it.
  repeat 3 "special left"
  echo "snapshot turned.png"
  repeat 5 "special up"
  echo "snapshot slid.png"
  for viewpoint in 1 2 3 4 5; do
    echo "key $viewpoint"
    echo "snapshot viewpoint$viewpoint.png"
  done
  echo "menu 6"
  echo "snapshot orthographic.png"
  echo "menu 6"
  echo "snapshot perspective.png"
  # From viewpoint 2 turned 45 degrees to the left, the walker heads for the L's inner corner:
  # the L's cells stop him there, not its bounding box (along which he would slide on).
  echo "key 2"
  repeat 9 "special left"
  repeat 4 "special up"
  echo "snapshot corner4.png"
  repeat 8 "special up"
  echo "snapshot corner12.png"
  repeat 8 "special up"
  echo "snapshot corner20.png"
} >events.txt

status=0
GLASS_GLUT_SNAPSHOT=last.png GLASS_GLUT_EVENTS=events.txt "$program" >out.txt 2>err.txt || status=$?
cat err.txt >&2
[ "$status" -eq 0 ] || fail "the program exited with $status"

"$probe" sharp.png size 400 300 differ round5.png same sharp_again.png || fail "keys R and r"
previous=sharp.png
for press in 1 2 3 4 5; do
  "$probe" "$previous" differ round$press.png || fail "R pressed $press times did not change the picture"
  previous=round$press.png
done
"$probe" largest.png differ round5.png same largest_again.png || fail "R beyond the largest radius"
# The rim of the top is rounded too: the same L with its rim left sharp looks the same sharp and
# different rounded.
{
  echo "snapshot uprights_sharp.png"
  repeat 5 "key R"
  echo "snapshot uprights_round5.png"
} >uprights_events.txt
status=0
GLASS_GLUT_SNAPSHOT=last_uprights.png GLASS_GLUT_EVENTS=uprights_events.txt "$program" "$uprights_model" \
  >out.txt 2>err.txt || status=$?
[ "$status" -eq 0 ] || fail "the program exited with $status on the uprights-only L: $(cat err.txt)"
"$probe" uprights_sharp.png same sharp.png || fail "the two Ls differ before rounding"
"$probe" uprights_round5.png differ round5.png || fail "the rounded rim does not show"
# With every edge hard the bottom's rim is rounded too: the same sharp, different rounded, and
# nothing reported as left sharp.
sed 's/uprights_/all_hard_/' uprights_events.txt >all_hard_events.txt
status=0
GLASS_GLUT_SNAPSHOT=last_all_hard.png GLASS_GLUT_EVENTS=all_hard_events.txt "$program" "$all_hard_model" \
  >out.txt 2>err.txt || status=$?
[ "$status" -eq 0 ] || fail "the program exited with $status on the all-hard L: $(cat err.txt)"
[ ! -s err.txt ] || fail "the all-hard L reports: $(cat err.txt)"
"$probe" all_hard_sharp.png same sharp.png || fail "the all-hard L differs before rounding"
"$probe" all_hard_round5.png differ round5.png || fail "the rounded bottom rim does not show"
# Rims hard along some sides only: rounded there, ending in caps, quarter moons and cut faces
# where they meet a sharp stretch; nothing reported as left sharp, the same L sharp, a picture of
# its own rounded, changing with every press.
for kind in partial partial_sharp; do
  eval "file=\$${kind}_model"
  five_presses $kind "$file"
  "$probe" ${kind}_sharp.png same sharp.png || fail "$file differs from the L before rounding"
  for other in round5.png all_hard_round5.png uprights_round5.png; do
    "$probe" ${kind}_round5.png differ $other || fail "$file rounded looks like $other"
  done
done
"$probe" partial_round5.png differ partial_sharp_round5.png || fail "the partly marked Ls look the same"
# A ring of cubes round a hole, every edge hard: its outline is two loops, both rounded (the
# hole's corners filleted); nothing reported as left sharp, a picture of its own.
five_presses ring "$ring_model"
"$probe" ring_round5.png differ round5.png || fail "the ring rounded looks like the L"
# The same ring on a slab of 3 x 3 is drawn by layers: the ring's rims are rounded, round the hole
# too, and its foot round the hole is filleted (its outer sides are flush with the slab's):
# nothing is left sharp.
five_presses ring_on_slab "$ring_on_slab_model"
# An L standing inside the top of a slab, every edge hard: its foot is filleted all round (an
# eighth of a sphere in its inner corner), so nothing is left sharp.
five_presses l_inside_slab "$l_inside_slab_model"
# A side whose top edges are hard only in part is rounded along its hard stretch, which ends in
# a quarter moon across the side: nothing reported as left sharp, a picture of its own rounded,
# changing with every press.
five_presses half_side "$half_side_model"
for other in round5.png all_hard_round5.png uprights_round5.png partial_round5.png partial_sharp_round5.png; do
  "$probe" half_side_round5.png differ $other || fail "the half-hard side rounded looks like $other"
done
# The default L's hard edges are all rounded: nothing is reported as left sharp.
GLASS_GLUT_SNAPSHOT=quiet.png "$program" >out.txt 2>err.txt || fail "the default model"
[ ! -s err.txt ] || fail "the default model reports: $(cat err.txt)"
"$probe" start.png differ at_wall.png || fail "walking did not move"
# At the wall it fills the view (no pixel of the background, 26 26 38, beyond it).
"$probe" at_wall.png count 26 26 38 0 0 same still_at_wall.png || fail "walked through the wall"
"$probe" turned.png differ slid.png || fail "did not slide along the wall"
for a in 1 2 3 4 5; do
  for b in 1 2 3 4 5; do
    [ "$a" -lt "$b" ] || continue
    "$probe" viewpoint$a.png differ viewpoint$b.png || fail "viewpoints $a and $b look the same"
  done
done
"$probe" viewpoint5.png differ orthographic.png same perspective.png || fail "projection switch"
"$probe" corner4.png differ corner12.png || fail "did not walk into the L's inner corner"
"$probe" corner12.png same corner20.png || fail "walked on out of the L's inner corner"
# Objects of two layers of cubes, every edge hard: a cube on the corner of an L of three, a cube
# on a slab of 2 x 2, an L of three on a slab of 2 x 2. Each is drawn (unlike the L and unlike each
# other), its uprights are rounded layer by layer (every press of R up to the largest radius, 0.5,
# changes the picture; r takes it back), the standing cube's top rim is rounded too (and the
# bottom rims of the L and the slab below, the top rim of the L on the slab), it says that the
# other hard edges along its layers' tops and bottoms stay sharp (8 of the cube on an L's; none of
# the cube on a slab's, whose foot is filleted and whose slab's top rim is rounded up to the cube,
# nor of the L on a slab's, whose foot is filleted along its inner sides and ends at standing
# corners), and walking into it stops.
for kind in two_layers slab_cube l_on_slab; do
  eval "file=\$${kind}_model"
  {
    echo "snapshot ${kind}_sharp.png"
    for press in 1 2 3 4 5 6 7; do
      echo "key R"
      echo "snapshot ${kind}_round$press.png"
    done
    echo "key R"
    echo "snapshot ${kind}_largest_again.png"
    repeat 8 "key r"
    echo "snapshot ${kind}_sharp_again.png"
    # From viewpoint 3 he turns to walk along z = 3.5 to x = 1, then turns to head for the
    # object (x 0 to 2, z 0 to 2) along -z: after a few steps he stands at it.
    echo "key 3"
    repeat 9 "special right"
    repeat 18 "special up"
    repeat 18 "special left"
    echo "snapshot ${kind}_facing.png"
    echo "special up"
    echo "snapshot ${kind}_step1.png"
    repeat 10 "special up"
    echo "snapshot ${kind}_step11.png"
    repeat 10 "special up"
    echo "snapshot ${kind}_step21.png"
  } >${kind}_events.txt
  status=0
  GLASS_GLUT_SNAPSHOT=last_$kind.png GLASS_GLUT_EVENTS=${kind}_events.txt "$program" "$file" \
    >out.txt 2>err.txt || status=$?
  [ "$status" -eq 0 ] || fail "the program exited with $status on $file: $(cat err.txt)"
  case $kind in
  two_layers) sharp=8 ;;
  *) sharp=0 ;;
  esac
  if [ "$sharp" -gt 0 ]; then
    grep -q "^homework45: .*$kind.wings: $sharp hard edges stay sharp (of an object of more than one layer" err.txt ||
      fail "no message about the edges $file leaves sharp: $(cat err.txt)"
  else
    [ ! -s err.txt ] || fail "$file reports: $(cat err.txt)"
  fi
  "$probe" ${kind}_sharp.png size 400 300 differ sharp.png || fail "$file looks like the L"
  previous=${kind}_sharp.png
  for press in 1 2 3 4 5 6 7; do
    "$probe" "$previous" differ ${kind}_round$press.png || fail "$file: R pressed $press times did not change the picture"
    previous=${kind}_round$press.png
  done
  "$probe" ${kind}_round7.png same ${kind}_largest_again.png || fail "$file: R beyond the largest radius"
  "$probe" ${kind}_sharp.png same ${kind}_sharp_again.png || fail "$file: r did not bring the sharp picture back"
  "$probe" ${kind}_facing.png differ ${kind}_step1.png || fail "$file: walking did not move"
  "$probe" ${kind}_step11.png same ${kind}_step21.png || fail "$file: walked through the object"
done
"$probe" two_layers_sharp.png differ slab_cube_sharp.png || fail "the two objects of two layers look the same"
"$probe" two_layers_round6.png differ slab_cube_round6.png || fail "the two rounded objects look the same"
"$probe" l_on_slab_sharp.png differ slab_cube_sharp.png || fail "the L on a slab looks like the cube on a slab"
# The standing cube's top rim is rounded: the cube on an L with only its uprights hard looks the
# same sharp and different rounded, and reports nothing left sharp.
{
  echo "snapshot two_layers_uprights_sharp.png"
  repeat 6 "key R"
  echo "snapshot two_layers_uprights_round6.png"
} >two_layers_uprights_events.txt
status=0
GLASS_GLUT_SNAPSHOT=last_two_layers_uprights.png GLASS_GLUT_EVENTS=two_layers_uprights_events.txt "$program" \
  "$two_layers_uprights_model" >out.txt 2>err.txt || status=$?
[ "$status" -eq 0 ] || fail "the program exited with $status on $two_layers_uprights_model: $(cat err.txt)"
[ ! -s err.txt ] || fail "$two_layers_uprights_model reports: $(cat err.txt)"
"$probe" two_layers_uprights_sharp.png same two_layers_sharp.png || fail "the cube on an L differs before rounding"
"$probe" two_layers_uprights_round6.png differ two_layers_round6.png || fail "the standing cube's rounded rim does not show"
# Objects of two layers alike are one floor plan raised by two layers: rounded as an object of one
# layer (uprights, the top's rim), nothing reported as left sharp, every press of R a new picture.
five_presses tall_l "$tall_l_model"
five_presses block "$block_model"
# Under an overhang: the walker heads along x = 1 for the column behind the arm (z -1 to 0). The
# arm's bottom above his head (2 > 1.8), he walks on under it (every five steps a new picture)
# to the column, where he stops; the arm's bottom below his head (1), the arm stops him.
for kind in high low; do
  eval "file=\$overhang_${kind}_model"
  {
    echo "key 3"
    repeat 9 "special right"
    repeat 18 "special up"
    repeat 18 "special left"
    for part in 1 2 3 4; do
      repeat 5 "special up"
      echo "snapshot ${kind}_under$part.png"
    done
    repeat 10 "special up"
    echo "snapshot ${kind}_under_end.png"
  } >overhang_${kind}_events.txt
  status=0
  GLASS_GLUT_SNAPSHOT=last_overhang_$kind.png GLASS_GLUT_EVENTS=overhang_${kind}_events.txt "$program" "$file" \
    >out.txt 2>err.txt || status=$?
  [ "$status" -eq 0 ] || fail "the program exited with $status on $file: $(cat err.txt)"
done
"$probe" high_under1.png differ high_under2.png || fail "stopped before the overhang"
"$probe" high_under2.png differ high_under3.png || fail "did not walk on under the overhang"
"$probe" high_under3.png same high_under4.png same high_under_end.png || fail "walked through the column"
"$probe" low_under1.png same low_under2.png same low_under_end.png || fail "walked into the low overhang"
"$probe" high_under2.png differ low_under2.png || fail "the two overhangs look the same"
# An object that is not made of cubes is named with what is wrong, and nothing runs.
status=0
"$program" "$not_cubes_model" >out.txt 2>err.txt || status=$?
[ "$status" -ne 0 ] || fail "an object of slanted edges was accepted"
grep -q "^homework45: .*: object 1, edge [0-9]*: not along the x, y or z axis (an object made of cubes is expected)$" err.txt ||
  fail "no message about the slanted edge: $(cat err.txt)"
# The object comes from a Wings3D file: a broken one is named with what is wrong, and nothing runs.
head -c 60 "$model" >truncated.wings
status=0
"$program" truncated.wings >out.txt 2>err.txt || status=$?
[ "$status" -ne 0 ] || fail "a truncated .wings file was accepted"
grep -q "^homework45: truncated.wings: the header states [0-9]* bytes of data, the file has 41$" err.txt ||
  fail "no message naming the truncated file: $(cat err.txt)"
status=0
"$program" missing.wings >out.txt 2>err.txt || status=$?
[ "$status" -ne 0 ] || fail "a missing .wings file was accepted"
grep -q "^homework45: missing.wings: cannot read the file$" err.txt || fail "no message naming the missing file"
# The same object named on the command line gives the same picture as the default.
GLASS_GLUT_SNAPSHOT=named.png "$program" "$model" >out.txt 2>err.txt || fail "the model named on the command line"
GLASS_GLUT_SNAPSHOT=default.png "$program" >out.txt 2>err.txt || fail "the default model"
"$probe" named.png same default.png || fail "the named model differs from the default one"
echo "homework45: all checks passed"
