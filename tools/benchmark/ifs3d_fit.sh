#!/bin/sh
# The benchmark of `glass ifs3d fit` (not a test): a 50,000-point cloud of
# scenes/ifs/homework3.ifs3 fitted 3 times by hyperfine, and the CPU time of one fit, which is
# the better measure on a loaded machine. Usage: tools/benchmark/ifs3d_fit.sh [build directory]
set -eu
cd "$(dirname "$0")/../.."
glass="${1:-build/release}/tools/glass/glass"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$glass" ifs3d points scenes/ifs/homework3.ifs3 -n 50000 -o "$work/cloud.txt" >/dev/null
/usr/bin/time -f "one fit: %U s user, %S s system, %e s wall" "$glass" ifs3d fit "$work/cloud.txt" >/dev/null
hyperfine --runs 3 "$glass ifs3d fit $work/cloud.txt"
