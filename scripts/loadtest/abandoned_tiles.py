#!/usr/bin/env python3
# Requests nobody waits for: CONNS clients each ask a real `strahler serve` (2 I/O threads,
# 2 workers) for a distinct 1024² EXR tile (zoom 15) and close their connection after WAIT
# seconds, as a browser cancels the tiles of a map panned away. Reports from /metrics how many
# tiles were computed and how many queued computations were skipped.
# usage: scripts/loadtest/abandoned_tiles.py build/release/bin/strahler [CONNS=200] [WAIT=0.5]
import os, re, socket, subprocess, sys, time, urllib.request
binary = sys.argv[1]
conns = int(sys.argv[2]) if len(sys.argv) > 2 else 200
wait_s = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
env = dict(os.environ, STRAHLER_CACHE_DIR=os.environ.get("STRAHLER_CACHE_DIR", "/tmp/strahler-rss-cache"))
p = subprocess.Popen([binary, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2",
                      "--max-client-connections", "0"], stdout=subprocess.PIPE, env=env, text=True)
port = int(re.search(r":(\d+)/", p.stdout.readline()).group(1))
socks = []
for i in range(conns):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    s.sendall(f"GET /worlds/default/tiles/15/{13856 + i % 32}/{11936 + i // 32}.exr?size=1024 HTTP/1.1\r\nHost: x\r\n\r\n".encode())
    socks.append(s)
time.sleep(wait_s)
for s in socks:
    s.close()
t0 = time.time()
def metric(name):
    text = urllib.request.urlopen(f"http://127.0.0.1:{port}/metrics", timeout=10).read().decode()
    return float(re.search(rf"^{name} (\S+)$", text, re.M).group(1))
while metric("strahler_workers_busy") > 0 or metric("strahler_worker_queue_depth") > 0:
    time.sleep(0.05)
print(f"{conns} requests for distinct 1024² EXR tiles, clients gone after {wait_s} s")
print(f"computed {metric('strahler_tile_computations_total'):.0f}, skipped "
      f"{metric('strahler_tile_computations_cancelled_total'):.0f}; workers idle "
      f"{time.time() - t0:.2f} s after the clients left")
p.terminate(); p.wait()
