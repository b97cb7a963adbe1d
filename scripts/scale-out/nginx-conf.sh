#!/usr/bin/env bash
# Renders scripts/scale-out/nginx.conf.in, the one nginx configuration of the scale-out kit:
#   nginx-conf.sh docker                      # docker/nginx.conf (compose's two replicas)
#   nginx-conf.sh loopback DIR PORT HOST:PORT...  # scripts/scale-out/run.sh: nginx as an
#                                             # unprivileged foreground process, its pid, logs,
#                                             # temporary files and cache under DIR
# Only where nginx runs differs (process settings, listen address, cache path, upstream
# servers); the proxying, hashing, caching and retry rules are the template's, for both.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

usage() { echo "usage: $0 docker | loopback DIR PORT HOST:PORT..." >&2; exit 2; }
[ $# -ge 1 ] || usage
case "$1" in
  docker)
    [ $# -eq 1 ] || usage
    main="# Generated from scripts/scale-out/nginx.conf.in by \`scripts/scale-out/nginx-conf.sh docker\`:
# edit the template, not this file."
    http="  # The image's defaults: error log to stderr, access log to stdout, temporary files in
  # /var/cache/nginx."
    cache_path=/tmp/strahler-cache
    listen=80
    upstreams=(strahler-a:8080 strahler-b:8080)
    ;;
  loopback)
    [ $# -ge 4 ] || usage
    dir="$2"
    listen="127.0.0.1:$3"
    shift 3
    upstreams=("$@")
    main="daemon off;
pid $dir/nginx.pid;
error_log $dir/error.log warn;"
    # No access log: the load test compares nginx with a replica, which runs --quiet.
    http="  access_log off;
  client_body_temp_path $dir/client_body;
  proxy_temp_path $dir/proxy;
  fastcgi_temp_path $dir/fastcgi;
  uwsgi_temp_path $dir/uwsgi;
  scgi_temp_path $dir/scgi;"
    cache_path="$dir/cache"
    ;;
  *) usage ;;
esac

servers=""
for upstream in "${upstreams[@]}"; do
  servers+="${servers:+$'\n'}    server $upstream;"
done
# Every replica may be tried once, so a request is lost only when all of them fail.
tries=${#upstreams[@]}

while IFS= read -r line || [ -n "$line" ]; do
  [[ "$line" == "##"* ]] && continue
  line="${line//@MAIN@/$main}"
  line="${line//@HTTP@/$http}"
  line="${line//@CACHE_PATH@/$cache_path}"
  line="${line//@SERVERS@/$servers}"
  line="${line//@LISTEN@/$listen}"
  line="${line//@TRIES@/$tries}"
  printf '%s\n' "$line"
done <"$here/nginx.conf.in"
