#!/bin/sh
# Builds the benchmark (Release) and prints glass's and Mesa's frame times side by side.
#
#   tools/benchmark/run.sh [THREADS]
#
# THREADS (default: all hardware threads) is passed to Mesa's llvmpipe as LP_NUM_THREADS and to
# glass as GLASS_THREADS.
set -eu
cd "$(dirname "$0")/../.."

threads=${1:-$(nproc)}
export LP_NUM_THREADS="$threads" GLASS_THREADS="$threads" GALLIUM_DRIVER=llvmpipe

cmake --preset release >/dev/null
targets="benchmark"
if cmake --build --preset release --target help | grep 'benchmark_mesa' >/dev/null; then
  targets="$targets benchmark_mesa"
fi
# shellcheck disable=SC2086 # one word per target
cmake --build --preset release -j"$(nproc)" --target $targets >/dev/null

bin=build/release/tools/benchmark
glass_out=$(mktemp)
mesa_out=$(mktemp)
trap 'rm -f "$glass_out" "$mesa_out"' EXIT
"$bin/benchmark" >"$glass_out"
if [ -x "$bin/benchmark_mesa" ]; then "$bin/benchmark_mesa" >"$mesa_out"; fi

grep -E '^(machine|resolution|timing):' "$glass_out"
echo "threads:    $threads (LP_NUM_THREADS for Mesa, GLASS_THREADS for glass)"
echo "glass:      $(sed -n 's/^renderer: *//p' "$glass_out")"
[ -s "$mesa_out" ] && echo "Mesa:       $(sed -n 's/^renderer: *//p' "$mesa_out")"
echo
# "frame <name> <count> primitives median <ms> ms ..." from both runs, joined by frame name.
awk '
  FNR == 1 { file++ }
  /^frame / { name = $2; count[name] = $3; ms[file, name] = $6; if (file == 1) order[++n] = name }
  END {
    printf "%-18s %12s %14s %14s\n", "frame", "primitives", "glass ms", "Mesa ms"
    for (i = 1; i <= n; i++) {
      name = order[i]
      mesa = ((2, name) in ms) ? ms[2, name] : "-"
      printf "%-18s %12s %14s %14s\n", name, count[name], ms[1, name], mesa
    }
  }' "$glass_out" "$mesa_out"
