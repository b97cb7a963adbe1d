#!/usr/bin/env node
// Independent decoder for strahler's PNG heightmap tiles.
//
// Reads every <name>.<format>.png in a folder (written by write_heightmap_samples), decodes
// it with pngjs and the published formulas, and compares with <name>.<format>.json, the
// heights the C++ side says the tile holds (already clamped to the format's range):
//
//   terrainrgb  h = -10000 + (R·65536 + G·256 + B) · 0.1        (Mapbox Terrain-RGB)  ±0.05 m
//   terrarium   h = R·256 + G + B/256 − 32768                    (Mapzen Terrarium)    ±1/256 m
//   png16       h = value · 0.1 − 1000, 16-bit grey              (strahler png16)      ±0.05 m
//
// Usage: node check_heightmaps.mjs <folder>. Exits 1 on any mismatch or if nothing was checked.

import fs from "node:fs";
import path from "node:path";
import { loadPng } from "./png_samples.mjs";

// Rounding in the decoder's own double arithmetic may exceed a tolerance by a few ulps.
const SLACK = 1e-9;

const FORMATS = {
  terrainrgb: {
    colorType: 2,
    depth: 8,
    tolerance: 0.05,
    decode: (d, i) => -10000 + (d[4 * i] * 65536 + d[4 * i + 1] * 256 + d[4 * i + 2]) * 0.1,
  },
  terrarium: {
    colorType: 2,
    depth: 8,
    tolerance: 1 / 256,
    decode: (d, i) => d[4 * i] * 256 + d[4 * i + 1] + d[4 * i + 2] / 256 - 32768,
  },
  png16: {
    colorType: 0,
    depth: 16,
    tolerance: 0.05,
    decode: (d, i) => d[4 * i] * 0.1 - 1000,
  },
};

/** Compares one PNG with its expected heights; returns a list of problems (empty when fine). */
function checkSample(PNG, pngPath, expected) {
  const format = FORMATS[expected.format];
  if (!format) return { problems: [`unknown format "${expected.format}" in the JSON`], maxError: NaN };
  // skipRescale keeps 16-bit samples as they are (a Uint16Array of RGBA, grey replicated).
  const png = PNG.sync.read(fs.readFileSync(pngPath), { skipRescale: true });
  const problems = [];
  if (png.colorType !== format.colorType || png.depth !== format.depth)
    problems.push(
      `colour type ${png.colorType}, bit depth ${png.depth}; ` +
        `expected ${format.colorType}, ${format.depth}`,
    );
  if (png.width !== expected.width || png.height !== expected.height)
    problems.push(`${png.width}x${png.height}, expected ${expected.width}x${expected.height}`);
  if (expected.heights.length !== expected.width * expected.height)
    problems.push(`the JSON holds ${expected.heights.length} heights for ${expected.width}x${expected.height}`);
  if (problems.length) return { problems, maxError: NaN };
  let maxError = 0;
  let bad = 0;
  for (let i = 0; i < expected.heights.length; ++i) {
    const decoded = format.decode(png.data, i);
    const error = Math.abs(decoded - expected.heights[i]);
    maxError = Math.max(maxError, error);
    if (error <= format.tolerance + SLACK) continue; // also false for NaN
    if (++bad <= 5)
      problems.push(
        `pixel (${i % png.width}, ${Math.floor(i / png.width)}): decoded ${decoded}, ` +
          `expected ${expected.heights[i]} ± ${format.tolerance}`,
      );
  }
  if (bad > 5) problems.push(`... ${bad} pixels out of tolerance in all`);
  return { problems, maxError };
}

async function main() {
  const dir = process.argv[2];
  if (!dir || !fs.existsSync(dir)) {
    console.error(`FAIL: sample folder "${dir ?? ""}" not found (run write_heightmap_samples first)`);
    process.exit(1);
  }
  const PNG = await loadPng();
  const files = fs.readdirSync(dir).filter((f) => f.endsWith(".png")).sort();
  let failures = 0;
  for (const file of files) {
    const jsonPath = path.join(dir, file.replace(/\.png$/, ".json"));
    let result;
    try {
      const expected = JSON.parse(fs.readFileSync(jsonPath, "utf8"));
      result = checkSample(PNG, path.join(dir, file), expected);
    } catch (error) {
      result = { problems: [error.message], maxError: NaN };
    }
    const ok = result.problems.length === 0;
    failures += ok ? 0 : 1;
    console.log(`${ok ? "ok  " : "FAIL"} ${file}  max error ${result.maxError.toFixed(6)} m`);
    for (const problem of result.problems) console.log(`       ${problem}`);
  }
  if (files.length === 0) {
    console.error(`FAIL: no .png samples in ${dir}`);
    process.exit(1);
  }
  console.log(`${files.length - failures}/${files.length} heightmap tiles decode as expected`);
  process.exit(failures === 0 ? 0 : 1);
}

await main();
