#!/usr/bin/python3
"""The scale-out kit run for real on loopback (issue 18): scripts/scale-out/run.sh starts three
`strahler serve` replicas behind Debian's nginx; this checks that

  1. the replicas answer the same tile with the same bytes and ETag (png, png16, terrarium,
     drc, glb);
  2. nginx caches: the second request for a tile is X-Cache-Status HIT, same bytes and ETag;
  3. If-None-Match through nginx gets 304, for a cached and for an uncached tile; /health,
     /metrics and /worlds are not cached; TileJSON names the host the client asked nginx for
     (nginx's X-Forwarded-Host, which the replicas trust from loopback);
  4. a 10 s wrk run through nginx has no error and no status other than 200/304;
  5. SIGKILL of a replica during a stream of uncached tiles through nginx loses no request:
     every one is 200 with the bytes and ETag the surviving replica gives; then the same for
     SIGTERM of a second replica (it drains: queued tiles get 503, which nginx retries);
  6. SIGTERM to run.sh stops every process of the kit and removes its scratch folder.

Usage: scale_out_test.py STRAHLER_BINARY SOURCE_DIR SCRATCH_DIR. Fails (never skips) when nginx,
wrk or curl is missing. Every wait is bounded; the whole takes about 30-40 s.
"""

import concurrent.futures
import http.client
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

READY_TIMEOUT_S = 90  # world generation (first run of a build folder) and three starts
WRK_SECONDS = 10
KILL_TILES = 128
KILL_AFTER = 20  # answers received before the replica is killed
STOP_TIMEOUT_S = 15  # a replica drains within 4 s plus its tile; nginx stops at once


def fail(message):
    print(f"FAIL: {message}", flush=True)
    raise SystemExit(1)


def check(condition, message):
    if not condition:
        fail(message)


class Reply:
    def __init__(self, status, headers, body):
        self.status = status
        self.headers = headers
        self.body = body

    def header(self, name):
        return self.headers.get(name.lower())


def get(port, path, headers=None, timeout=30, connection=None):
    """One GET on 127.0.0.1:port (on `connection` when given, kept alive)."""
    own = connection is None
    conn = connection or http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        conn.request("GET", path, headers=headers or {})
        response = conn.getresponse()
        body = response.read()
        return Reply(response.status, {k.lower(): v for k, v in response.getheaders()}, body)
    finally:
        if own:
            conn.close()


class Kit:
    """scripts/scale-out/run.sh as a child process, with the addresses it printed."""

    def __init__(self, binary, source_dir, cache_dir):
        env = dict(os.environ)
        env.update(
            STRAHLER_BIN=binary,
            STRAHLER_SCALE_PORT="0",
            STRAHLER_SCALE_REPLICA_PORT="0",
            STRAHLER_CACHE_DIR=cache_dir,
        )
        env.pop("STRAHLER_SCALE_DIR", None)
        self.lines = []
        self.process = subprocess.Popen(
            [os.path.join(source_dir, "scripts/scale-out/run.sh"), "3", "--threads", "2",
             "--workers", "2", "--cache-mb", "64"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
            start_new_session=True)
        self.replicas = []  # (pid, port)
        self.nginx = None  # (pid, port)
        self.scratch = None
        ready = threading.Event()
        threading.Thread(target=self._read, args=(ready,), daemon=True).start()
        if not ready.wait(READY_TIMEOUT_S) or self.nginx is None:
            self.stop()
            fail("the kit did not get ready within %d s; its output:\n%s"
                 % (READY_TIMEOUT_S, "\n".join(self.lines)))

    def _read(self, ready):
        for line in self.process.stdout:
            line = line.rstrip("\n")
            self.lines.append(line)
            print(f"  | {line}", flush=True)
            if m := re.match(r"scale-out: replica \d+ pid (\d+) at http://127\.0\.0\.1:(\d+)/", line):
                self.replicas.append((int(m[1]), int(m[2])))
            elif m := re.match(
                    r"scale-out: nginx pid (\d+) at http://127\.0\.0\.1:(\d+)/ \(files in (.*)\)$",
                    line):
                self.nginx = (int(m[1]), int(m[2]))
                self.scratch = m[3]
            elif line.startswith("scale-out: ready"):
                ready.set()
        ready.set()

    def stop(self):
        """SIGTERM, as Ctrl-C would; the time run.sh took to exit, or None if it had to be killed."""
        if self.process.poll() is not None:
            return 0.0
        start = time.monotonic()
        self.process.send_signal(signal.SIGTERM)
        try:
            self.process.wait(STOP_TIMEOUT_S)
            return time.monotonic() - start
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            for pid, _ in self.replicas + ([self.nginx] if self.nginx else []):
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            self.process.wait(5)
            return None


def web_tile(zoom, lon, lat):
    """The Web Mercator tile (x, y) holding a point."""
    n = 2 ** zoom
    x = int((lon + 180) / 360 * n)
    y = int((1 - math.asinh(math.tan(math.radians(lat))) / math.pi) / 2 * n)
    return x, y


# The default island's centre (scripts/loadtest/tile_lists.mjs).
LON, LAT = -27.35, 43.72


def identical_replicas(kit):
    x, y = web_tile(13, LON, LAT)
    paths = [f"/worlds/default/tiles/13/{x}/{y}.png",
             f"/worlds/default/tiles/13/{x + 1}/{y}.png16",
             f"/worlds/default/tiles/12/{x // 2}/{y // 2}.png?encoding=terrarium",
             f"/worlds/default/tiles/13/{x}/{y + 1}.drc",
             f"/worlds/default/tiles/13/{x - 1}/{y}.glb",
             "/worlds/default/local/3/2/5.glb?size=16"]
    for path in paths:
        replies = [get(port, path) for _, port in kit.replicas]
        for (_, port), reply in zip(kit.replicas, replies):
            check(reply.status == 200, f"replica :{port} {path}: status {reply.status}")
            check(reply.header("etag"), f"replica :{port} {path}: no ETag")
        first = replies[0]
        for (_, port), reply in zip(kit.replicas[1:], replies[1:]):
            check(reply.body == first.body,
                  f"{path}: replica :{port} sent other bytes ({len(reply.body)} vs {len(first.body)})")
            check(reply.header("etag") == first.header("etag"),
                  f"{path}: ETags differ: {reply.header('etag')} vs {first.header('etag')}")
        print(f"ok   replicas agree on {path}: {len(first.body)} bytes, ETag {first.header('etag')}")


def nginx_caches(kit):
    nginx_port = kit.nginx[1]
    x, y = web_tile(13, LON, LAT)
    for path in [f"/worlds/default/tiles/13/{x + 2}/{y + 2}.png",
                 f"/worlds/default/tiles/13/{x + 2}/{y + 2}.glb"]:
        direct = get(kit.replicas[0][1], path)
        first = get(nginx_port, path)
        # nginx commits a cache entry once the upstream's response is in: a client that reads
        # the last byte first may ask again before it is there (seen once in CI), so wait a
        # little for the HIT, never longer than 2 s.
        second = get(nginx_port, path)
        for _ in range(40):
            if second.header("x-cache-status") == "HIT":
                break
            time.sleep(0.05)
            second = get(nginx_port, path)
        check(first.status == 200 and second.status == 200,
              f"nginx {path}: statuses {first.status}, {second.status}")
        check(first.header("x-cache-status") == "MISS",
              f"nginx {path}: first X-Cache-Status {first.header('x-cache-status')}, want MISS")
        check(second.header("x-cache-status") == "HIT",
              f"nginx {path}: second X-Cache-Status {second.header('x-cache-status')}, want HIT")
        for reply in (first, second):
            check(reply.body == direct.body, f"nginx {path}: other bytes than the replica")
            check(reply.header("etag") == direct.header("etag"),
                  f"nginx {path}: ETag {reply.header('etag')}, replica {direct.header('etag')}")
            check(reply.header("cache-control") == direct.header("cache-control"),
                  f"nginx {path}: Cache-Control {reply.header('cache-control')}")
        print(f"ok   nginx {path}: MISS then HIT, same bytes and ETag as the replica")


def conditional_requests(kit):
    nginx_port = kit.nginx[1]
    x, y = web_tile(13, LON, LAT)
    cached = f"/worlds/default/tiles/13/{x + 2}/{y + 2}.png"  # nginx_caches left it in the cache
    fresh = f"/worlds/default/tiles/13/{x + 3}/{y + 3}.png"
    for path, want in [(cached, "HIT"), (fresh, "MISS")]:
        etag = get(kit.replicas[1][1], path).header("etag")
        reply = get(nginx_port, path, {"If-None-Match": etag})
        check(reply.status == 304, f"nginx {path} If-None-Match {etag}: status {reply.status}")
        check(reply.body == b"", f"nginx {path}: a 304 with a body")
        check(reply.header("etag") == etag, f"nginx {path}: 304 ETag {reply.header('etag')}")
        check(reply.header("x-cache-status") == want,
              f"nginx {path}: 304 X-Cache-Status {reply.header('x-cache-status')}, want {want}")
        other = get(nginx_port, path, {"If-None-Match": '"0000000000000000"'})
        check(other.status == 200, f"nginx {path}: another ETag got {other.status}, want 200")
        print(f"ok   nginx {path} If-None-Match: 304 ({want}); another ETag: 200")


def other_endpoints(kit):
    """What must not be cached stays fresh through nginx; TileJSON names the host asked for."""
    nginx_port = kit.nginx[1]
    for path in ["/health", "/metrics", "/worlds"]:
        replies = [get(nginx_port, path) for _ in range(2)]
        check(all(r.status == 200 for r in replies), f"nginx {path}: {[r.status for r in replies]}")
        check(replies[1].header("x-cache-status") != "HIT", f"nginx {path}: served from its cache")
    tilejson = get(nginx_port, "/worlds/default/tilejson.json")
    check(tilejson.status == 200, f"nginx tilejson: {tilejson.status}")
    base = f"http://127.0.0.1:{nginx_port}/worlds/default/tiles/"
    check(base.encode() in tilejson.body,
          f"TileJSON does not name nginx's address {base}: {tilejson.body[:300]!r}")
    # Another name for the same nginx (as behind DNS): the URLs follow it, through nginx only.
    named = get(nginx_port, "/worlds/default/tilejson.json", {"Host": "tiles.example.org:8443"})
    check(b'"http://tiles.example.org:8443/worlds/default/tiles/' in named.body,
          f"TileJSON does not follow the Host asked of nginx: {named.body[:300]!r}")
    print("ok   /health, /metrics, /worlds not cached by nginx; TileJSON's tiles name the host asked of nginx")


def wrk_run(kit, source_dir, scratch):
    nginx_port = kit.nginx[1]
    paths = []
    for zoom, radius in [(12, 6), (13, 10)]:
        cx, cy = web_tile(zoom, LON, LAT)
        paths += [f"/worlds/default/tiles/{zoom}/{cx + dx}/{cy + dy}.png"
                  for dy in range(-radius, radius + 1) for dx in range(-radius, radius + 1)]
    tile_list = os.path.join(scratch, "sweep.txt")
    with open(tile_list, "w") as out:
        out.write("\n".join(paths) + "\n")
    command = ["wrk", "-t2", "-c32", f"-d{WRK_SECONDS}s", "--timeout", "20s",
               "-s", os.path.join(source_dir, "scripts/loadtest/tiles.lua"),
               f"http://127.0.0.1:{nginx_port}"]
    result = subprocess.run(command, env=dict(os.environ, TILE_LIST=tile_list),
                            capture_output=True, text=True, timeout=WRK_SECONDS + 40)
    line = next((l for l in result.stdout.splitlines() if l.startswith("RESULT")), None)
    check(result.returncode == 0 and line,
          f"wrk: exit {result.returncode}, output:\n{result.stdout}{result.stderr}")
    figures = dict(kv.split("=") for kv in line.split()[1:])
    check(int(figures["requests"]) > len(paths),
          f"wrk: only {figures['requests']} requests in {WRK_SECONDS} s")
    check(figures["errors"] == "0" and figures["non2xx"] == "0",
          f"wrk through nginx: {figures['errors']} socket errors, {figures['non2xx']} statuses "
          f"other than 200/304:\n{result.stdout}")
    # wrk's own summary line too, e.g. "Non-2xx or 3xx responses: 3", "Socket errors: ..."
    check("Non-2xx" not in result.stdout and "Socket errors" not in result.stdout,
          f"wrk reported errors:\n{result.stdout}")
    print(f"ok   wrk through nginx, {len(paths)} tiles, 32 connections, {WRK_SECONDS} s: "
          f"{figures['requests']} requests, {float(figures['rps']):.0f} req/s, "
          f"p50 {figures['p50_ms']} ms, p99 {figures['p99_ms']} ms, 0 errors")


def stream_through_a_stop(kit, victim, how, paths, clients):
    """`paths` through nginx from `clients` keep-alive clients; after KILL_AFTER answers the
    replica `victim` (an index into kit.replicas) gets signal `how`. Every answer must be 200
    with the bytes and ETag the last replica (the survivor) gives directly. Returns the seconds
    taken and the lines of nginx's error log that name the victim."""
    nginx_port = kit.nginx[1]
    victim_pid, victim_port = kit.replicas[victim]
    survivor_port = kit.replicas[-1][1]
    answers = {}
    lock = threading.Lock()
    signalled = threading.Event()

    def client(share):
        conn = http.client.HTTPConnection("127.0.0.1", nginx_port, timeout=30)
        try:
            for path in share:
                try:
                    reply = get(nginx_port, path, connection=conn)
                except (OSError, http.client.HTTPException) as error:
                    conn.close()
                    conn = http.client.HTTPConnection("127.0.0.1", nginx_port, timeout=30)
                    reply = Reply(None, {}, repr(error).encode())
                with lock:
                    answers[path] = reply
                    if len(answers) == KILL_AFTER and not signalled.is_set():
                        os.kill(victim_pid, how)
                        signalled.set()
        finally:
            conn.close()

    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(clients) as pool:
        for future in [pool.submit(client, paths[i::clients]) for i in range(clients)]:
            future.result(timeout=120)
    took = time.monotonic() - start
    name = signal.Signals(how).name
    check(signalled.is_set(), f"replica :{victim_port} never got {name}")
    bad = {p: r.status for p, r in answers.items() if r.status != 200}
    check(len(answers) == len(paths) and not bad,
          f"requests lost when replica :{victim_port} got {name}: {len(bad)} of {len(paths)}: "
          + ", ".join(f"{p} -> {s}" for p, s in list(bad.items())[:10]))
    for path, reply in answers.items():
        direct = get(survivor_port, path)
        check(direct.status == 200, f"survivor :{survivor_port} {path}: {direct.status}")
        check(reply.body == direct.body, f"{path}: nginx's bytes differ from the survivor's")
        check(reply.header("etag") == direct.header("etag"),
              f"{path}: ETag {reply.header('etag')} vs the survivor's {direct.header('etag')}")
    with open(os.path.join(kit.scratch, "nginx/error.log")) as log:
        failures = [l for l in log if f"127.0.0.1:{victim_port}" in l]
    return took, failures


def kinds(failures):
    """nginx's error lines summed up by what failed, e.g. {"connect() failed (111: ...)": 3}."""
    counts = {}
    for line in failures:
        m = re.search(r"\*\d+ (.*?)(?: while |, client:)", line)
        kind = m[1] if m else line.strip()
        counts[kind] = counts.get(kind, 0) + 1
    return counts


def zoom_tiles(zoom, count, formats):
    """`count` distinct tiles nothing asked for before, around the island's centre at `zoom`,
    cycling through `formats` (extension and query)."""
    cx, cy = web_tile(zoom, LON, LAT)
    return [f"/worlds/default/tiles/{zoom}/{cx - 8 + i % 16}/{cy - 5 + i // 16}."
            + formats[i % len(formats)] for i in range(count)]


def kill_a_replica(kit):
    """SIGKILL: in-flight requests see a reset, later ones a refused connection."""
    victim_port = kit.replicas[0][1]
    # 512² png and 128² drc at zoom 14 from eight clients: tens to hundreds of ms each, so the
    # victim is computing some when it dies.
    paths = zoom_tiles(14, KILL_TILES, ["png?size=512", "drc?size=128"])
    took, failures = stream_through_a_stop(kit, 0, signal.SIGKILL, paths, 8)
    # The kill must have been felt: nginx logged failures talking to the dead replica.
    check(failures, f"nginx's error log names no failure of the killed replica :{victim_port}")
    print(f"ok   SIGKILL of replica :{victim_port} after {KILL_AFTER} of {len(paths)} distinct "
          f"uncached tiles: all {len(paths)} answered 200 with the survivor's bytes and ETags "
          f"in {took:.1f} s; nginx retried after {kinds(failures)}")


def drain_a_replica(kit):
    """SIGTERM: the replica answers its queued tiles 503 and closes; nginx retries them."""
    victim_pid, victim_port = kit.replicas[1]
    # Larger tiles at zoom 15 and eight clients, so tiles are queued on the victim when it
    # begins to drain.
    paths = zoom_tiles(15, KILL_TILES, ["png?size=512", "glb?size=128"])
    took, failures = stream_through_a_stop(kit, 1, signal.SIGTERM, paths, 8)
    deadline = time.monotonic() + 8
    while alive(victim_pid) and time.monotonic() < deadline:
        time.sleep(0.1)
    check(not alive(victim_pid), f"replica :{victim_port} still running 8 s after SIGTERM")
    print(f"ok   SIGTERM of replica :{victim_port} after {KILL_AFTER} of {len(paths)} distinct "
          f"uncached tiles: all answered 200 with the survivor's bytes and ETags in {took:.1f} s "
          f"(nginx's errors: {kinds(failures)}); the replica exited")


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # A zombie (not yet reaped by its parent) is gone for our purposes.
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split(") ")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    binary, source_dir, scratch = sys.argv[1:]
    missing = [tool for tool in ("wrk", "curl") if not shutil.which(tool)]
    if not (shutil.which("nginx") or os.access("/usr/sbin/nginx", os.X_OK)):
        missing.append("nginx")
    if missing:
        fail(f"{', '.join(missing)} not found: the scale-out test needs them "
             "(scripts/install-deps.sh installs nginx-light, wrk and curl)")
    os.makedirs(scratch, exist_ok=True)
    began = time.monotonic()
    kit = Kit(binary, source_dir, os.path.join(scratch, "cache"))
    stopped = False
    try:
        check(len(kit.replicas) == 3, f"want 3 replicas, the kit printed {kit.replicas}")
        identical_replicas(kit)
        nginx_caches(kit)
        conditional_requests(kit)
        other_endpoints(kit)
        wrk_run(kit, source_dir, scratch)
        kill_a_replica(kit)
        drain_a_replica(kit)
        pids = [pid for pid, _ in kit.replicas] + [kit.nginx[0]]
        took = kit.stop()
        stopped = True
        check(took is not None, f"run.sh did not exit within {STOP_TIMEOUT_S} s of SIGTERM")
        check(not any(alive(pid) for pid in pids),
              f"processes left after SIGTERM: {[pid for pid in pids if alive(pid)]}")
        check(not os.path.exists(kit.scratch), f"scratch folder {kit.scratch} left behind")
        print(f"ok   SIGTERM: run.sh stopped nginx and the replicas in {took:.1f} s and removed "
              f"{kit.scratch}")
    finally:
        if not stopped:
            kit.stop()
    print(f"PASS in {time.monotonic() - began:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
