#!/usr/bin/env bash
# The portable preset (Release, STRAHLER_SIMD=none): the vector code's portable path only, as a
# target without x86 intrinsics builds it (no `#pragma GCC target` regions, no immintrin.h).
# Runs the suite on it, less what this path cannot change: the browser test, the scale-out kit
# and the timing tests (the real server under load: their bounds are sized for the vector
# build), the Debian package tests and the fuzz corpus replays (parsers only).
# Tiles, golden files and bit-identity tests must pass unchanged: the portable path computes
# the same bits as every instruction set.
# scripts/test must have run first (node modules for the decoder checks).
set -euo pipefail
cd "$(dirname "$0")/.."
extra=(-DSTRAHLER_BUILD_BENCH=OFF)
# CI treats warnings as errors.
if [ "${CI:-}" = "true" ]; then extra+=(-DSTRAHLER_WERROR=ON); fi
cmake --preset portable "${extra[@]}" >/dev/null
cmake --build --preset portable -j "$(nproc)"
ctest --preset portable -j "$(nproc)" --timeout 600 -LE 'browser|scale_out|timing|fuzz' \
  -E '^Package\.'
