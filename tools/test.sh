#!/bin/sh
# From a fresh clone: installs what is missing, builds everything (Release) and runs every test
# through ctest; then builds the tests the sanitizers run (the `asan` preset: AddressSanitizer and
# UndefinedBehaviorSanitizer, where any report fails the test that caused it) and runs them:
# the fuzz replays, the unit tests and GLU's mipmaps with the fast paths on and off. Exits
# non-zero when a build or any test fails.
#
# GLASS_TEST_SANITIZERS=0 leaves out the sanitizer part (a quick local run).
set -eu
cd "$(dirname "$0")/.."

jobs="$(nproc)"
tools/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$jobs"
ctest --preset release -j"$jobs"

if [ "${GLASS_TEST_SANITIZERS:-1}" != 0 ]; then
  cmake --preset asan
  cmake --build --preset asan -j"$jobs" --target glass_unit_tests glass_scene_fuzz_replay \
    glass_gl_calls_fuzz_replay glu_mipmap_values
  ctest --preset asan -j"$jobs" -R '^(unit|fuzz_replay\.|glu_mipmaps\.fast_paths)'
fi
