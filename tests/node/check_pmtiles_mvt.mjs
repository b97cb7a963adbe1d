#!/usr/bin/env node
// Independent reader for strahler's vector tile PMTiles archives (`strahler export --tile mvt`):
// the `pmtiles` npm library reads <dir>/world-vector.pmtiles (tests/cli/write_export_archives.sh),
// the header must say MVT (tile type 1) gzipped (tile compression 2), the metadata must list the
// vector_layers, and sampled tiles must be `strahler tile --format mvt`'s bytes once gunzipped and
// decode with @mapbox/vector-tile into its layers.
//
// Usage: node check_pmtiles_mvt.mjs <dir> <strahler>. Exits 1 on any mismatch.

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";

import { fail, load, openPmtiles } from "./pmtiles_file.mjs";

const [dir, strahler] = process.argv.slice(2);
if (!dir || !strahler) fail("usage: node check_pmtiles_mvt.mjs <dir> <strahler>");
const { VectorTile } = await load("@mapbox/vector-tile");
const { PbfReader } = await load("pbf");

const archive = await openPmtiles(path.join(dir, "world-vector.pmtiles"));
const header = await archive.getHeader();
const metadata = await archive.getMetadata();
if (header.tileType !== 1) fail(`tile type ${header.tileType} (1: mvt)`);
if (header.tileCompression !== 2) fail(`tile compression ${header.tileCompression} (2: gzip)`);
if (metadata.format !== "pbf") fail(`metadata format ${metadata.format}`);
const ids = (metadata.vector_layers ?? []).map((l) => l.id).sort().join(",");
if (ids !== "contours,features,rivers,water") fail(`vector_layers ${ids}`);

const scratch = fs.mkdtempSync(path.join(dir, "vector-"));
const z = header.maxZoom;
const n = 2 ** z;
const x = Math.floor(((header.centerLon + 180) / 360) * n);
const lat = (header.centerLat * Math.PI) / 180;
const y = Math.floor(((1 - Math.asinh(Math.tan(lat)) / Math.PI) / 2) * n);
const stored = await archive.getZxy(z, x, y);
if (stored === undefined) fail(`tile ${z}/${x}/${y} is missing`);
let bytes = Buffer.from(stored.data);
if (bytes[0] === 0x1f && bytes[1] === 0x8b) bytes = zlib.gunzipSync(bytes); // if the reader left it
const out = path.join(scratch, "tile.mvt");
execFileSync(strahler, ["tile", path.join(dir, "world.world"), "--scheme", "web", "--z", `${z}`, "--x", `${x}`,
  "--y", `${y}`, "--format", "mvt", "-o", out], { stdio: ["ignore", "ignore", "pipe"] });
if (!bytes.equals(fs.readFileSync(out))) fail(`tile ${z}/${x}/${y} differs from strahler tile's bytes`);
const tile = new VectorTile(new PbfReader(bytes));
for (const id of ["contours", "rivers"]) if (!tile.layers[id]?.length) fail(`tile ${z}/${x}/${y} has no ${id}`);
fs.rmSync(scratch, { recursive: true, force: true });
console.log(`OK: centre tile ${z}/${x}/${y} is strahler tile's, layers ${Object.keys(tile.layers).join(", ")}; ` +
  `${header.numAddressedTiles} tiles`);
