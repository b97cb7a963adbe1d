#!/usr/bin/python3
"""Independent reader for strahler's MBTiles files: Python's sqlite3, none of our code.

Opens <dir>/world.mbtiles (written by `strahler export`, see write_export_archives.sh) and checks
the MBTiles 1.3 metadata rows (name, format, bounds, center, minzoom, maxzoom, type, encoding),
the `tiles` view over the deduplicated map/images tables, the TMS row flip
(tile_row = 2^z - 1 - y), and the bytes of sampled tiles against `strahler tile` (the server's
code path) for the same XYZ tile. Then <dir>/world-vector.mbtiles (`--tile mvt`): format pbf, the
"json" row's vector_layers, and sampled tiles that gunzip to `strahler tile --format mvt`'s bytes.
Then <dir>/world-layer.mbtiles (`--layer vegetation --species bush`): format png, the rows naming
the layer, its parameters and encoding (no raster-dem encoding), and sampled tiles equal to
`strahler tile --layer vegetation --species bush`'s bytes.

Usage: check_mbtiles.py <dir> <strahler> <minzoom> <maxzoom>. Exits 1 on any mismatch.
"""
import math
import os
import re
import gzip
import json
import sqlite3
import subprocess
import sys
import tempfile


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def main():
    if len(sys.argv) != 5:
        fail("usage: check_mbtiles.py <dir> <strahler> <minzoom> <maxzoom>")
    folder, strahler, min_zoom, max_zoom = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    db = sqlite3.connect(f"file:{os.path.join(folder, 'world.mbtiles')}?mode=ro", uri=True)
    meta = dict(db.execute("SELECT name, value FROM metadata"))
    for key in ("name", "format", "bounds", "center", "minzoom", "maxzoom", "type", "encoding"):
        if key not in meta:
            fail(f"metadata has no '{key}' row: {meta}")
    if meta["format"] != "png" or meta["type"] != "baselayer" or meta["encoding"] != "mapbox":
        fail(f"metadata format/type/encoding: {meta}")
    # The world's content version, which the server's tile URLs carry as `v`.
    if not re.fullmatch(r"[0-9a-f]{16}", meta.get("worldVersion", "")):
        fail(f"metadata worldVersion: {meta.get('worldVersion')}")
    if (int(meta["minzoom"]), int(meta["maxzoom"])) != (min_zoom, max_zoom):
        fail(f"metadata zooms {meta['minzoom']}-{meta['maxzoom']}")
    west, south, east, north = (float(v) for v in meta["bounds"].split(","))
    lon, lat, zoom = meta["center"].split(",")
    if not (west < float(lon) < east and south < float(lat) < north and min_zoom <= int(zoom) <= max_zoom):
        fail(f"center {meta['center']} outside bounds {meta['bounds']}")

    tiles = db.execute("SELECT COUNT(*) FROM tiles").fetchone()[0]
    mapped = db.execute("SELECT COUNT(*) FROM map").fetchone()[0]
    images = db.execute("SELECT COUNT(*) FROM images").fetchone()[0]
    if tiles != mapped or images > mapped or images == 0:
        fail(f"tiles {tiles}, map {mapped}, images {images}")
    zooms = [z for (z,) in db.execute("SELECT DISTINCT zoom_level FROM tiles ORDER BY zoom_level")]
    if zooms != list(range(min_zoom, max_zoom + 1)):
        fail(f"zoom levels {zooms}")

    def tile_range(z):
        n = 2 ** z
        fx = lambda lon: (lon + 180) / 360 * n
        fy = lambda lat: (1 - math.asinh(math.tan(math.radians(lat))) / math.pi) / 2 * n
        x0 = min(max(math.floor(fx(west)), 0), n - 1)
        y0 = min(max(math.floor(fy(north)), 0), n - 1)
        return x0, min(max(math.ceil(fx(east)) - 1, x0), n - 1), y0, min(max(math.ceil(fy(south)) - 1, y0), n - 1)

    compared = 0
    with tempfile.TemporaryDirectory(dir=folder) as scratch:
        def server_tile(z, x, y):
            out = os.path.join(scratch, f"{z}-{x}-{y}.png")
            subprocess.run([strahler, "tile", os.path.join(folder, "world.world"), "--scheme", "web",
                            "--z", str(z), "--x", str(x), "--y", str(y), "--format", "png", "-o", out],
                           check=True, stderr=subprocess.DEVNULL)
            with open(out, "rb") as f:
                return f.read()

        for z in (min_zoom, (min_zoom + max_zoom) // 2, max_zoom):
            x0, x1, y0, y1 = tile_range(z)
            count = db.execute("SELECT COUNT(*) FROM tiles WHERE zoom_level = ?", (z,)).fetchone()[0]
            if count != (x1 - x0 + 1) * (y1 - y0 + 1):
                fail(f"zoom {z}: {count} tiles, expected {(x1 - x0 + 1) * (y1 - y0 + 1)}")
            for x, y in ((x0, y0), (x1, y1), ((x0 + x1) // 2, (y0 + y1) // 2)):
                tms = 2 ** z - 1 - y
                row = db.execute("SELECT tile_data FROM tiles WHERE zoom_level = ? AND tile_column = ? "
                                 "AND tile_row = ?", (z, x, tms)).fetchone()
                if row is None:
                    fail(f"no tile at zoom {z}, column {x}, TMS row {tms} (XYZ y {y})")
                if bytes(row[0]) != server_tile(z, x, y):
                    fail(f"tile {z}/{x}/{y} (TMS row {tms}) differs from strahler tile's bytes")
                compared += 1
    print(f"OK: {compared} tiles identical to strahler tile's, {tiles} tiles, {images} distinct")
    check_vector(folder, strahler)
    check_layer(folder, strahler)


def check_vector(folder, strahler):
    """world-vector.mbtiles: a pbf tileset of gzipped vector tiles with its layers listed."""
    db = sqlite3.connect(f"file:{os.path.join(folder, 'world-vector.mbtiles')}?mode=ro", uri=True)
    meta = dict(db.execute("SELECT name, value FROM metadata"))
    if meta.get("format") != "pbf" or "json" not in meta:
        fail(f"vector metadata: {meta}")
    layers = {layer["id"] for layer in json.loads(meta["json"])["vector_layers"]}
    if layers != {"water", "contours", "rivers", "features"}:
        fail(f"vector_layers {layers}")
    rows = db.execute("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles "
                      "ORDER BY length(tile_data) DESC LIMIT 3").fetchall()
    if not rows:
        fail("no vector tiles")
    with tempfile.TemporaryDirectory(dir=folder) as scratch:
        for z, x, tms, data in rows:
            y = 2 ** z - 1 - tms
            out = os.path.join(scratch, f"{z}-{x}-{y}.mvt")
            subprocess.run([strahler, "tile", os.path.join(folder, "world.world"), "--scheme", "web",
                            "--z", str(z), "--x", str(x), "--y", str(y), "--format", "mvt", "-o", out],
                           check=True, stderr=subprocess.DEVNULL)
            with open(out, "rb") as f:
                if gzip.decompress(bytes(data)) != f.read():
                    fail(f"vector tile {z}/{x}/{y} does not gunzip to strahler tile's bytes")
    print(f"OK: {len(rows)} vector tiles gunzip to strahler tile's, layers {sorted(layers)}")


def check_layer(folder, strahler):
    """world-layer.mbtiles: a png tileset of one layer's grey tiles, the layer named."""
    db = sqlite3.connect(f"file:{os.path.join(folder, 'world-layer.mbtiles')}?mode=ro", uri=True)
    meta = dict(db.execute("SELECT name, value FROM metadata"))
    if meta.get("format") != "png" or "encoding" in meta:
        fail(f"layer metadata format/encoding: {meta}")
    if meta.get("layer") != "vegetation" or meta.get("layerQuery") != "species=bush":
        fail(f"layer metadata layer/layerQuery: {meta}")
    if not meta.get("layerEncoding", "").startswith("strahler vegetation: 8-bit grey PNG"):
        fail(f"layer metadata layerEncoding: {meta}")
    zooms = [z for (z,) in db.execute("SELECT DISTINCT zoom_level FROM tiles ORDER BY zoom_level")]
    if zooms != [9, 10, 11]:
        fail(f"layer zoom levels {zooms}")
    # The largest tiles of each zoom: the ones with the most vegetation.
    rows = []
    for z in zooms:
        rows += db.execute("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles "
                           "WHERE zoom_level = ? ORDER BY length(tile_data) DESC LIMIT 2", (z,)).fetchall()
    with tempfile.TemporaryDirectory(dir=folder) as scratch:
        for z, x, tms, data in rows:
            y = 2 ** z - 1 - tms
            out = os.path.join(scratch, f"{z}-{x}-{y}.png")
            subprocess.run([strahler, "tile", os.path.join(folder, "world.world"), "--scheme", "web",
                            "--z", str(z), "--x", str(x), "--y", str(y), "--layer", "vegetation",
                            "--species", "bush", "-o", out], check=True, stderr=subprocess.DEVNULL)
            with open(out, "rb") as f:
                if bytes(data) != f.read():
                    fail(f"layer tile {z}/{x}/{y} differs from strahler tile --layer's bytes")
    print(f"OK: {len(rows)} layer tiles identical to strahler tile --layer's")


if __name__ == "__main__":
    main()
