#!/usr/bin/env node
// Independent reader for strahler's PMTiles archives (the `pmtiles` npm library, as MapLibre
// and static hosts use it).
//
// Opens <dir>/world.pmtiles (written by `strahler export`, see tests/cli/write_export_archives.sh),
// checks its header (zooms, bounds, tile type, compression) and JSON metadata, then for every
// tile of zooms 0..6 in the bounds and the corners and centre of the deepest zoom, compares the
// archive's bytes with those `strahler tile` writes for the same z/x/y (the server's code path),
// decodes a corner tile (open sea) with pngjs and checks that it is all below sea level, and
// checks that a tile outside the bounds is not in the archive.
//
// Usage: node check_pmtiles.mjs <dir> <strahler> <minzoom> <maxzoom>. Exits 1 on any mismatch.

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";

import { fail, load, openPmtiles, webTileRange } from "./pmtiles_file.mjs";

const [dir, strahler, minZoomArg, maxZoomArg] = process.argv.slice(2);
if (!dir || !strahler || minZoomArg === undefined || maxZoomArg === undefined) {
  fail("usage: node check_pmtiles.mjs <dir> <strahler> <minzoom> <maxzoom>");
}
const minZoom = Number(minZoomArg);
const maxZoom = Number(maxZoomArg);
const { PNG } = await load("pngjs");

// A Source over a local file: the library asks for byte ranges, as it would over HTTP.
const archivePath = path.join(dir, "world.pmtiles");
const worldPath = path.join(dir, "world.world");
const archive = await openPmtiles(archivePath);
const header = await archive.getHeader();
const metadata = await archive.getMetadata();
let checks = 0;
function expect(condition, message) {
  if (!condition) fail(message);
  checks++;
}

expect(header.specVersion === 3, `spec version ${header.specVersion}`);
expect(header.minZoom === minZoom && header.maxZoom === maxZoom, `zooms ${header.minZoom}-${header.maxZoom}`);
expect(header.tileType === 2, `tile type ${header.tileType} (2: png)`);
expect(header.tileCompression === 1, `tile compression ${header.tileCompression} (1: none)`);
expect(header.internalCompression === 2, `internal compression ${header.internalCompression} (2: gzip)`);
expect(header.clustered, "not clustered");
expect(header.minLon < header.maxLon && header.minLat < header.maxLat, "empty bounds");
expect(header.minLon <= header.centerLon && header.centerLon <= header.maxLon, "centre outside the bounds");
expect(header.numTileContents <= header.numAddressedTiles, "more contents than tiles");
expect(header.rootDirectoryOffset + header.rootDirectoryLength <= 16384, "root directory beyond 16 KiB");
expect(metadata.encoding === "mapbox", `metadata encoding ${metadata.encoding}`);
expect(metadata.format === "png", `metadata format ${metadata.format}`);
expect(typeof metadata.name === "string" && metadata.name.length > 0, "metadata without a name");
expect(/^strahler /.test(metadata.generator ?? ""), `metadata generator ${metadata.generator}`);
expect(/^[0-9a-f]{32}$/.test(metadata.worldId ?? ""), `metadata worldId ${metadata.worldId}`);
// The world's content version, which the server's tile URLs carry as `v`.
expect(/^[0-9a-f]{16}$/.test(metadata.worldVersion ?? ""), `metadata worldVersion ${metadata.worldVersion}`);

const range = (z) => webTileRange(header, z);

const scratch = fs.mkdtempSync(path.join(dir, "tiles-"));
function serverTile(z, x, y) {
  const out = path.join(scratch, `${z}-${x}-${y}.png`);
  execFileSync(strahler, ["tile", worldPath, "--scheme", "web", "--z", `${z}`, "--x", `${x}`, "--y", `${y}`,
    "--format", "png", "-o", out], { stdio: ["ignore", "ignore", "pipe"] });
  return fs.readFileSync(out);
}

async function compare(z, x, y) {
  const stored = await archive.getZxy(z, x, y);
  expect(stored !== undefined, `tile ${z}/${x}/${y} is missing from the archive`);
  const expected = serverTile(z, x, y);
  expect(Buffer.from(stored.data).equals(expected),
    `tile ${z}/${x}/${y}: ${stored.data.byteLength} bytes in the archive differ from strahler tile's ${expected.length}`);
  return expected;
}

let compared = 0;
for (let z = minZoom; z <= Math.min(maxZoom, 6); z++) {
  const r = range(z);
  for (let x = r.x0; x <= r.x1; x++) for (let y = r.y0; y <= r.y1; y++) { await compare(z, x, y); compared++; }
}
const deep = range(maxZoom);
const cx = Math.floor((deep.x0 + deep.x1) / 2), cy = Math.floor((deep.y0 + deep.y1) / 2);
for (const [x, y] of [[deep.x0, deep.y0], [deep.x1, deep.y0], [deep.x0, deep.y1], [deep.x1, deep.y1], [cx, cy]]) {
  await compare(maxZoom, x, y);
  compared++;
}

// The north-west corner of the deepest zoom is open sea: every Terrain-RGB height below 0.
const sea = PNG.sync.read(await compare(maxZoom, deep.x0, deep.y0));
let highest = -Infinity;
for (let i = 0; i < sea.width * sea.height; i++) {
  const d = sea.data;
  highest = Math.max(highest, -10000 + (d[4 * i] * 65536 + d[4 * i + 1] * 256 + d[4 * i + 2]) * 0.1);
}
expect(highest < 0, `the sea tile ${maxZoom}/${deep.x0}/${deep.y0} rises to ${highest} m`);

const outside = await archive.getZxy(maxZoom, deep.x1 + 1, deep.y1 + 1);
expect(outside === undefined, "a tile outside the bounds is in the archive");

fs.rmSync(scratch, { recursive: true, force: true });
console.log(`OK: ${compared} tiles identical to strahler tile's, ${checks} checks, ` +
  `${header.numAddressedTiles} tiles, ${header.numTileContents} contents, ${header.numTileEntries} entries`);
