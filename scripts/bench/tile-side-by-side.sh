#!/usr/bin/env bash
# Compares two builds of the tile benchmark by running them at the same time, one on each
# core, sides swapped every repetition: the host's noise (this kind of VM drifts by up to 1.7×
# in cycles) then hits both alike, and the ratio of their cycles per tile is what decides.
# Per tile: a process evaluating 300 tiles minus the same process evaluating none
# (BM_TileFixedCount), user cycles and instructions from perf.
# Usage: scripts/bench/tile-side-by-side.sh BENCH_A BENCH_B "ZOOMS" [REPETITIONS]
#   e.g. scripts/bench/tile-side-by-side.sh /tmp/before/strahler_tile_bench \
#          build/release/tests/bench/strahler_tile_bench "9 13" 4
# Needs perf (Debian: linux-perf), taskset (util-linux), two cores, perf_event_paranoid ≤ 2.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,11p' "$0" >&2; exit 2; }
a="$1" b="$2" zooms="$3" reps="${4:-3}"
command -v perf >/dev/null || { echo "tile-side-by-side: perf is missing (apt-get install linux-perf)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
count() { # binary zoom tiles cpu out -> "cycles instructions" in out
  taskset -c "$4" perf stat -x, -e cycles:u,instructions:u "$1" \
    --benchmark_filter="BM_TileFixedCount/zoom:$2/tiles:$3/" 2>&1 >/dev/null |
    awk -F, '$3 ~ /cycles/ { c = $1 } $3 ~ /instructions/ { i = $1 } END { print c, i }' >"$5"
}
printf "%-5s %22s %22s %10s\n" zoom "A: Mcycles Minstr" "B: Mcycles Minstr" "B/A cycles"
for z in $zooms; do
  for r in $(seq "$reps"); do
    if [ $((r % 2)) = 1 ]; then ca=0 cb=1; else ca=1 cb=0; fi
    count "$a" "$z" 0 "$ca" "$scratch/a0" & count "$b" "$z" 0 "$cb" "$scratch/b0" & wait
    count "$a" "$z" 300 "$ca" "$scratch/a1" & count "$b" "$z" 300 "$cb" "$scratch/b1" & wait
    read -r ac0 ai0 <"$scratch/a0"; read -r bc0 bi0 <"$scratch/b0"
    read -r ac1 ai1 <"$scratch/a1"; read -r bc1 bi1 <"$scratch/b1"
    awk -v z="$z" -v ac=$((ac1 - ac0)) -v bc=$((bc1 - bc0)) -v ai=$((ai1 - ai0)) -v bi=$((bi1 - bi0)) \
      'BEGIN { printf "%-5s %11.2f %10.2f %11.2f %10.2f %10.3f\n", z, ac / 300e6, ai / 300e6, bc / 300e6, bi / 300e6, bc / ac }'
  done
done
