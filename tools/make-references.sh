#!/bin/sh
# Renders every image-test program (tests/image/programs/*.c) with Mesa into
# reference_images/<name>.png, and records in reference_images/README.md how each was made.
#
# The programs are built against OSMesa (<name>_mesa, see cmake/GlassGLProgram.cmake). Mesa's
# gallium driver is pinned to llvmpipe with GALLIUM_DRIVER=llvmpipe, so that the pictures do not
# depend on which software driver a machine's Mesa picks by default.
set -eu
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target mesa_programs >/dev/null

export GALLIUM_DRIVER=llvmpipe
build=build/release
if [ ! -x "$build/tools/reference/mesa_info" ]; then
  echo "make-references: the Mesa builds are off; they need libosmesa6-dev and libglu1-mesa-dev" >&2
  exit 1
fi
version=$("$build/tools/reference/mesa_info" | sed -n 's/^GL_VERSION: .*\(Mesa [^ ]*\).*/\1/p')
renderer=$("$build/tools/reference/mesa_info" | sed -n 's/^GL_RENDERER: //p')
package=$(dpkg-query -W -f='${Version}' libosmesa6 2>/dev/null || echo unknown)

rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for source in tests/image/programs/*.c; do
  name=$(basename "$source" .c)
  program="$build/tests/image/image_${name}_mesa"
  "$program" "reference_images/$name.png"
  echo "reference_images/$name.png"
  command="GALLIUM_DRIVER=llvmpipe $program reference_images/$name.png"
  printf '| %s.png | %s | %s (libosmesa6 %s), %s | `%s` |\n' \
    "$name" "$source" "$version" "$package" "$renderer" "$command" >>"$rows"
done

# Replace the table between the markers in the README, keeping everything else.
readme=reference_images/README.md
awk -v rows="$rows" '
  /<!-- mesa-references:end -->/ { skipping = 0 }
  !skipping { print }
  /<!-- mesa-references:begin -->/ {
    print "| image | program | Mesa | command |"
    print "|---|---|---|---|"
    while ((getline line < rows) > 0) print line
    skipping = 1
  }' "$readme" >"$readme.tmp"
mv "$readme.tmp" "$readme"
