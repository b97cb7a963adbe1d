#!/usr/bin/env bash
# The asan preset (GCC, AddressSanitizer + UndefinedBehaviorSanitizer) on the code that reads
# hostile input: the tests of the coastline, params and world-spec readers (input_test), the
# coastline repair, the world-file decoder and cache (store_test), the HTTP server core
# (http_server_test: real sockets), the tile cache, worker pool and trimmer (service_test),
# the PMTiles varint directories and the archive writers (archive_test), gzip's inflate with its
# bound (gzip_test), the HTTP fuzz harness's corpus through the router and the tile route
# parsers (fuzz_corpus_http_request), and geometry and base under them. These build a third of the sources, which keeps CI within
# its 90 minutes on a 2-core machine; the fuzz harnesses (scripts/fuzz.sh) cover the router
# and the decoders under the same sanitizers. `--all` builds and runs the whole suite instead,
# less the tests labelled `timing` (wall-time and resident-memory bounds of the real server,
# meaningless under the sanitizers' slowdown and shadow memory) and the browser test.
# scripts/test must have run first (node modules for the decoder checks of --all).
# Usage: scripts/test-asan.sh [--all]
set -euo pipefail
cd "$(dirname "$0")/.."
# No benchmarks; one CTest test per test binary (each process start costs seconds here).
extra=(-DSTRAHLER_BUILD_BENCH=OFF -DSTRAHLER_TEST_PER_BINARY=ON)
# CI treats warnings as errors.
if [ "${CI:-}" = "true" ]; then extra+=(-DSTRAHLER_WERROR=ON); fi
cmake --preset asan "${extra[@]}" >/dev/null
# halt_on_error: the first report fails its test; detect_leaks: LeakSanitizer at exit.
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
if [ "${1:-}" = "--all" ]; then
  cmake --build --preset asan -j "$(nproc)"
  ctest --preset asan -j "$(nproc)" --timeout 900 --no-tests=error -LE 'timing|browser'
  exit
fi
tests=(base_test geometry_test input_test repair_test store_test http_server_test service_test
       archive_test gzip_test)
# The HTTP harness's corpus replayed (the router and every tile route parser: tiles, Cesium
# terrain with its Accept header and ?extensions=, layers, vector and vegetation tiles).
cmake --build --preset asan -j "$(nproc)" --target "${tests[@]}" fuzz_http_request
ctest --preset asan -j "$(nproc)" --timeout 900 --no-tests=error \
  -R "^($(IFS='|'; echo "${tests[*]}")|fuzz_corpus_http_request)\$"
