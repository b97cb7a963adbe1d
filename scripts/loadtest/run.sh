#!/usr/bin/env bash
# Load test of the tile endpoints on loopback (see docs/performance.md):
#  (a) one hot tile, (b) a viewport sweep of distinct tiles, both served from strahler's cache,
#  (c) nginx serving the same tile bytes as static files, in the same run, for comparison,
#  (d) uncached tiles with 1 and with 2 workers (scaling).
# Usage: scripts/loadtest/run.sh [seconds per run, default 10] [connections, default 64]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-10}"
connections="${2:-64}"
command -v wrk >/dev/null && command -v nginx >/dev/null || {
  echo "loadtest: installing wrk and nginx"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq wrk nginx-light >/dev/null
}
scripts/build.sh release >/dev/null
bin=build/release/bin/strahler
work=$(mktemp -d)
port=18080
nginx_port=18081
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

start_server() { # workers cache_mb
  "$bin" serve --quiet --cache-dir "$work/cache" --port $port --threads 2 --workers "$1" --cache-mb "$2" \
    >"$work/server.log" 2>&1 &
  server=$!
  pids+=("$server")
  for _ in $(seq 1 600); do curl -fsS "http://127.0.0.1:$port/health" >/dev/null 2>&1 && return; sleep 0.1; done
  echo "loadtest: server did not start"; cat "$work/server.log"; exit 1
}
stop_server() { kill -TERM "$server"; wait "$server" 2>/dev/null || true; }

run_wrk() { # label url-base list
  TILE_LIST="$3" wrk -t2 -c"$connections" -d"${seconds}s" --timeout 20s --latency \
    -s scripts/loadtest/tiles.lua "$2" \
    | grep RESULT | sed "s/^RESULT/$1/"
}

# Tile lists: a viewport sweep at zoom 12 and 13 over the default island, and one hot tile.
node scripts/loadtest/tile_lists.mjs "$work"

start_server 2 512
# Warm the cache and mirror the same bytes for nginx.
while read -r path; do
  mkdir -p "$work/static$(dirname "$path")"
  curl -fsS "http://127.0.0.1:$port$path" -o "$work/static$path"
done <"$work/sweep.txt"
chmod -R a+rX "$work" # nginx's workers run as an unprivileged user
cat >"$work/nginx.conf" <<NGINX
worker_processes 2;
pid $work/nginx.pid;
error_log $work/nginx-error.log;
events { worker_connections 1024; }
http {
  access_log off;
  types { image/png png; }
  server { listen 127.0.0.1:$nginx_port; root $work/static; }
}
NGINX
nginx -c "$work/nginx.conf" -g 'daemon off;' &
pids+=("$!")
sleep 0.5

echo "# $connections connections, ${seconds}s per run, 2 I/O threads"
run_wrk "strahler-hot-tile" "http://127.0.0.1:$port" "$work/hot.txt"
run_wrk "nginx-hot-tile" "http://127.0.0.1:$nginx_port" "$work/hot.txt"
run_wrk "strahler-sweep-cached" "http://127.0.0.1:$port" "$work/sweep.txt"
run_wrk "nginx-sweep" "http://127.0.0.1:$nginx_port" "$work/sweep.txt"
stop_server

# Uncached: a 1 MB cache cannot hold the sweep, so (almost) every request computes a tile.
for workers in 1 2; do
  start_server "$workers" 1
  run_wrk "strahler-uncached-workers-$workers" "http://127.0.0.1:$port" "$work/sweep.txt"
  stop_server
done
