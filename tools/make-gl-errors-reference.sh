#!/bin/sh
# Writes tests/gl_errors/reference.txt: the output of tests/gl_errors/gl_errors.c built against
# Mesa's OSMesa (gl_errors_mesa, see cmake/GlassGLProgram.cmake), which the gl_errors test compares
# glass's output with. Mesa's gallium driver is pinned to llvmpipe, as for the reference images.
set -eu
cd "$(dirname "$0")/.."

cmake --preset release >/dev/null
cmake --build --preset release -j2 --target gl_errors_mesa >/dev/null

program=build/release/tests/gl_errors/gl_errors_mesa
if [ ! -x "$program" ]; then
  echo "make-gl-errors-reference: the Mesa builds are off; they need libosmesa6-dev and libglu1-mesa-dev" >&2
  exit 1
fi
GALLIUM_DRIVER=llvmpipe "$program" >tests/gl_errors/reference.txt
echo "tests/gl_errors/reference.txt: $(wc -l <tests/gl_errors/reference.txt) lines"
