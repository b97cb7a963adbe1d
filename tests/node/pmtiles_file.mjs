// What the PMTiles checks share: fail and load (from decoders.mjs), a PMTiles archive opened
// from a local file through the `pmtiles` library's Source interface (byte ranges read with
// fs), and the Web Mercator tiles that cover an archive's bounds.

import fs from "node:fs";
import { fail, load } from "./decoders.mjs";

export { fail, load };

/** A pmtiles Source over a local file. */
class FileRangeSource {
  constructor(file) {
    this.file = file;
    this.fd = fs.openSync(file, "r");
  }
  getKey() {
    return this.file;
  }
  async getBytes(offset, length) {
    const buffer = Buffer.alloc(length);
    const read = fs.readSync(this.fd, buffer, 0, length, offset);
    return { data: buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + read) };
  }
}

/** The archive at `file`, read by the `pmtiles` library. */
export async function openPmtiles(file) {
  const { PMTiles } = await load("pmtiles");
  return new PMTiles(new FileRangeSource(file));
}

/** The Web Mercator tiles {x0, x1, y0, y1} (inclusive) that cover the bounds of a PMTiles `header` at zoom `z`. */
export function webTileRange(header, z) {
  const tileX = (lon) => ((lon + 180) / 360) * 2 ** z;
  const tileY = (lat) => ((1 - Math.asinh(Math.tan((lat * Math.PI) / 180)) / Math.PI) / 2) * 2 ** z;
  const clamp = (v, lo) => Math.min(Math.max(v, lo), 2 ** z - 1);
  const x0 = clamp(Math.floor(tileX(header.minLon)), 0);
  const x1 = clamp(Math.ceil(tileX(header.maxLon)) - 1, x0);
  const y0 = clamp(Math.floor(tileY(header.maxLat)), 0);
  const y1 = clamp(Math.ceil(tileY(header.minLat)) - 1, y0);
  return { x0, x1, y0, y1 };
}
