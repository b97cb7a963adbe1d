#!/usr/bin/env node
// Independent reader for a layer archive of `strahler export --layer` (the `pmtiles` npm
// library, as MapLibre and static hosts use it, and pngjs).
//
// Opens <dir>/world-layer.pmtiles (`--layer vegetation --species bush`, zooms 9-11, see
// tests/cli/write_export_archives.sh): header (PNG tiles, no tile compression), metadata naming
// the layer, its parameters and encoding (and no raster-dem encoding: these are not heights);
// then the corners and centre of every zoom compared byte for byte with `strahler tile --layer
// vegetation --species bush` of the same z/x/y, the centre decoded as an 8-bit grey PNG with
// vegetation in it.
//
// Usage: node check_pmtiles_layer.mjs <dir> <strahler>. Exits 1 on any mismatch.

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";

import { fail, load, openPmtiles, webTileRange } from "./pmtiles_file.mjs";

const [dir, strahler] = process.argv.slice(2);
if (!dir || !strahler) fail("usage: node check_pmtiles_layer.mjs <dir> <strahler>");
const { PNG } = await load("pngjs");

const archive = await openPmtiles(path.join(dir, "world-layer.pmtiles"));
const worldPath = path.join(dir, "world.world");
const header = await archive.getHeader();
const metadata = await archive.getMetadata();
let checks = 0;
function expect(condition, message) {
  if (!condition) fail(message);
  checks++;
}

expect(header.minZoom === 9 && header.maxZoom === 11, `zooms ${header.minZoom}-${header.maxZoom}`);
expect(header.tileType === 2, `tile type ${header.tileType} (2: png)`);
expect(header.tileCompression === 1, `tile compression ${header.tileCompression} (1: none)`);
expect(metadata.format === "png", `metadata format ${metadata.format}`);
expect(metadata.layer === "vegetation", `metadata layer ${metadata.layer}`);
expect(metadata.layerQuery === "species=bush", `metadata layerQuery ${metadata.layerQuery}`);
expect(/^strahler vegetation: 8-bit grey PNG/.test(metadata.layerEncoding ?? ""),
  `metadata layerEncoding ${metadata.layerEncoding}`);
expect(metadata.encoding === undefined, `a layer has no raster-dem encoding: ${metadata.encoding}`);

const range = (z) => webTileRange(header, z);

const scratch = fs.mkdtempSync(path.join(dir, "layer-tiles-"));
function serverTile(z, x, y) {
  const out = path.join(scratch, `${z}-${x}-${y}.png`);
  execFileSync(strahler, ["tile", worldPath, "--scheme", "web", "--z", `${z}`, "--x", `${x}`, "--y", `${y}`,
    "--layer", "vegetation", "--species", "bush", "-o", out], { stdio: ["ignore", "ignore", "pipe"] });
  return fs.readFileSync(out);
}

let compared = 0, centre = null;
for (let z = header.minZoom; z <= header.maxZoom; z++) {
  const r = range(z);
  const cx = Math.floor((r.x0 + r.x1) / 2), cy = Math.floor((r.y0 + r.y1) / 2);
  for (const [x, y] of [[r.x0, r.y0], [r.x1, r.y1], [cx, cy]]) {
    const stored = await archive.getZxy(z, x, y);
    expect(stored !== undefined, `tile ${z}/${x}/${y} is missing from the archive`);
    const expected = serverTile(z, x, y);
    expect(Buffer.from(stored.data).equals(expected),
      `tile ${z}/${x}/${y}: ${stored.data.byteLength} bytes in the archive differ from strahler tile --layer's ${expected.length}`);
    compared++;
    if (z === header.maxZoom && x === cx && y === cy) centre = expected;
  }
}

// The island's centre grows bushes: an 8-bit grey PNG with non-zero densities.
const png = PNG.sync.read(centre, { skipRescale: true });
expect(png.depth === 8 && png.colorType === 0, `centre tile depth ${png.depth}, colour type ${png.colorType}`);
let growing = 0;
for (let i = 0; i < png.width * png.height; i++) if (png.data[4 * i] > 0) growing++;
expect(growing > 0, "the centre tile has no vegetation");

fs.rmSync(scratch, { recursive: true, force: true });
console.log(`OK: ${compared} layer tiles identical to strahler tile --layer's, ${checks} checks, ` +
  `${growing} pixels with bushes in the centre tile`);
