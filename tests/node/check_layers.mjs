#!/usr/bin/env node
// Independent decoder for strahler's layer tiles (layers/{name}/...png).
//
// Reads every <name>.<layer>.png in a folder (written by write_world_tile_samples), decodes it
// with pngjs and checks that it is a grey PNG of <name>.<layer>.json's width × height and bit
// depth whose samples are the JSON's "expected" values (the layer computed by core/layers from
// the whole-world evaluator's heights at the tile's bordered samples, scaled as the tile
// encodes it) within one step. A sample whose JSON names an "east" neighbour must join it
// without a seam: the mean step between its last and the neighbour's first pixel column is no
// larger than the largest step between two columns inside either tile.
//
// Usage: node check_layers.mjs <folder>. Exits 1 on any mismatch or if nothing was checked.

import fs from "node:fs";
import path from "node:path";

const TOLERANCE = 1; // one step: heights from two evaluators may round differently

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

/** Grey samples of a decoded PNG (pngjs gives RGBA; 16-bit kept as is with skipRescale). */
function greySamples(png) {
  const out = new Array(png.width * png.height);
  for (let i = 0; i < out.length; ++i) out[i] = png.data[4 * i];
  return out;
}

/** The mean absolute step between column `a` of `left` and column `b` of `right`. */
function columnStep(left, a, right, b) {
  let sum = 0;
  for (let y = 0; y < left.height; ++y)
    sum += Math.abs(left.samples[y * left.width + a] - right.samples[y * right.width + b]);
  return sum / left.height;
}

function largestInsideStep(tile) {
  let largest = 0;
  for (let x = 0; x + 1 < tile.width; ++x) largest = Math.max(largest, columnStep(tile, x, tile, x + 1));
  return largest;
}

function checkSample(PNG, dir, name) {
  const expected = JSON.parse(fs.readFileSync(path.join(dir, `${name}.json`), "utf8"));
  const png = PNG.sync.read(fs.readFileSync(path.join(dir, `${name}.png`)), { skipRescale: true });
  const problems = [];
  if (png.colorType !== 0 || png.depth !== expected.depth)
    problems.push(`colour type ${png.colorType}, bit depth ${png.depth}; expected 0 (grey), ${expected.depth}`);
  if (png.width !== expected.width || png.height !== expected.height)
    problems.push(`${png.width}x${png.height}, expected ${expected.width}x${expected.height}`);
  if (problems.length) return { problems };
  const tile = { width: png.width, height: png.height, samples: greySamples(png) };
  let bad = 0;
  let maxError = 0;
  for (let i = 0; i < tile.samples.length; ++i) {
    const error = Math.abs(tile.samples[i] - expected.expected[i]);
    maxError = Math.max(maxError, error);
    if (error > TOLERANCE && ++bad <= 5)
      problems.push(
        `pixel (${i % png.width}, ${Math.floor(i / png.width)}): ${tile.samples[i]}, ` +
          `expected ${expected.expected[i].toFixed(2)} ± ${TOLERANCE}`,
      );
  }
  if (bad > 5) problems.push(`... ${bad} samples out of tolerance in all`);
  return { problems, tile, maxError, east: expected.east };
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
    console.log(`${ok ? "ok  " : "FAIL"} ${name}.png  max error ${result.maxError?.toFixed(3) ?? NaN}`);
    for (const problem of result.problems) console.log(`       ${problem}`);
  }
  let seams = 0;
  for (const [name, result] of results) {
    if (!result.east || result.problems.length) continue;
    const east = results.get(result.east);
    if (!east || !east.tile) {
      console.log(`FAIL ${name}: its east neighbour ${result.east} was not written`);
      ++failures;
      continue;
    }
    const seam = columnStep(result.tile, result.tile.width - 1, east.tile, 0);
    const inside = Math.max(largestInsideStep(result.tile), largestInsideStep(east.tile));
    const ok = inside > 0 && seam <= inside;
    failures += ok ? 0 : 1;
    ++seams;
    console.log(
      `${ok ? "ok  " : "FAIL"} ${name} | ${result.east}: step across the seam ` +
        `${seam.toFixed(2)}, largest inside ${inside.toFixed(2)}`,
    );
  }
  if (names.length === 0 || seams === 0) {
    console.error(`FAIL: no layer samples (or no neighbours) in ${dir}`);
    process.exit(1);
  }
  console.log(`${names.length - failures}/${names.length} layer tiles decode as expected`);
  process.exit(failures === 0 ? 0 : 1);
}

await main();
