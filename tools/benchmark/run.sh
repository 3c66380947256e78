#!/bin/sh
# Builds the benchmarks (Release) and prints glass's and Mesa's frame times side by side, with
# glass's time as a share of Mesa's, for each thread count.
#
#   tools/benchmark/run.sh [--rounds N] [--threads "1 2"] [--runs N] [FRAME...]
#
#   --rounds N    how many times each program runs per thread count (default 3); a figure is the
#                 median of the rounds' figures
#   --threads L   the thread counts, passed to Mesa's llvmpipe as LP_NUM_THREADS and to glass as
#                 GLASS_THREADS (default "1 2")
#   --runs N      timed frames per program run (default 7); a round's figure is their median
#   FRAME         only these frames of the benchmark program (default: all), e.g. lit_spheres;
#                 scene_room and scene_showcase name the scene frames
#
# The machine may be shared: within a round, glass and Mesa run one after the other, in turns
# (glass first in odd rounds, Mesa first in even ones), so that load that comes and goes falls on
# both. The load average before and after is printed with the figures.
set -eu
cd "$(dirname "$0")/../.."

rounds=3
thread_counts="1 2"
runs=7
frames=""
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift 2 ;;
    --threads) thread_counts=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    -h|--help) sed -n '2,18s/^# \{0,1\}//p' "$0"; exit 0 ;;
    -*) echo "run.sh: unknown option $1" >&2; exit 2 ;;
    *) frames="$frames $1"; shift ;;
  esac
done

# Which frames go to which program: scene_<name> frames are scenes/<name>.scene.
array_frames="" scene_files=""
for frame in $frames; do
  case "$frame" in
    scene_*) scene_files="$scene_files scenes/${frame#scene_}.scene" ;;
    *) array_frames="$array_frames $frame" ;;
  esac
done
if [ -z "$frames" ]; then scene_files="scenes/room.scene scenes/showcase.scene"; fi
run_arrays=yes
if [ -n "$frames" ] && [ -z "$array_frames" ]; then run_arrays=no; fi

cmake --preset release >/dev/null
targets="benchmark scene_benchmark"
have_mesa=no
if cmake --build --preset release --target help | grep 'benchmark_mesa' >/dev/null; then
  targets="$targets benchmark_mesa scene_benchmark_mesa"
  have_mesa=yes
fi
# shellcheck disable=SC2086 # one word per target
cmake --build --preset release -j"$(nproc)" --target $targets >/dev/null

bin=build/release/tools/benchmark
results=$(mktemp)
trap 'rm -f "$results"' EXIT
export GALLIUM_DRIVER=llvmpipe
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

# Runs one renderer's programs with `threads` threads and appends their lines to $results, each
# prefixed with the renderer, the thread count and which program wrote it.
measure() {
  renderer=$1 threads=$2 suffix=""
  [ "$renderer" = mesa ] && suffix=_mesa
  if [ "$run_arrays" = yes ]; then
    # shellcheck disable=SC2086 # one word per frame
    LP_NUM_THREADS=$threads GLASS_THREADS=$threads "$bin/benchmark$suffix" --runs "$runs" $array_frames |
      sed "s/^/$renderer $threads frames /" >>"$results"
  fi
  if [ -n "$scene_files" ]; then
    # shellcheck disable=SC2086 # one word per scene
    LP_NUM_THREADS=$threads GLASS_THREADS=$threads "$bin/scene_benchmark$suffix" --runs "$runs" $scene_files |
      sed "s/^/$renderer $threads scenes /" >>"$results"
  fi
}

round=1
while [ "$round" -le "$rounds" ]; do
  for threads in $thread_counts; do
    if [ "$have_mesa" = no ]; then
      measure glass "$threads"
    elif [ $((round % 2)) -eq 1 ]; then
      measure glass "$threads"; measure mesa "$threads"
    else
      measure mesa "$threads"; measure glass "$threads"
    fi
  done
  echo "round $round of $rounds done" >&2
  round=$((round + 1))
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

first() { sed -n "s/^$1 [0-9]* frames $2 *//p" "$results" | head -n 1; }
echo "machine:    $(first glass machine:)"
echo "load:       $load_before before, $load_after after (1, 5, 15 minute load averages; the"
echo "            machine may be shared, so figures vary from run to run)"
echo "glass:      $(first glass renderer:)"
[ "$have_mesa" = yes ] && echo "Mesa:       $(first mesa renderer:)"
echo "frames:     1920 x 1080 (scenes: 800 x 600, context, drawing and read-back)"
echo "timing:     median of $rounds rounds, each the median of $runs frames after 1 warm-up frame,"
echo "            glass and Mesa in turns within a round; ms, and glass / Mesa (goal: <= 0.50)"
echo
awk -v threads="$thread_counts" '
  function median(list,    n, i, j, v, a) {
    n = split(list, a, " ")
    for (i = 2; i <= n; i++) { v = a[i]; for (j = i - 1; j >= 1 && a[j] + 0 > v + 0; j--) a[j + 1] = a[j]; a[j + 1] = v }
    return n == 0 ? "" : (n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2)
  }
  $4 == "frame" {
    name = $5
    if (!(name in count)) { count[name] = $6; order[++n] = name }
    for (i = 7; i < NF; i++) if ($i == "median") ms[$1, $2, name] = ms[$1, $2, name] " " $(i + 1)
  }
  $4 == "peak" && $5 == "memory:" { if ($6 + 0 > peak[$1, $3] + 0) peak[$1, $3] = $6 }
  END {
    t = split(threads, counts, " ")
    printf "%-26s %9s", "", ""
    for (k = 1; k <= t; k++) printf "   %-25s", counts[k] (counts[k] == 1 ? " thread" : " threads")
    printf "\n%-26s %9s", "frame", "primitives"
    for (k = 1; k <= t; k++) printf "   %8s %8s %7s", "glass", "Mesa", "ratio"
    printf "\n"
    for (i = 1; i <= n; i++) {
      name = order[i]
      printf "%-26s %9s", name, count[name]
      for (k = 1; k <= t; k++) {
        g = median(ms["glass", counts[k], name]); m = median(ms["mesa", counts[k], name])
        printf "   %8s %8s %7s", g == "" ? "-" : sprintf("%.1f", g), m == "" ? "-" : sprintf("%.1f", m),
               (g == "" || m == "" || m == 0) ? "-" : sprintf("%.2f", g / m)
      }
      printf "\n"
    }
    scenes = 0
    for (i = 1; i <= n; i++) if (order[i] ~ /^scene_/) scenes++
    if (scenes) {
      printf "\nscenes in frames per second (800 x 600)"
      for (k = 1; k <= t; k++) printf "   %s: glass / Mesa", counts[k] (counts[k] == 1 ? " thread" : " threads")
      printf "\n"
      for (i = 1; i <= n; i++) {
        name = order[i]
        if (name !~ /^scene_/) continue
        printf "%-26s", name
        for (k = 1; k <= t; k++) {
          g = median(ms["glass", counts[k], name]); m = median(ms["mesa", counts[k], name])
          printf "   %8s / %-8s", g == "" ? "-" : sprintf("%.1f", 1000 / g), m == "" ? "-" : sprintf("%.1f", 1000 / m)
        }
        printf "\n"
      }
    }
    printf "\npeak memory, MiB (the largest maximum resident set size of any run of the program)\n"
    for (p = 1; p <= 2; p++) {
      program = p == 1 ? "frames" : "scenes"
      if (!(("glass", program) in peak)) continue
      printf "%-26s glass %8s   Mesa %8s\n", p == 1 ? "benchmark" : "scene_benchmark", peak["glass", program],
             (("mesa", program) in peak) ? peak["mesa", program] : "-"
    }
  }' "$results"
