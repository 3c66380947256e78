#!/bin/sh
# The pictures of docs/teaching.md, made with the teaching views from the course's programs as
# they are: Listing 5 (tests/glut/programs/), the homework 4-5 room (examples/homework45/) and a
# textured floor (tests/image/programs/textured_fog_floor.c).
#   tools/make-teaching-pictures.sh [BUILD_DIR]     (default build/release)
# The programs must be built: cmake --build BUILD_DIR --target glut_listing5_offscreen homework45
# image_textured_fog_floor. Writes docs/images/teaching/*.png; runs headless (SDL's dummy driver).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
out=$root/docs/images/teaching
listing5=$build/tests/glut/glut_listing5_offscreen
room=$build/examples/homework45/homework45
floor=$build/tests/image/image_textured_fog_floor
for program in "$listing5" "$room" "$floor"; do
  [ -x "$program" ] || { echo "make-teaching-pictures: $program is not built" >&2; exit 1; }
done
mkdir -p "$out"
export SDL_VIDEODRIVER=dummy
unset GLASS_VIEW GLASS_STATS GLASS_TRACE_VERTEX

# Listing 5: step 4 as drawn, its overdraw, and the wireframe of step 3.
"$listing5" 4 "$out/listing5.png"
GLASS_VIEW=overdraw "$listing5" 4 "$out/listing5_overdraw.png"
GLASS_VIEW=wireframe "$listing5" 3 "$out/listing5_wireframe.png"
# The lit room of homework 4-5, its first frame, and its normals.
GLASS_GLUT_SNAPSHOT="$out/room.png" "$room"
GLASS_VIEW=normals GLASS_GLUT_SNAPSHOT="$out/room_normals.png" "$room"
# A textured floor receding to the horizon, and the mipmap levels its pixels read.
"$floor" "$out/floor.png"
GLASS_VIEW=mipmap "$floor" "$out/floor_mipmap.png"
echo "make-teaching-pictures: wrote $out"
