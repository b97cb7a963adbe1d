#!/usr/bin/env bash
# The asan preset (GCC, AddressSanitizer + UndefinedBehaviorSanitizer): builds what the tests
# need (no benchmarks) and runs the test suite, less the tests labelled `timing` (wall-time and
# resident-memory bounds of the real server, meaningless under the sanitizers' slowdown and
# shadow memory: tests/CMakeLists.txt) and the browser test (label `browser`: chromium's
# waits against a server several times slower). scripts/test must have run first (node
# modules for the decoder checks). Usage: scripts/test-asan.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# No benchmarks; one CTest test per test binary (each process start costs seconds here).
extra=(-DSTRAHLER_BUILD_BENCH=OFF -DSTRAHLER_TEST_PER_BINARY=ON)
# CI treats warnings as errors.
if [ "${CI:-}" = "true" ]; then extra+=(-DSTRAHLER_WERROR=ON); fi
cmake --preset asan "${extra[@]}" >/dev/null
cmake --build --preset asan -j "$(nproc)"
# halt_on_error: the first report fails its test; detect_leaks: LeakSanitizer at exit.
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --preset asan -j "$(nproc)" --timeout 900 -LE 'timing|browser'
