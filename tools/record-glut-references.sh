#!/bin/sh
# Records what freeglut 3.4 with Mesa does with the differential GLUT programs
# (tests/glut/programs/spin_menu.c, drag_teapot.c, timer_window.c, key_repeat.c) for the same X
# input as glass gets in the test glut.xvfb_differential_CASE: each program built against the
# system's freeglut, GLU and GL (Debian freeglut3-dev; Mesa's llvmpipe under Xvfb's GLX) and
# driven by tests/glut/xvfb_differential.sh; its log, the window's title and geometry, the screenshots and
# their text masks go to tests/glut/expected/differential/CASE/.
#   tools/record-glut-references.sh [CASE...]      (from the repository's root)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cases=${*:-spin_menu drag_teapot timer_window key_repeat}
build=$(mktemp -d)
trap 'rm -rf "$build"' EXIT
for case in $cases; do
  cc -O1 -o "$build/glut_$case" "$root/tests/glut/programs/$case.c" -lglut -lGLU -lGL
  xvfb-run -a -s "-screen 0 800x600x24 +extension GLX" \
    sh "$root/tests/glut/xvfb_differential.sh" "$build" "$build/work_$case" "$case"
  destination="$root/tests/glut/expected/differential/$case"
  rm -rf "$destination"
  mkdir -p "$destination"
  # A line repeated at once is kept once: freeglut draws a window a second time for the same
  # change when X's ConfigureNotify and Expose of a resize reach it in two passes of its loop
  # rather than one, which depends on timing; glass, drawing once, must match the single line.
  uniq "$build/work_$case/out.txt" >"$destination/out.txt"
  cp "$build/work_$case/driver.txt" "$build/work_$case"/shot_*.png "$destination/"
  for mask in "$build/work_$case"/mask_*.txt; do
    [ -f "$mask" ] && cp "$mask" "$destination/"
  done
  pictures=$(ls "$destination"/shot_*.png | wc -l)
  echo "recorded $case: $(wc -l <"$destination/out.txt") lines, $pictures pictures"
done
