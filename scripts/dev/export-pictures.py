#!/usr/bin/env python3
"""Pictures of `strahler export-heightmap` files for docs/game-engines.md, read back
independently of strahler (standard library only: its own r16 reader and PNG decoder).

usage: export-pictures.py pair PLAIN.r16 ERODED.r16 OUT.png [STEP]
         hillshades of two r16 exports side by side (north up, lit from the north-west)
       export-pictures.py splat HEIGHTMAP.r16 OUT.png [STEP]
         the sidecar's splat maps blended in one colour per layer (Ground tan, Rock grey,
         Sediment ochre, Vegetation green, Water blue), shaded by the heightmap
Every STEP-th sample (default 2). Unity's alphamaps are (N-1)^2 and its RAW south-first: both
are handled from the sidecar.
"""
import json
import math
import struct
import sys
import zlib
from pathlib import Path

COLOURS = {"Ground": (196, 170, 120), "Rock": (130, 128, 124), "Sediment": (214, 160, 60),
           "Vegetation": (52, 120, 40), "Water": (40, 90, 200)}


def read_r16(path):
    """(rows north first, sidecar) of an r16 export."""
    side = json.loads(path.with_suffix(".json").read_text())
    n = side["width"]
    values = struct.unpack("<%dH" % (n * n), path.read_bytes())
    lo, hi = side["minHeight"], side["maxHeight"]
    rows = [[lo + v / 65535.0 * (hi - lo) for v in values[r * n:(r + 1) * n]] for r in range(n)]
    if side["row0"] == "south":
        rows.reverse()
    return rows, side


def read_png(path):
    """(width, height, channels, rows of bytes) of an 8-bit grey or RGBA, non-interlaced PNG."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (0, 6) and interlace == 0, path
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 1 if colour == 0 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for r in range(height):
        kind, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def shade(rows, side, step):
    """Hillshade in [0, 1] of every step-th sample, lit from the north-west at 45 degrees."""
    picked = [row[::step] for row in rows[::step]]
    h, w = len(picked), len(picked[0])
    dx = side["metresPerPixel"]["x"] * step
    dy = side["metresPerPixel"]["y"] * step
    az, alt = math.radians(315), math.radians(45)
    light = (math.cos(alt) * math.sin(az), math.cos(alt) * math.cos(az), math.sin(alt))
    out = []
    for r in range(h):
        line = []
        for c in range(w):
            gx = (picked[r][min(c + 1, w - 1)] - picked[r][max(c - 1, 0)]) / (2 * dx)
            gy = (picked[max(r - 1, 0)][c] - picked[min(r + 1, h - 1)][c]) / (2 * dy)
            norm = math.sqrt(gx * gx + gy * gy + 1)
            line.append(max(0.0, min(1.0, (-gx * light[0] - gy * light[1] + light[2]) / norm)))
        out.append(line)
    return out


def write_png(path, pixels):
    """An 8-bit RGB PNG of rows of (r, g, b)."""
    h, w = len(pixels), len(pixels[0])
    raw = b"".join(b"\x00" + bytes(v for p in row for v in p) for row in pixels)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                     chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def pair(plain, eroded, out, step):
    left = shade(*read_r16(plain), step)
    right = shade(*read_r16(eroded), step)
    grey = lambda s: (int(255 * s),) * 3
    write_png(out, [[grey(s) for s in a] + [(255, 255, 255)] * 8 + [grey(s) for s in b]
                    for a, b in zip(left, right)])


def splat(heightmap, out, step):
    rows, side = read_r16(heightmap)
    relief = shade(rows, side, step)
    info = side["splat"]
    layers = info["layers"]
    weights = {}  # layer -> rows of bytes, north up
    folder = heightmap.parent
    if info["files"][0].endswith("_alphamap0.png"):
        for m, name in enumerate(info["files"]):
            _, _, _, rgba = read_png(folder / name)
            for k in range(4):
                if 4 * m + k < len(layers):
                    weights[layers[4 * m + k]] = [row[k::4] for row in rgba]
    else:
        for name, layer in zip(info["files"], layers):
            weights[layer] = read_png(folder / name)[3]
    side_px = info["width"]
    pixels = []
    for r, shade_row in enumerate(relief):
        line = []
        for c, s in enumerate(shade_row):
            rr, cc = min(r * step, side_px - 1), min(c * step, side_px - 1)
            mix = [0.0, 0.0, 0.0]
            for layer in layers:
                w = weights[layer][rr][cc] / 255.0
                for i in range(3):
                    mix[i] += w * COLOURS[layer][i]
            line.append(tuple(int(v * (0.45 + 0.55 * s)) for v in mix))
        pixels.append(line)
    write_png(out, pixels)


def main():
    step = 2
    if sys.argv[1] == "pair":
        step = int(sys.argv[5]) if len(sys.argv) > 5 else step
        pair(Path(sys.argv[2]), Path(sys.argv[3]), Path(sys.argv[4]), step)
    elif sys.argv[1] == "splat":
        step = int(sys.argv[4]) if len(sys.argv) > 4 else step
        splat(Path(sys.argv[2]), Path(sys.argv[3]), step)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
