#!/usr/bin/env bash
# Builds the libFuzzer harnesses (the fuzz preset: clang, ASan + UBSan) and runs each for SECONDS
# (default 60): scripts/fuzz.sh [SECONDS] [HARNESS ...]; or shares one budget of SECONDS
# between them (CI: .ci/run): scripts/fuzz.sh --total SECONDS [HARNESS ...]
# Harnesses: http_request coastline params mouths features world_file (default: all, one after another).
# Each starts from the committed seeds (tests/fuzz/corpus/, tests/fuzz/regressions/, test data)
# plus what earlier runs here found (build/fuzz/corpus/<harness>/, kept between runs). A crash,
# leak, sanitizer report or timeout leaves its input in build/fuzz/findings/<harness>/ and makes
# the script exit 1 after the remaining harnesses ran. docs/testing.md: running longer.
set -euo pipefail
cd "$(dirname "$0")/.."
total=""
if [ "${1:-}" = "--total" ]; then
  total="${2:?--total needs SECONDS}"
  shift 2
  seconds=""
else
  seconds="${1:-60}"
  shift || true
fi
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(http_request coastline params mouths features world_file)
fi
if [ -n "$total" ]; then
  seconds=$((total / ${#harnesses[@]}))
  [ "$seconds" -ge 1 ] || seconds=1
  echo "fuzz: ${total} s shared by ${#harnesses[@]} harnesses: ${seconds} s each"
fi

cmake --preset fuzz >/dev/null
targets=(make_world_seeds)
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build --preset fuzz -j "$(nproc)" --target "${targets[@]}"

build=build/fuzz
"$build/tests/fuzz/make_world_seeds" "$build/tests/fuzz/world-seeds"
failed=()
for h in "${harnesses[@]}"; do
  corpus="$build/corpus/$h"
  findings="$build/findings/$h"
  mkdir -p "$corpus" "$findings"
  seeds=()
  for dir in "tests/fuzz/corpus/$h" "tests/fuzz/regressions/$h"; do
    [ -d "$dir" ] && seeds+=("$dir")
  done
  options=()
  case "$h" in
    # Inputs up to twice the server's header limit (8 KB), so 414 and 431 are reached.
    http_request) options+=(-max_len=16384) ;;
    coastline) seeds+=(tests/data core/input/data) ;;
    world_file) seeds+=("$build/tests/fuzz/world-seeds") ;;
  esac
  echo "fuzz: $h for ${seconds} s"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: 2 GB is a leak or a bomb.
  if ! "$build/tests/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$findings/" "${options[@]}" "$corpus" "${seeds[@]}" \
      >"$build/fuzz-$h.log" 2>&1; then
    failed+=("$h")
    echo "fuzz: $h FAILED; the input is in $findings/, the report in $build/fuzz-$h.log:" >&2
    grep -E -A 30 "ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error|fuzz invariant|kInternal" \
      "$build/fuzz-$h.log" | head -60 >&2 || tail -40 "$build/fuzz-$h.log" >&2
  else
    grep -E "^stat::(number_of_executed_units|peak_rss_mb)|^Done|cov:" "$build/fuzz-$h.log" | tail -3
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
