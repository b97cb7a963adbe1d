#!/usr/bin/env bash
# The scale-out kit on one machine: N `strahler serve` replicas of the same world on loopback
# behind Debian's nginx, configured as docker/nginx.conf (both rendered from nginx.conf.in):
# consistent hash on the URI, proxy_cache with lock, retry on the next replica.
#
# Usage: scripts/scale-out/run.sh [REPLICAS] [SERVE OPTIONS...]
#   REPLICAS defaults to 2; SERVE OPTIONS go to every replica (e.g. --coast FILE --seed 7,
#   a WORLD.world, --threads N, --workers N, --cache-mb M, --cache-dir DIR).
# Environment:
#   STRAHLER_SCALE_PORT          nginx's port on 127.0.0.1 (default 8080; 0 picks a free one)
#   STRAHLER_SCALE_REPLICA_PORT  first replica's port, the others follow (default 0: each
#                                replica picks a free one)
#   STRAHLER_SCALE_PUBLIC_URL    the replicas' --public-url (default none: TileJSON names the
#                                host the client asked nginx for, from nginx's X-Forwarded-*
#                                headers, which the replicas trust from loopback)
#   STRAHLER_SCALE_DIR           scratch folder for nginx's files and the logs (default: a new
#                                temporary folder); removed on exit
#   STRAHLER_BIN                 the program (default build/release/bin/strahler, built if missing)
#   NGINX                        nginx (default: from PATH or /usr/sbin/nginx)
# The first replica generates the world (or loads it from the cache) before the others
# start, so they load the same world file from the shared cache folder. Prints one line per
# process, then "scale-out: ready at URL"; Ctrl-C or SIGTERM stops everything and removes the
# scratch folder.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
here="$root/scripts/scale-out"

replicas=2
if [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then
  replicas="$1"
  shift
fi
[ "$replicas" -ge 1 ] || { echo "scale-out: at least one replica" >&2; exit 2; }
serve_args=("$@")
port="${STRAHLER_SCALE_PORT:-8080}"
replica_port="${STRAHLER_SCALE_REPLICA_PORT:-0}"
nginx="${NGINX:-$(command -v nginx || echo /usr/sbin/nginx)}"
[ -x "$nginx" ] || { echo "scale-out: nginx not found: apt-get install nginx-light (scripts/install-deps.sh)" >&2; exit 1; }
command -v curl >/dev/null || { echo "scale-out: curl not found (scripts/install-deps.sh)" >&2; exit 1; }
bin="${STRAHLER_BIN:-$root/build/release/bin/strahler}"
if [ -z "${STRAHLER_BIN:-}" ] && [ ! -x "$bin" ]; then
  (cd "$root" && scripts/build.sh release >/dev/null)
fi
[ -x "$bin" ] || { echo "scale-out: $bin not found" >&2; exit 1; }

if [ -n "${STRAHLER_SCALE_DIR:-}" ]; then
  work="$STRAHLER_SCALE_DIR"
  mkdir -p "$work"
else
  work="$(mktemp -d -t strahler-scale-out.XXXXXX)"
fi
# nginx's workers drop to an unprivileged user when nginx starts as root: they must reach
# the cache and temporary folders nginx creates (and chowns) under the scratch folder.
chmod 755 "$work"

pids=()
stopping=0
# shellcheck disable=SC2317 # (called by the traps)
cleanup() {
  [ "$stopping" -eq 1 ] && return
  stopping=1
  trap - INT TERM EXIT
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  # A replica drains within 4 s plus the tile being computed; nginx stops at once.
  for _ in $(seq 1 100); do
    alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
    [ "$alive" -eq 0 ] && break
    sleep 0.1
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap 'cleanup; exit 130' INT
trap 'cleanup; exit 143' TERM
trap cleanup EXIT

# A free port on 127.0.0.1 for nginx, chosen before the replicas start. It is drawn below the kernel's ephemeral range, so neither the replicas' ports nor
# any connection's local port can take it before nginx binds it.
free_port() {
  /usr/bin/python3 - <<'PY'
import random, socket
low = int(open("/proc/sys/net/ipv4/ip_local_port_range").read().split()[0])
for port in random.sample(range(10000, max(low, 10001)), min(500, max(low - 10000, 1))):
    with socket.socket() as s:
        try:
            s.bind(("127.0.0.1", port))
        except OSError:
            continue
        print(port)
        break
else:
    raise SystemExit("scale-out: no free port below the ephemeral range")
PY
}
[ "$port" = 0 ] && port="$(free_port)"
public_url=()
[ -n "${STRAHLER_SCALE_PUBLIC_URL:-}" ] && public_url=(--public-url "$STRAHLER_SCALE_PUBLIC_URL")

wait_healthy() { # url pid log
  for _ in $(seq 1 1200); do
    curl -fsS -o /dev/null --max-time 2 "$1/health" 2>/dev/null && return 0
    kill -0 "$2" 2>/dev/null || { echo "scale-out: $1 exited; its log:" >&2; cat "$3" >&2; exit 1; }
    sleep 0.1
  done
  echo "scale-out: $1 not healthy after 120 s; its log:" >&2
  cat "$3" >&2
  exit 1
}

# Starts replica $1 and sets $replica_url from the address in its banner.
start_replica() {
  local i="$1" p=0 log="$work/replica-$1.log"
  [ "$replica_port" != 0 ] && p=$((replica_port + i - 1))
  "$bin" serve --quiet --host 127.0.0.1 --port "$p" "${public_url[@]}" \
    --max-client-connections 0 "${serve_args[@]}" >"$log" 2>&1 &
  local pid=$!
  pids+=("$pid")
  replica_url=""
  for _ in $(seq 1 1200); do # the banner comes once the world is ready: generation may take a while
    replica_url="$(sed -n 's|^strahler: serving .* at \(http://[^ ]*\)/$|\1|p' "$log" | head -n 1)"
    [ -n "$replica_url" ] && break
    kill -0 "$pid" 2>/dev/null || { echo "scale-out: replica $i exited; its log:" >&2; cat "$log" >&2; exit 1; }
    sleep 0.1
  done
  [ -n "$replica_url" ] || { echo "scale-out: replica $i printed no address; its log:" >&2; cat "$log" >&2; exit 1; }
  replica_urls+=("$replica_url")
  replica_pids+=("$pid")
}

replica_urls=()
replica_pids=()
start_replica 1
wait_healthy "${replica_urls[0]}" "${replica_pids[0]}" "$work/replica-1.log"
for i in $(seq 2 "$replicas"); do start_replica "$i"; done
for i in $(seq 1 "$replicas"); do
  wait_healthy "${replica_urls[i - 1]}" "${replica_pids[i - 1]}" "$work/replica-$i.log"
  echo "scale-out: replica $i pid ${replica_pids[i - 1]} at ${replica_urls[i - 1]}/"
done

"$here/nginx-conf.sh" loopback "$work/nginx" "$port" "${replica_urls[@]#http://}" >"$work/nginx.conf"
mkdir -p "$work/nginx"
chmod 755 "$work/nginx"
"$nginx" -p "$work/nginx" -e "$work/nginx/error.log" -c "$work/nginx.conf" >"$work/nginx.log" 2>&1 &
nginx_pid=$!
pids+=("$nginx_pid")
wait_healthy "http://127.0.0.1:$port" "$nginx_pid" "$work/nginx/error.log"
echo "scale-out: nginx pid $nginx_pid at http://127.0.0.1:$port/ (files in $work)"
echo "scale-out: ready at http://127.0.0.1:$port/"

# Runs until nginx stops or a signal comes (a replica may die: nginx routes around it).
set +e
wait "$nginx_pid"
status=$?
echo "scale-out: nginx exited with status $status; its error log:" >&2
cat "$work/nginx/error.log" >&2
exit 1
