#!/usr/bin/env bash
# Installs the Debian 12 packages strahler needs to build, run and test. Idempotent: does
# nothing when everything is present. Uses sudo when not run as root.
set -euo pipefail

packages=(
  g++ cmake ninja-build ccache pkg-config git clang-format
  # dpkg-shlibdeps, which CPack's Debian package (tests/cli/package_test.cpp) needs
  dpkg-dev
  libboost-dev libboost-system-dev
  libcgal-dev
  libopenimageio-dev
  libspng-dev libdraco-dev libeigen3-dev
  nlohmann-json3-dev
  # SQLite for MBTiles; python3 (below) reads them in tests/cli/check_mbtiles.py
  libsqlite3-dev
  libprotobuf-dev protobuf-compiler
  googletest libgtest-dev libbenchmark-dev
  # clang and its runtimes (libFuzzer, sanitizers) for the fuzz harnesses: scripts/fuzz.sh
  clang libclang-rt-14-dev
  chromium
  # the scale-out kit and its test (scripts/scale-out, tests/scale_out), the load test, and
  # tests/cli/check_mbtiles.py
  nginx-light wrk curl python3
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js runs the independent decoders in the tests; a machine may already have it from
# another source (e.g. NodeSource, whose nodejs bundles npm), so look for the commands.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
