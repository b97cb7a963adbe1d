#!/usr/bin/env bash
# Throughput of `strahler export`: Mallorca (tests/data/mallorca.geojson, ~3,640 km²) to a
# PMTiles archive of Web Mercator zooms 0..ZOOM, once with --threads 1 and once with
# --threads 2. Prints, per run, the tiles, the wall and CPU time (user + system of the child,
# from wait4), tiles per second of wall time and per CPU-second (≈ per core) and the peak
# resident memory, and checks that both archives are byte-identical (the export is
# deterministic).
# Usage: scripts/bench/export.sh [STRAHLER] [ZOOM]
#   STRAHLER defaults to build/release/bin/strahler, ZOOM to 13.
#   The world is generated once into build/bench-export/ (strahler generate --coast ...).
set -euo pipefail
cd "$(dirname "$0")/../.."
strahler="$(realpath "${1:-build/release/bin/strahler}")"
zoom="${2:-13}"
[ -x "$strahler" ] || { echo "export bench: no program at $strahler (build it first)" >&2; exit 1; }
work=build/bench-export
mkdir -p "$work"
world="$work/mallorca.world"
if [ ! -f "$world" ]; then
  STRAHLER_CACHE_DIR="$work/cache" "$strahler" generate --quiet \
    --coast tests/data/mallorca.geojson -o "$world"
fi

/usr/bin/python3 - "$strahler" "$world" "$zoom" "$work" <<'PY'
import os, subprocess, sys, time

strahler, world, zoom, work = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
archives = []
for threads in (1, 2):
    out = os.path.join(work, f"mallorca-z{zoom}-t{threads}.pmtiles")
    start = time.monotonic()
    child = subprocess.Popen([strahler, "export", world, "--zooms", f"0-{zoom}", "--threads",
                              str(threads), "-o", out], stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    summary = child.stderr.read().strip().splitlines()[-1]
    if status != 0:
        sys.exit(f"export failed: {summary}")
    tiles = int(summary.split()[1])
    unique = int(summary.split("(")[1].split()[0])
    cpu = usage.ru_utime + usage.ru_stime
    print(f"--threads {threads}: {tiles} tiles ({unique} unique), wall {wall:.1f} s, CPU {cpu:.1f} s, "
          f"{tiles / wall:.0f} tiles/s, {tiles / cpu:.0f} tiles per CPU-second, "
          f"{os.path.getsize(out)} bytes, max RSS {usage.ru_maxrss / 1024:.0f} MB")
    archives.append(out)
same = open(archives[0], "rb").read() == open(archives[1], "rb").read()
print("archives byte-identical" if same else "ARCHIVES DIFFER")
sys.exit(0 if same else 1)
PY
