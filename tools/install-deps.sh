#!/bin/sh
# Installs the Debian packages glass needs to build, test and make reference images, and only
# those that are missing. Runs apt-get update first, but only when something has to be installed,
# so that on a machine that has everything it is quiet and needs no network. Uses sudo only when
# not already root.
set -eu

# Build: compilers, CMake and make. Libraries: GLM (maths), stb (PNG files), doctest (unit
# tests), OpenImageIO (image comparison in tests). Reference tool: OSMesa and GLU (the same GL
# programs rendered by Mesa), freeglut's headers. Model loading: tinyobjloader, zlib (Wings3D
# files). SIMD kernels with run-time dispatch: Highway. GLUT windows: SDL2; their test in a
# real window: Xvfb, xdotool, xwd (x11-apps), ImageMagick. The OSMesa tests: PyOpenGL and
# numpy. Test data: erlang-base (Erlang's term_to_binary writes the .wings test files).
PACKAGES="gcc g++ cmake make pkg-config libglm-dev libstb-dev doctest-dev libopenimageio-dev
openimageio-tools libosmesa6-dev libglu1-mesa-dev freeglut3-dev libtinyobjloader-dev
libsdl2-dev libhwy-dev xvfb xdotool x11-apps imagemagick python3-opengl python3-numpy zlib1g-dev erlang-base"

missing=""
for package in $PACKAGES; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
  if [ "$status" != "installed" ]; then
    missing="$missing $package"
  fi
done

if [ -z "$missing" ]; then
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=""
elif command -v sudo >/dev/null 2>&1; then
  as_root="sudo"
else
  echo "install-deps: missing:$missing; run me as root or install sudo" >&2
  exit 1
fi

echo "install-deps: installing$missing"
$as_root apt-get update -qq
# shellcheck disable=SC2086 # the list is meant to split into words
$as_root env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "install-deps: done"
