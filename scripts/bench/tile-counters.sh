#!/usr/bin/env bash
# Per-tile cost of restricted tile evaluation by CPU counters, robust to this kind of VM's
# drifting speed: `perf stat` over a process evaluating 300 tiles minus the same process
# evaluating none (world generation and start-up cancel out). Cycles and instructions count
# only this process's user time; task-clock gives milliseconds.
# Other instruction sets: STRAHLER_BENCH_SET=avx2 (or sse2) in the environment.
# Usage: scripts/bench/tile-counters.sh [benchmark binary] [zooms...]
#   e.g. scripts/bench/tile-counters.sh build/release/tests/bench/strahler_tile_bench 9 13
# Needs perf (Debian: linux-perf) and kernel.perf_event_paranoid ≤ 2.
set -euo pipefail
bench="${1:-build/release/tests/bench/strahler_tile_bench}"
shift || true
zooms=("$@")
[ ${#zooms[@]} -gt 0 ] || zooms=(0 5 8 9 10 11 13 18)
command -v perf >/dev/null || { echo "tile-counters: perf is missing (apt-get install linux-perf)" >&2; exit 1; }
count() { # zoom tiles -> "task-clock cycles instructions branch-misses"
  perf stat -x, -e task-clock,cycles:u,instructions:u,branch-misses:u \
    "$bench" --benchmark_filter="BM_TileFixedCount/zoom:$1/tiles:$2/" 2>&1 >/dev/null |
    awk -F, '$3 ~ /task-clock|cycles|instructions|branch-misses/ { v[$3] = $1 }
      END { printf "%s %s %s %s\n", v["task-clock"], v["cycles:u"], v["instructions:u"], v["branch-misses:u"] }'
}
printf "%-5s %10s %12s %14s %14s\n" zoom "ms/tile" "Mcycles" "Minstructions" "kbranch-miss"
for z in "${zooms[@]}"; do
  read -r t0 c0 i0 b0 < <(count "$z" 0)
  read -r t1 c1 i1 b1 < <(count "$z" 300)
  awk -v z="$z" -v t="$t1-$t0" -v c="$c1-$c0" -v i="$i1-$i0" -v b="$b1-$b0" 'BEGIN {
    split(t, tt, "-"); split(c, cc, "-"); split(i, ii, "-"); split(b, bb, "-")
    printf "%-5s %10.3f %12.2f %14.2f %14.1f\n", z, (tt[1]-tt[2])/300, (cc[1]-cc[2])/300e6,
      (ii[1]-ii[2])/300e6, (bb[1]-bb[2])/300e3 }'
done
