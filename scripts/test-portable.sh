#!/usr/bin/env bash
# The portable preset (Release, STRAHLER_SIMD=none): the vector code's portable path only, as a
# target without x86 intrinsics builds it (no `#pragma GCC target` regions, no immintrin.h).
# The portable path's promise is the same bits as every instruction set, so this step builds
# and runs the tests that hold bits: the kernels against their scalar definitions (simd_test),
# the evaluator's and the filters' bit-identity across instruction sets and thread counts
# (tiling_test, construction_test, folds_test, drawn_relief_test), the world-file and tile
# goldens (store_test, generated_world_store_test, heightmap_encoder_test, quantized_mesh_test)
# and the served tiles' goldens and shared edges (tile_server_test, cesium_server_test,
# vector_tile_server_test). The rest of the suite sees the same bits through these; leaving it
# out keeps CI within its 40 minutes (docs/testing.md).
# scripts/test must have run first (node modules for the decoder checks).
set -euo pipefail
cd "$(dirname "$0")/.."
# No benchmarks; one CTest test per binary (the list below names binaries).
extra=(-DSTRAHLER_BUILD_BENCH=OFF -DSTRAHLER_TEST_PER_BINARY=ON)
# CI treats warnings as errors.
if [ "${CI:-}" = "true" ]; then extra+=(-DSTRAHLER_WERROR=ON); fi
cmake --preset portable "${extra[@]}" >/dev/null
tests=(simd_test tiling_test construction_test folds_test drawn_relief_test store_test
       generated_world_store_test heightmap_encoder_test quantized_mesh_test tile_server_test
       cesium_server_test vector_tile_server_test)
cmake --build --preset portable -j "$(nproc)" --target "${tests[@]}"
ctest --preset portable -j "$(nproc)" --timeout 900 --no-tests=error \
  -R "^($(IFS='|'; echo "${tests[*]}"))\$"
