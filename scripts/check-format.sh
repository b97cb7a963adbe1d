#!/usr/bin/env bash
# Fails when a tracked C++ file is not clang-formatted (.clang-format at the root).
set -euo pipefail
cd "$(dirname "$0")/.."
files=$(git ls-files '*.cpp' '*.h' '*.hpp' '*.inc')
[ -n "$files" ] || exit 0
if ! echo "$files" | xargs clang-format --dry-run --Werror 2>/tmp/strahler-format.log; then
  grep -m 20 'error:' /tmp/strahler-format.log >&2 || true
  echo "check-format: run 'clang-format -i' on the files above" >&2
  exit 1
fi
