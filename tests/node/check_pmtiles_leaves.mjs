#!/usr/bin/env node
// Reads the leaf directories of a PMTiles archive written by our writer with the npm pmtiles
// library: the archive of write_synthetic_pmtiles (40,000 tiles "tile k" at zoom 9 on every
// other tile id from the first of zoom 9, and "sea" on the odd ids after k = 39,000).
//
// Usage: node check_pmtiles_leaves.mjs <file>. Exits 1 on any mismatch.

import { fail, load, openPmtiles } from "./pmtiles_file.mjs";

const { tileIdToZxy, zxyToTileId } = await load("pmtiles");

const file = process.argv[2];
if (!file) fail("usage: node check_pmtiles_leaves.mjs <file>");
const archive = await openPmtiles(file);

const header = await archive.getHeader();
if (header.leafDirectoryLength === 0) fail("no leaf directories");
if (header.rootDirectoryOffset + header.rootDirectoryLength > 16384) fail("root beyond 16 KiB");
if (header.numAddressedTiles !== 41000) fail(`addressed tiles ${header.numAddressedTiles}`);
if (header.numTileContents !== 40001) fail(`tile contents ${header.numTileContents}`);

const first = zxyToTileId(9, 0, 0);
const text = (tile) => (tile ? Buffer.from(tile.data).toString() : undefined);
let checked = 0;
for (let k = 0; k < 40000; k += 97) {
  const [z, x, y] = tileIdToZxy(first + 2 * k);
  const got = text(await archive.getZxy(z, x, y));
  if (got !== `tile ${k}`) fail(`tile id ${first + 2 * k} (${z}/${x}/${y}): '${got}', expected 'tile ${k}'`);
  const [oz, ox, oy] = tileIdToZxy(first + 2 * k + 1);
  const odd = text(await archive.getZxy(oz, ox, oy));
  const expected = k >= 39000 ? "sea" : undefined;
  if (odd !== expected) fail(`tile id ${first + 2 * k + 1}: '${odd}', expected '${expected}'`);
  checked += 2;
}
console.log(`OK: ${checked} tiles read through ${header.leafDirectoryLength} bytes of leaf directories`);
