#!/usr/bin/env python3
# Shutdown under load: a real `strahler serve` (2 I/O threads, 2 workers) gets CONNS concurrent
# requests for distinct 1024² EXR tiles of the default island (zoom 15, so the cache cannot
# help), then SIGTERM after LOAD seconds. Reports the time from SIGTERM to the exit, the exit
# code and the statuses the clients received.
# usage: scripts/loadtest/sigterm_under_load.py build/release/bin/strahler [CONNS=300] [LOAD=2]
import collections, os, re, signal, socket, subprocess, sys, threading, time
binary = sys.argv[1]
conns = int(sys.argv[2]) if len(sys.argv) > 2 else 300
load_s = float(sys.argv[3]) if len(sys.argv) > 3 else 2.0
env = dict(os.environ, STRAHLER_CACHE_DIR=os.environ.get("STRAHLER_CACHE_DIR", "/tmp/strahler-rss-cache"))
p = subprocess.Popen([binary, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2"],
                     stdout=subprocess.PIPE, env=env, text=True)
port = int(re.search(r":(\d+)/", p.stdout.readline()).group(1))
statuses = collections.Counter()
lock = threading.Lock()

def client(i):
    target = f"/worlds/default/tiles/15/{13856 + i % 32}/{11936 + i // 32}.exr?size=1024"
    status = "none"
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=60)
        s.sendall(f"GET {target} HTTP/1.1\r\nHost: x\r\n\r\n".encode())
        head = s.recv(64)
        status = head[9:12].decode() if head.startswith(b"HTTP/1.1 ") else "none"
        while s.recv(1 << 20):
            pass
        s.close()
    except OSError as e:
        status = type(e).__name__
    with lock:
        statuses[status] += 1

ts = [threading.Thread(target=client, args=(i,)) for i in range(conns)]
[t.start() for t in ts]
time.sleep(load_s)
t0 = time.time()
p.send_signal(signal.SIGTERM)
code = p.wait()
exit_s = time.time() - t0
[t.join() for t in ts]
print(f"{conns} connections of distinct 1024² EXR tiles, SIGTERM after {load_s:.0f} s of load")
print(f"exit {exit_s:.2f} s after SIGTERM, exit code {code}")
print(f"statuses: {dict(statuses)}")
