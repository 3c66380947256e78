#!/bin/sh
# From a fresh clone: installs what is missing, builds glass (Release), renders the showcase scene
# (scenes/showcase.scene) to out/showcase.png with the glass command line and prints its path.
set -eu
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target glass

mkdir -p out
build/release/tools/glass/glass render scenes/showcase.scene -o out/showcase.png
echo "$(pwd)/out/showcase.png"
