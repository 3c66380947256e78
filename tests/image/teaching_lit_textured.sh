#!/bin/sh
# The teaching tools on a lit, textured program run as it is (textured_fog_floor.c): each view,
# GLASS_STATS and GLASS_TRACE_VERTEX, with checks that follow from the program's calls.
#   teaching_lit_textured.sh PROGRAM PNG_PROBE WORK_DIR
set -eu
program=$1
probe=$2
work=$3
. "$(dirname "$0")/../shell_test_support.sh"
expect_text() {  # FILE TEXT
  grep -F -- "$2" "$1" >/dev/null || { echo "--- $1:" >&2; cat "$1" >&2; fail "$1 lacks: $2"; }
}

"$program" plain.png
for view in depth overdraw wireframe normals mipmap; do
  GLASS_VIEW=$view "$program" "$view.png" 2>"$view.txt" || fail "GLASS_VIEW=$view: the program failed"
  "$probe" "$view.png" size 400 260 differ plain.png
done
# The floor is drawn with the current normal, never set: (0, 0, 1) in object space. gluLookAt
# from (0, 1.6, 6) to (0, 1, -10) turns it to (0, -0.6 / |f|, 16 / |f|) = (0, -0.037474, 0.999298),
# |f| = sqrt(0.36 + 256), in eye space: 255 (n + 1) / 2 = (128, 123, 255), over much of the picture.
"$probe" normals.png count 128 123 255 20000 104000
# The fence posts are untextured lines (grey); the crates are magnified, level 0 (red).
"$probe" mipmap.png count 96 96 96 50 5000 count 255 0 0 5000 104000
# GLASS_STATS: the same picture; the floor and crates are textured, so texels are read.
GLASS_STATS=1 "$program" stats.png 2>stats.txt
"$probe" stats.png same plain.png
expect_text stats.txt "glass stats, frame 0:"
expect_text stats.txt "(0 points, 12 lines,"
grep -E "^  texel reads +[1-9]" stats.txt >/dev/null || fail "no texel reads counted"
# GLASS_TRACE_VERTEX: vertex 1 is the floor's corner (30, 0, 8) with texture coordinates (20, 0).
GLASS_TRACE_VERTEX=1 "$program" trace.png 2>trace.txt
"$probe" trace.png same plain.png
expect_text trace.txt "glass trace: vertex 1 of frame 0"
expect_text trace.txt "  object  (  30.000000,    0.000000,    8.000000,    1.000000)   as given"
expect_text trace.txt "    as given            (  20.000000,    0.000000,    0.000000,    1.000000)"
echo "ok: teaching_lit_textured"
