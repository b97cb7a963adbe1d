#!/usr/bin/env bash
# Compares two builds of the tile benchmark by running them alternately on one core, the best
# (least) cycles per tile of each over several rounds: on this kind of VM the host's noise only
# ever adds cycles, so the least of a few runs is the steadiest figure of a build, and running
# the builds in turn spreads slow spells over both.
# Per tile: a process evaluating 300 tiles minus the same process evaluating none
# (BM_TileFixedCount), user cycles from perf.
# Other instruction sets: STRAHLER_BENCH_SET=avx2 (or sse2) in the environment.
# Usage: scripts/bench/tile-alternate.sh BENCH_A BENCH_B "ZOOMS" [ROUNDS]
#   e.g. scripts/bench/tile-alternate.sh /tmp/before/strahler_tile_bench \
#          build/release/tests/bench/strahler_tile_bench "9 13" 4
# Needs perf (Debian: linux-perf), taskset (util-linux), perf_event_paranoid ≤ 2.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,11p' "$0" >&2; exit 2; }
a="$1" b="$2" zooms="$3" rounds="${4:-3}"
command -v perf >/dev/null || { echo "tile-alternate: perf is missing (apt-get install linux-perf)" >&2; exit 1; }
cycles() { # binary zoom tiles -> user cycles
  taskset -c 0 perf stat -x, -e cycles:u "$1" \
    --benchmark_filter="BM_TileFixedCount/zoom:$2/tiles:$3/" 2>&1 >/dev/null |
    awk -F, '$3 ~ /cycles/ { print $1 }'
}
perTile() { # binary zoom -> cycles per tile
  local c0 c1
  c0=$(cycles "$1" "$2" 0)
  c1=$(cycles "$1" "$2" 300)
  echo $(((c1 - c0) / 300))
}
printf "%-5s %12s %12s %10s\n" zoom "A: Mcycles" "B: Mcycles" "B/A"
for z in $zooms; do
  bestA="" bestB=""
  for _ in $(seq "$rounds"); do
    ca=$(perTile "$a" "$z")
    cb=$(perTile "$b" "$z")
    if [ -z "$bestA" ] || [ "$ca" -lt "$bestA" ]; then bestA=$ca; fi
    if [ -z "$bestB" ] || [ "$cb" -lt "$bestB" ]; then bestB=$cb; fi
  done
  awk -v z="$z" -v a="$bestA" -v b="$bestB" \
    'BEGIN { printf "%-5s %12.3f %12.3f %10.4f\n", z, a / 1e6, b / 1e6, b / a }'
done
