#!/usr/bin/env node
// Independent decoder for strahler's colour-relief tiles (.relief).
//
// Reads every <name>.png in a folder (written by write_world_tile_samples), decodes it with
// pngjs and checks that it is an 8-bit RGB PNG of <name>.json's width × height whose pixels
// are <name>.rgb (raw RGB: the same colour relief shaded from the whole-world evaluator's
// heights) within one step per channel. A sample whose JSON names an "east" neighbour must
// join it without a seam: the colour step between its last and the neighbour's first pixel
// column is no larger than the largest step between two columns inside either tile.
//
// Usage: node check_relief.mjs <folder>. Exits 1 on any mismatch or if nothing was checked.

import fs from "node:fs";
import path from "node:path";

const TOLERANCE = 1; // per channel: heights from two evaluators may truncate differently

async function loadPng() {
  try {
    return (await import("pngjs")).PNG;
  } catch (error) {
    console.error(
      `FAIL: cannot load pngjs (${error.message}).\n` +
        "Install the test decoders first: npm ci --prefix tests/node",
    );
    process.exit(1);
  }
}

/** The mean absolute colour step between column `a` of `left` and column `b` of `right`. */
function columnStep(left, a, right, b) {
  let sum = 0;
  for (let y = 0; y < left.height; ++y)
    for (let k = 0; k < 3; ++k)
      sum += Math.abs(left.data[4 * (y * left.width + a) + k] - right.data[4 * (y * right.width + b) + k]);
  return sum / (3 * left.height);
}

/** The largest column step inside a decoded tile. */
function largestInsideStep(png) {
  let largest = 0;
  for (let x = 0; x + 1 < png.width; ++x) largest = Math.max(largest, columnStep(png, x, png, x + 1));
  return largest;
}

function checkSample(PNG, dir, name) {
  const expected = JSON.parse(fs.readFileSync(path.join(dir, `${name}.json`), "utf8"));
  const png = PNG.sync.read(fs.readFileSync(path.join(dir, `${name}.png`)));
  const problems = [];
  if (png.colorType !== 2 || png.depth !== 8)
    problems.push(`colour type ${png.colorType}, bit depth ${png.depth}; expected 2 (RGB), 8`);
  if (png.width !== expected.width || png.height !== expected.height)
    problems.push(`${png.width}x${png.height}, expected ${expected.width}x${expected.height}`);
  const rgb = fs.readFileSync(path.join(dir, `${name}.rgb`));
  if (rgb.length !== expected.width * expected.height * 3)
    problems.push(`${rgb.length} expected bytes for ${expected.width}x${expected.height}`);
  if (problems.length) return { problems, png };
  let bad = 0;
  let maxError = 0;
  for (let i = 0; i < png.width * png.height; ++i)
    for (let k = 0; k < 3; ++k) {
      const error = Math.abs(png.data[4 * i + k] - rgb[3 * i + k]);
      maxError = Math.max(maxError, error);
      if (error > TOLERANCE && ++bad <= 5)
        problems.push(
          `pixel (${i % png.width}, ${Math.floor(i / png.width)}) channel ${k}: ` +
            `${png.data[4 * i + k]}, expected ${rgb[3 * i + k]} ± ${TOLERANCE}`,
        );
    }
  if (bad > 5) problems.push(`... ${bad} channels out of tolerance in all`);
  return { problems, png, maxError, east: expected.east };
}

async function main() {
  const dir = process.argv[2];
  if (!dir || !fs.existsSync(dir)) {
    console.error(`FAIL: sample folder "${dir ?? ""}" not found (run write_world_tile_samples first)`);
    process.exit(1);
  }
  const PNG = await loadPng();
  const names = fs
    .readdirSync(dir)
    .filter((f) => f.endsWith(".png"))
    .map((f) => f.replace(/\.png$/, ""))
    .sort();
  const results = new Map();
  let failures = 0;
  for (const name of names) {
    let result;
    try {
      result = checkSample(PNG, dir, name);
    } catch (error) {
      result = { problems: [error.message] };
    }
    results.set(name, result);
    const ok = result.problems.length === 0;
    failures += ok ? 0 : 1;
    console.log(`${ok ? "ok  " : "FAIL"} ${name}.png  max channel error ${result.maxError ?? NaN}`);
    for (const problem of result.problems) console.log(`       ${problem}`);
  }
  let seams = 0;
  for (const [name, result] of results) {
    if (!result.east || result.problems.length) continue;
    const east = results.get(result.east);
    if (!east || !east.png) {
      console.log(`FAIL ${name}: its east neighbour ${result.east} was not written`);
      ++failures;
      continue;
    }
    const seam = columnStep(result.png, result.png.width - 1, east.png, 0);
    const inside = Math.max(largestInsideStep(result.png), largestInsideStep(east.png));
    const ok = inside > 0 && seam <= inside;
    failures += ok ? 0 : 1;
    ++seams;
    console.log(
      `${ok ? "ok  " : "FAIL"} ${name} | ${result.east}: colour step across the seam ` +
        `${seam.toFixed(2)}, largest inside ${inside.toFixed(2)}`,
    );
  }
  if (names.length === 0 || seams === 0) {
    console.error(`FAIL: no relief samples (or no neighbours) in ${dir}`);
    process.exit(1);
  }
  console.log(`${names.length - failures}/${names.length} relief tiles decode as expected`);
  process.exit(failures === 0 ? 0 : 1);
}

await main();
