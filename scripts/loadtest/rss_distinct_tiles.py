#!/usr/bin/env python3
# RSS of a real `strahler serve --cache-mb M` filled with distinct far-sea 256² PNG tiles
# (zoom 18, four keep-alive clients): after start, after 400 tiles, after COUNT more.
# usage: scripts/loadtest/rss_distinct_tiles.py build/release/bin/strahler M COUNT
import http.client, subprocess, sys, threading, time, re, os
binary, cache_mb, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
env = dict(os.environ, STRAHLER_CACHE_DIR=os.environ.get("STRAHLER_CACHE_DIR", "/tmp/strahler-rss-cache"))
p = subprocess.Popen([binary, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2",
                      "--cache-mb", str(cache_mb)], stdout=subprocess.PIPE, env=env, text=True)
line = p.stdout.readline()
port = int(re.search(r":(\d+)/", line).group(1))
def rss():
    for l in open(f"/proc/{p.pid}/status"):
        if l.startswith("VmRSS"): return int(l.split()[1]) // 1024
def run(start, n):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    for i in range(start, start + n):
        c.request("GET", f"/worlds/default/tiles/18/{1000 + i}/5000.png")
        r = c.getresponse(); r.read()
        assert r.status == 200, r.status
def fill(start, n, threads=4):
    ts = [threading.Thread(target=run, args=(start + k * (n // threads), n // threads)) for k in range(threads)]
    [t.start() for t in ts]; [t.join() for t in ts]
print("after load", rss(), "MB")
t0 = time.time()
fill(0, 400)
base = rss(); print("after 400 tiles", base, "MB")
fill(400, count)
print(f"after {count} more tiles", rss(), "MB", f"{time.time()-t0:.1f} s")
c = http.client.HTTPConnection("127.0.0.1", port); c.request("GET", "/metrics")
m = c.getresponse().read().decode()
print([l for l in m.splitlines() if l.startswith("strahler_tile_cache_bytes") or l.startswith("strahler_tile_cache_entries")])
p.terminate(); p.wait()
