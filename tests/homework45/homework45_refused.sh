#!/bin/sh
# Objects homework 4-5's program refuses: each run must end with status 1 (not a crash), print
# nothing but one line "homework45: FILE: message" naming what is wrong (which object, which face,
# edge or vertex, where), and write no snapshot (GLASS_GLUT_SNAPSHOT is set, the window never
# opens).
#   homework45_refused.sh PROGRAM WORK_DIR REFUSED_DIR UNIT_WINGS_DIR MODEL
# REFUSED_DIR holds the refused_*.wings files and UNIT_WINGS_DIR the unit tests' broken files, all
# written by scenes/models/make_wings_models.escript; MODEL is a good file to break by hand.
set -eu
program=$1
work=$2
refused=$3
unit=$4
model=$5
. "$(dirname "$0")/../shell_test_support.sh"

# refuses FILE MESSAGE: the program given FILE says exactly "homework45: FILE: MESSAGE" (a grep
# basic regular expression) and nothing else, ends with status 1, and writes no picture.
refuses() {
  rm -f picture.png
  status=0
  GLASS_GLUT_SNAPSHOT=picture.png "$program" "$1" >out.txt 2>err.txt || status=$?
  [ "$status" -eq 1 ] || fail "$1: exit status $status, 1 expected: $(cat err.txt)"
  [ ! -s out.txt ] || fail "$1: printed on standard output: $(cat out.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$1: not one line of message: $(cat err.txt)"
  grep -qx "homework45: $1: $2" err.txt || fail "$1: the message is not \"$2\" but: $(cat err.txt)"
  [ ! -e picture.png ] || fail "$1: a snapshot was written"
}

# Objects that are not closed solids.
refuses "$refused/refused_open_cube.wings" \
  "object 1, face 2: a hole (listed in the object's holes property), so the object is not closed (a closed object made of cubes is expected)"
refuses "$refused/refused_face_on_both_sides.wings" \
  "object 1, edge 0: face 0 on both of its sides (a closed object is expected)"
refuses "$refused/refused_face_not_in_a_plane.wings" \
  "object 1, face 0: its edges do not close into a loop at vertex 4 (a closed object is expected)"
refuses "$refused/refused_inside_out.wings" \
  "object 1 is inside out: its faces run clockwise seen from outside (the volume they enclose is -1)"
# Objects whose faces overlap: two cubes stacked without sharing the face between them, two
# cubes pushed into each other, two cubes touching along an edge only.
refuses "$refused/refused_overlapping_faces.wings" \
  "object 1, faces 2 and 9: both at height 1 above x 0.5, z 0.5 (faces overlap; a closed object made of cubes is expected)"
refuses "$refused/refused_crossing_cubes.wings" \
  "object 1, face 2: below it, above x 0.75, z 0.75, the object is inside itself twice from height 0.5 to 1 (parts of it overlap; a closed object made of cubes is expected)"
refuses "$refused/refused_cubes_on_an_edge.wings" \
  "object 1: between heights 0 and 1 its cubes meet only along the upright line at x 1, z 1"
refuses "$refused/refused_flat.wings" \
  "object 1 is flat: all its vertices have y 0 (an object made of cubes is expected)"
# Objects the reader cannot take.
refuses "$refused/refused_infinite_vertex.wings" "object 1, vertex 0: a coordinate is not finite"
refuses "$refused/refused_no_vertices.wings" "object 1 has no vertices"
refuses "$refused/refused_no_objects.wings" "the file has no object"
refuses "$unit/face_out_of_range.wings" "object 1, edge 0: a vertex or face number out of range"
refuses "$unit/hard_edge_out_of_range.wings" "object 1, hard edge 0: not an edge's number"
refuses "$unit/no_edge_record.wings" "object 1, edge 0: no {edge, Vs, Ve, Lf, Rf, ...} record"
refuses "$unit/short_vertex.wings" "object 1, vertex 0: no <<X, Y, Z>> position of three floats"
refuses "$unit/version_3.wings" "not a version 2 {wings, 2, {Shapes, Materials, Props}} term"
refuses "$unit/not_a_tuple.wings" "not a version 2 {wings, 2, {Shapes, Materials, Props}} term"
# Files that are not Wings3D files, or whose data is damaged.
echo "not a model" >text.wings
refuses text.wings "not a Wings3D file (no #!WINGS-1.0 header)"
# The header and the size kept, the compressed term after its first bytes overwritten.
head -c 30 "$model" >damaged.wings
size=$(wc -c <"$model")
head -c $((size - 30)) /dev/zero | tr '\000' '\377' >>damaged.wings
status=0
GLASS_GLUT_SNAPSHOT=picture.png "$program" damaged.wings >out.txt 2>err.txt || status=$?
[ "$status" -eq 1 ] || fail "damaged.wings: exit status $status, 1 expected: $(cat err.txt)"
grep -q "^homework45: damaged.wings: ." err.txt || fail "damaged.wings: no message: $(cat err.txt)"
[ ! -e picture.png ] || fail "damaged.wings: a snapshot was written"
echo "homework45 refusals: all checks passed"
