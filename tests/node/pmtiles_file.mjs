// What the PMTiles checks share: failing with a message, loading an npm decoder with a hint
// when it is missing, and opening a PMTiles archive from a local file through the `pmtiles`
// library's Source interface (byte ranges read with fs).

import fs from "node:fs";

/** Prints FAIL: `message` and exits 1. */
export function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

/** The module `name`, or fail() with how to install the test decoders. */
export async function load(name) {
  try {
    return await import(name);
  } catch (error) {
    fail(`cannot load ${name} (${error.message}).\nInstall the test decoders first: npm ci --prefix tests/node`);
  }
}

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
