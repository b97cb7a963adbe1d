#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release): scripts/build.sh [dev|release|asan]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
extra=()
# CI treats warnings as errors.
if [ "${CI:-}" = "true" ]; then extra+=(-DSTRAHLER_WERROR=ON); fi
cmake --preset "$preset" "${extra[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
