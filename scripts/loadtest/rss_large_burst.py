#!/usr/bin/env python3
# RSS of a real `strahler serve --cache-mb M` around a burst of 64 distinct 1024² EXR tiles of
# the default island (zoom 13, eight keep-alive clients): after start, peak, 1 s after.
# usage: scripts/loadtest/rss_large_burst.py build/release/bin/strahler M
import http.client, subprocess, sys, threading, time, re, os
binary, cache_mb = sys.argv[1], int(sys.argv[2])
env = dict(os.environ, STRAHLER_CACHE_DIR=os.environ.get("STRAHLER_CACHE_DIR", "/tmp/strahler-rss-cache"))
p = subprocess.Popen([binary, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2",
                      "--cache-mb", str(cache_mb)], stdout=subprocess.PIPE, env=env, text=True)
port = int(re.search(r":(\d+)/", p.stdout.readline()).group(1))
def rss():
    for l in open(f"/proc/{p.pid}/status"):
        if l.startswith("VmRSS"): return int(l.split()[1]) // 1024
tiles = [(x, y) for x in range(3464, 3472) for y in range(2984, 2992)]
peak = [0]
def run(part):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=120)
    for x, y in part:
        c.request("GET", f"/worlds/default/tiles/13/{x}/{y}.exr?size=1024")
        r = c.getresponse(); body = r.read(); assert r.status == 200, r.status
        peak[0] = max(peak[0], rss())
print("after load", rss(), "MB")
t0 = time.time()
ts = [threading.Thread(target=run, args=(tiles[k::8],)) for k in range(8)]
[t.start() for t in ts]; [t.join() for t in ts]
time.sleep(1)
c = http.client.HTTPConnection("127.0.0.1", port); c.request("GET", "/metrics")
m = c.getresponse().read().decode()
cb = [l for l in m.splitlines() if l.startswith("strahler_tile_cache_bytes ")]
print(f"64 tiles in {time.time()-t0:.1f} s; peak RSS {peak[0]} MB; after burst {rss()} MB; {cb}")
p.terminate(); p.wait()
