#!/usr/bin/env python3
# One client cannot take every connection: a real `strahler serve` (default caps) under SLOW
# reconnecting slowloris connections from 127.0.0.1 (each sends half a request header and
# stalls; a connection the server closes is reopened at once), while 200 normal requests come
# from 127.0.0.2 (eight at a time, a fresh connection each). Reports the statuses of the
# normal requests, the connections the server holds (its open sockets), how many slow
# connections it shed, and what a lone stalled header receives after the 10 s header timeout.
# usage: scripts/loadtest/slow_clients.py build/release/bin/strahler [SLOW=1100] [EXTRA serve args]
import collections, os, re, selectors, socket, subprocess, sys, threading, time
binary = sys.argv[1]
slow_count = int(sys.argv[2]) if len(sys.argv) > 2 else 1100
extra = sys.argv[3:]
env = dict(os.environ, STRAHLER_CACHE_DIR=os.environ.get("STRAHLER_CACHE_DIR", "/tmp/strahler-rss-cache"))
p = subprocess.Popen([binary, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2",
                      *extra], stdout=subprocess.PIPE, env=env, text=True)
port = int(re.search(r":(\d+)/", p.stdout.readline()).group(1))
baseline_fds = len(os.listdir(f"/proc/{p.pid}/fd"))

def server_sockets():
    return len(os.listdir(f"/proc/{p.pid}/fd")) - baseline_fds

SLOW = b"GET /worlds/default/tiles/3/4/2.png HTTP/1.1\r\nHost: x\r\nX-Slow: "
stop = threading.Event()
shed = collections.Counter()

def slowloris():
    sel = selectors.DefaultSelector()
    def open_one():
        s = socket.socket()
        s.bind(("127.0.0.1", 0))
        s.setblocking(False)
        s.connect_ex(("127.0.0.1", port))
        sel.register(s, selectors.EVENT_WRITE, "connecting")
    for _ in range(slow_count):
        open_one()
    while not stop.is_set():
        for key, _ in sel.select(timeout=0.1):
            s = key.fileobj
            if key.data == "connecting":
                if s.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR) != 0:
                    sel.unregister(s); s.close(); open_one(); continue
                try:
                    s.send(SLOW)
                except OSError:
                    pass
                sel.modify(s, selectors.EVENT_READ, "stalled")
                continue
            try:
                data = s.recv(4096)
            except OSError:
                data = b""
            status = data[9:12].decode(errors="replace") if data.startswith(b"HTTP/1.1 ") else "closed"
            shed[status] += 1
            sel.unregister(s); s.close(); open_one()  # reconnect

t = threading.Thread(target=slowloris); t.start()
time.sleep(3)
held_before = server_sockets()

statuses = collections.Counter()
lock = threading.Lock()
def normal(k):
    for i in range(k, 200, 8):
        s = socket.create_connection(("127.0.0.1", port), timeout=10, source_address=("127.0.0.2", 0))
        try:
            s.sendall(b"GET /worlds/default/tiles/3/4/2.png HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            data = b""
            while True:
                chunk = s.recv(65536)
                if not chunk: break
                data += chunk
            status = data[9:12].decode() if data else "none"
        except OSError as e:
            status = type(e).__name__
        finally:
            s.close()
        with lock: statuses[status] += 1
t0 = time.time()
ns = [threading.Thread(target=normal, args=(k,)) for k in range(8)]
[n.start() for n in ns]; [n.join() for n in ns]
normal_s = time.time() - t0
held_after = server_sockets()

lone = socket.create_connection(("127.0.0.1", port), timeout=15, source_address=("127.0.0.3", 0))
lone.sendall(SLOW)
t1 = time.time(); reply = lone.recv(4096); waited = time.time() - t1
lone.close()
stop.set(); t.join()
p.terminate(); p.wait()
print(f"slow connections kept open by the client: {slow_count} (from 127.0.0.1)")
print(f"server sockets held: {held_before} after 3 s of slowloris, {held_after} after the normal requests")
print(f"normal requests from 127.0.0.2: {dict(statuses)} in {normal_s:.2f} s")
print(f"slow connections shed meanwhile (what they received): {dict(shed)}")
first_line = reply.split(b"\r\n")[0].decode()
print(f"lone stalled header from 127.0.0.3: {first_line!r} after {waited:.1f} s")
