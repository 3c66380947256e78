#!/bin/sh
# From a fresh clone: installs what is missing, builds everything (Release) and runs every test
# through ctest. Exits non-zero when the build or any test fails.
set -eu
cd "$(dirname "$0")/.."

tools/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)"
