#!/bin/sh
# Renders the reference picture of every scene in scenes/ and tests/scenes/images/ (scenes that
# test the language rather than show it off) into reference_images/scenes/<name>.png
# and records in reference_images/README.md how each was made.
#
# tests/scenes/tolerances.txt says where each reference comes from: `mesa` scenes use only GL 1.x
# and are rendered by Mesa (glass_mesa, the scene library built on OSMesa, with Mesa's gallium
# driver pinned to llvmpipe); `glass` scenes use glass's own extensions (per-pixel Phong shading)
# and are rendered by glass itself: after this script, look at those pictures before committing
# them, since they check glass only against its earlier self.
set -eu
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target glass glass_mesa mesa_info >/dev/null

export GALLIUM_DRIVER=llvmpipe
build=build/release
if [ ! -x "$build/tools/glass/glass_mesa" ]; then
  echo "make-scene-references: the Mesa build is off; it needs libosmesa6-dev and libglu1-mesa-dev" >&2
  exit 1
fi
version=$("$build/tools/reference/mesa_info" | sed -n 's/^GL_VERSION: .*\(Mesa [^ ]*\).*/\1/p')
renderer=$("$build/tools/reference/mesa_info" | sed -n 's/^GL_RENDERER: //p')
package=$(dpkg-query -W -f='${Version}' libosmesa6 2>/dev/null || echo unknown)

mkdir -p reference_images/scenes
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for scene in scenes/*.scene tests/scenes/images/*.scene; do
  name=$(basename "$scene" .scene)
  source=$(awk -v n="$name" '$1 == n { print $2 }' tests/scenes/tolerances.txt)
  case "$source" in
    mesa)
      command="GALLIUM_DRIVER=llvmpipe $build/tools/glass/glass_mesa render $scene -o reference_images/scenes/$name.png"
      "$build/tools/glass/glass_mesa" render "$scene" -o "reference_images/scenes/$name.png" 2>/dev/null
      made="$version (libosmesa6 $package), $renderer"
      ;;
    glass)
      command="$build/tools/glass/glass render $scene -o reference_images/scenes/$name.png"
      "$build/tools/glass/glass" render "$scene" -o "reference_images/scenes/$name.png"
      made="glass, reviewed (uses a glass extension Mesa lacks)"
      ;;
    *)
      echo "make-scene-references: tests/scenes/tolerances.txt has no line for $name" >&2
      exit 1
      ;;
  esac
  echo "reference_images/scenes/$name.png"
  printf '| scenes/%s.png | %s | %s | `%s` |\n' "$name" "$scene" "$made" "$command" >>"$rows"
done

# Replace the table between the markers in the README, keeping everything else.
readme=reference_images/README.md
awk -v rows="$rows" '
  /<!-- scene-references:end -->/ { skipping = 0 }
  !skipping { print }
  /<!-- scene-references:begin -->/ {
    print "| image | scene | made by | command |"
    print "|---|---|---|---|"
    while ((getline line < rows) > 0) print line
    skipping = 1
  }' "$readme" >"$readme.tmp"
mv "$readme.tmp" "$readme"
