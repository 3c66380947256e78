#!/bin/sh
# From a fresh clone: installs what is missing, builds glass (Release), renders the showcase to
# out/showcase.png and prints its path.
set -eu
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target showcase

mkdir -p out
build/release/tools/showcase/showcase out/showcase.png
echo "$(pwd)/out/showcase.png"
