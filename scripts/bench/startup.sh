#!/usr/bin/env bash
# Start-up of the strahler program against `python3 -S -c pass`, measured in the same run
# (issue 18's yardstick: `strahler --help` and `strahler info WORLD` within 3x of it). The
# commands run in turn, ROUNDS times (interleaved, so that a change of load on a shared machine
# hits them alike); the script prints each one's median wall time and median CPU time (user +
# system of the child, from wait4), and the ratios of strahler's to python's. `tile png` and
# `tile exr` (256² web tiles) are shown for scale: exr loads the OpenImageIO module.
# Usage: scripts/bench/startup.sh [STRAHLER] [ROUNDS]
#   STRAHLER defaults to build/release/bin/strahler, ROUNDS to 30.
#   WORLD: $STRAHLER_BENCH_WORLD, else the default island, generated into build/bench-startup/.
#   PYTHON: $PYTHON, else /usr/bin/python3 (the interpreter itself: a pyenv shim is a shell
#   script that takes ten times as long).
set -euo pipefail
cd "$(dirname "$0")/../.."
strahler="$(realpath "${1:-build/release/bin/strahler}")"
rounds="${2:-30}"
python="${PYTHON:-/usr/bin/python3}"
[ -x "$strahler" ] || { echo "startup: no program at $strahler (build it first)" >&2; exit 1; }
work=build/bench-startup
mkdir -p "$work"
world="${STRAHLER_BENCH_WORLD:-$work/island.world}"
if [ ! -f "$world" ]; then
  STRAHLER_CACHE_DIR="$work/cache" "$strahler" generate --quiet -o "$world"
fi

"$python" - "$strahler" "$rounds" "$python" "$world" "$work" <<'EOF'
import os, statistics, subprocess, sys, time

strahler, rounds, python, world, work = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
tile = [strahler, "tile", world, "--scheme", "web", "--z", "12", "--x", "1732", "--y", "1492"]
commands = [
    ("python3 -S -c pass", [python, "-S", "-c", "pass"]),
    ("strahler --help", [strahler, "--help"]),
    ("strahler info WORLD", [strahler, "info", world]),
    ("strahler tile --format png", tile + ["--format", "png", "-o", os.path.join(work, "t.png")]),
    ("strahler tile --format exr", tile + ["--format", "exr", "-o", os.path.join(work, "t.exr")]),
]

def run(argv):
    """Wall seconds and CPU seconds (user + system) of one run of argv."""
    start = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        sys.exit("startup: %s exited with %d" % (" ".join(argv), child.returncode))
    return wall, usage.ru_utime + usage.ru_stime

for _, argv in commands:  # warm the page cache
    run(argv)
walls = {name: [] for name, _ in commands}
cpus = {name: [] for name, _ in commands}
for _ in range(rounds):
    for name, argv in commands:
        wall, cpu = run(argv)
        walls[name].append(wall)
        cpus[name].append(cpu)

base_wall = statistics.median(walls[commands[0][0]])
base_cpu = statistics.median(cpus[commands[0][0]])
print("%d rounds; medians; ratio = strahler / python3 -S -c pass (target for --help and info: <= 3)" % rounds)
print("%-28s %9s %9s %11s %10s" % ("command", "wall ms", "CPU ms", "wall ratio", "CPU ratio"))
for name, _ in commands:
    wall = statistics.median(walls[name])
    cpu = statistics.median(cpus[name])
    print("%-28s %9.1f %9.1f %11.2f %10.2f" % (name, wall * 1e3, cpu * 1e3, wall / base_wall, cpu / base_cpu))
EOF
