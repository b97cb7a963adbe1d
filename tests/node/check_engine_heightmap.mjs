#!/usr/bin/env node
// Independent decoder for `strahler export-heightmap`'s 16-bit PNGs (Unreal's default).
//
// Runs the program twice on one world: --engine unreal (png16) and --engine raw (r16), the
// same size and box, so the same 16-bit values with row 0 north. Decodes the PNG with pngjs
// and the r16 as little-endian bytes, and checks: 16-bit grey, the sidecar's width and height,
// every sample equal, 0 and 65535 both present (the box's min..max), and the sidecar's Unreal
// Z scale = range × 100 / 512. The Unreal run also writes --splat: its five 8-bit grey weight
// PNGs at the heightmap's size, and a Unity --splat run its two RGBA alphamaps at (N − 1)²,
// must sum to 255 at every pixel.
//
// Usage: node check_engine_heightmap.mjs <strahler> <world> <scratch folder>. Exits 1 on any
// mismatch.

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { loadPng } from "./png_samples.mjs";

function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

async function main() {
  const [program, world, dir] = process.argv.slice(2);
  if (!program || !world || !dir) fail("usage: check_engine_heightmap.mjs <strahler> <world> <folder>");
  fs.mkdirSync(dir, { recursive: true });
  const size = "505";
  const png = path.join(dir, "unreal.png");
  const r16 = path.join(dir, "raw.r16");
  for (const [engine, out] of [["unreal", png], ["raw", r16]])
    execFileSync(program, ["export-heightmap", world, "--engine", engine, "--size", size, "--quiet", "-o", out,
                           ...(engine === "unreal" ? ["--splat"] : [])]);
  const PNG = await loadPng();
  const image = PNG.sync.read(fs.readFileSync(png), { skipRescale: true });
  const side = JSON.parse(fs.readFileSync(path.join(dir, "unreal.json"), "utf8"));
  if (image.colorType !== 0 || image.depth !== 16)
    fail(`colour type ${image.colorType}, depth ${image.depth}: expected 16-bit grey`);
  if (image.width !== side.width || image.height !== side.height || image.width !== Number(size))
    fail(`${image.width}x${image.height}, sidecar ${side.width}x${side.height}, asked ${size}`);
  const bytes = fs.readFileSync(r16);
  if (bytes.length !== 2 * image.width * image.height) fail(`r16 of ${bytes.length} bytes`);
  let bad = 0;
  let lo = 65535;
  let hi = 0;
  for (let i = 0; i < image.width * image.height; ++i) {
    const fromPng = image.data[4 * i];
    const fromR16 = bytes.readUInt16LE(2 * i);
    lo = Math.min(lo, fromPng);
    hi = Math.max(hi, fromPng);
    if (fromPng !== fromR16 && ++bad <= 5)
      console.error(`sample (${i % image.width}, ${Math.floor(i / image.width)}): png ${fromPng}, r16 ${fromR16}`);
  }
  if (bad) fail(`${bad} samples differ between the PNG and the r16`);
  if (lo !== 0 || hi !== 65535) fail(`values ${lo}..${hi}: expected the range 0..65535`);
  const range = side.maxHeight - side.minHeight;
  if (Math.abs(side.unreal.scaleZ - (range * 100) / 512) > 1e-9)
    fail(`Z scale ${side.unreal.scaleZ}, expected ${(range * 100) / 512}`);
  console.log(`OK: ${image.width}x${image.height} 16-bit PNG equals the r16, Z scale ${side.unreal.scaleZ}`);
  checkSplatSums(PNG, dir, side, image.width, 1);
  const unity = path.join(dir, "unity.raw");
  execFileSync(program, ["export-heightmap", world, "--engine", "unity", "--size", "257", "--splat", "--quiet", "-o", unity]);
  checkSplatSums(PNG, dir, JSON.parse(fs.readFileSync(path.join(dir, "unity.json"), "utf8")), 256, 4);
}

/** Every pixel of the sidecar's splat files (`channels` weights each) sums to 255. */
function checkSplatSums(PNG, dir, side, width, channels) {
  const files = side.splat.files.map((f) => PNG.sync.read(fs.readFileSync(path.join(dir, f))));
  for (const [i, f] of files.entries())
    if (f.width !== width || f.height !== width || f.depth !== 8)
      fail(`${side.splat.files[i]}: ${f.width}x${f.height}, depth ${f.depth}; expected ${width}² 8-bit`);
  for (let p = 0; p < width * width; ++p) {
    let sum = 0;
    for (const f of files) for (let c = 0; c < channels; ++c) sum += f.data[4 * p + c];
    if (sum !== 255) fail(`${side.splat.files.join(", ")}: pixel ${p} sums to ${sum}`);
  }
  console.log(`OK: ${files.length} splat files of ${width}², every pixel's weights sum to 255`);
}

main();
