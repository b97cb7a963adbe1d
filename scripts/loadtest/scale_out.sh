#!/usr/bin/env bash
# Load test of the scale-out kit on loopback (see docs/performance.md, "Scale-out"): the same
# tiles through nginx's cache (scripts/scale-out/run.sh, 2 replicas) and from one replica
# directly, both warm, in the same run.
# Usage: scripts/loadtest/scale_out.sh [seconds per run, default 10] [connections, default 64]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-10}"
connections="${2:-64}"
command -v wrk >/dev/null && command -v node >/dev/null || { echo "loadtest: run scripts/install-deps.sh first (wrk, node)" >&2; exit 1; }
scripts/build.sh release >/dev/null
work=$(mktemp -d)
kit=""
cleanup() {
  if [ -n "$kit" ]; then kill -TERM "$kit" 2>/dev/null || true; wait "$kit" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

STRAHLER_SCALE_PORT=0 STRAHLER_BIN=build/release/bin/strahler \
  scripts/scale-out/run.sh 2 --threads 2 --workers 2 >"$work/kit.log" 2>&1 &
kit=$!
for _ in $(seq 1 1200); do
  grep -q "^scale-out: ready" "$work/kit.log" && break
  kill -0 "$kit" 2>/dev/null || { cat "$work/kit.log" >&2; exit 1; }
  sleep 0.1
done
nginx_url="$(sed -n 's|^scale-out: ready at \(http://[^ ]*\)/$|\1|p' "$work/kit.log")"
replica_url="$(sed -n 's|^scale-out: replica 1 pid [0-9]* at \(http://[^ ]*\)/$|\1|p' "$work/kit.log")"
[ -n "$nginx_url" ] && [ -n "$replica_url" ] || { cat "$work/kit.log" >&2; exit 1; }

node scripts/loadtest/tile_lists.mjs "$work"
# Warm both: nginx's cache (each tile computed on its replica) and replica 1's own cache.
for base in "$nginx_url" "$replica_url"; do
  sed "s|^|$base|" "$work/sweep.txt" | xargs -P 4 -I{} curl -fsS -o /dev/null {}
done

run_wrk() { # label url-base list
  TILE_LIST="$3" wrk -t2 -c"$connections" -d"${seconds}s" --timeout 20s --latency \
    -s scripts/loadtest/tiles.lua "$2" \
    | grep RESULT | sed "s/^RESULT/$1/"
}
echo "# $connections connections, ${seconds}s per run; 2 replicas (2 I/O threads, 2 workers each) behind nginx"
run_wrk "replica-direct-hot-tile" "$replica_url" "$work/hot.txt"
run_wrk "nginx-cache-hot-tile" "$nginx_url" "$work/hot.txt"
run_wrk "replica-direct-sweep" "$replica_url" "$work/sweep.txt"
run_wrk "nginx-cache-sweep" "$nginx_url" "$work/sweep.txt"
