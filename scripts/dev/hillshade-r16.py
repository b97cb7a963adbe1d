#!/usr/bin/env python3
"""Hillshade of a `strahler export-heightmap` r16 file, read with its sidecar JSON.

usage: hillshade-r16.py HEIGHTMAP.r16 OUT.png [STEP]
Reads the little-endian 16-bit samples independently of strahler, undoes the sidecar's row
order (row0 south for Unity), and writes an 8-bit grey PNG, north up, every STEP-th sample
(default 4), lit from the north-west at 45 degrees. Standard library only.
"""
import json
import math
import struct
import sys
import zlib
from pathlib import Path


def main():
    source, out = Path(sys.argv[1]), Path(sys.argv[2])
    step = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    side = json.loads(source.with_suffix(".json").read_text())
    n = side["width"]
    lo, hi = side["minHeight"], side["maxHeight"]
    raw = source.read_bytes()
    values = struct.unpack("<%dH" % (n * n), raw)
    rows = [values[r * n:(r + 1) * n] for r in range(n)]
    if side["row0"] == "south":
        rows.reverse()  # north up
    scale = (hi - lo) / 65535.0
    dx = side["metresPerPixel"]["x"] * step
    dy = side["metresPerPixel"]["y"] * step
    az, alt = math.radians(315), math.radians(45)
    light = (math.cos(alt) * math.sin(az), math.cos(alt) * math.cos(az), math.sin(alt))
    picked = [rows[r][::step] for r in range(0, n, step)]
    h, w = len(picked), len(picked[0])
    lines = []
    for r in range(h):
        line = bytearray([0])  # PNG filter: none
        for c in range(w):
            e = picked[r][min(c + 1, w - 1)] - picked[r][max(c - 1, 0)]
            s = picked[max(r - 1, 0)][c] - picked[min(r + 1, h - 1)][c]  # north minus south
            gx, gy = e * scale / (2 * dx), s * scale / (2 * dy)
            norm = math.sqrt(gx * gx + gy * gy + 1)
            shade = (-gx * light[0] - gy * light[1] + light[2]) / norm
            line.append(max(0, min(255, int(255 * shade))))
        lines.append(bytes(line))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(lines), 9)) + chunk(b"IEND", b"")
    out.write_bytes(png)


if __name__ == "__main__":
    main()
