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

import { runPngSamples, seamTile } from "./png_samples.mjs";

const TOLERANCE = 1; // one step: heights from two evaluators may round differently

/** Grey samples of a decoded PNG (pngjs gives RGBA; 16-bit kept as is with skipRescale). */
function greySamples(png) {
  const out = new Array(png.width * png.height);
  for (let i = 0; i < out.length; ++i) out[i] = png.data[4 * i];
  return out;
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
  const tile = seamTile(png, 1);
  const samples = greySamples(png);
  let bad = 0;
  let maxError = 0;
  for (let i = 0; i < samples.length; ++i) {
    const error = Math.abs(samples[i] - expected.expected[i]);
    maxError = Math.max(maxError, error);
    if (error > TOLERANCE && ++bad <= 5)
      problems.push(
        `pixel (${i % png.width}, ${Math.floor(i / png.width)}): ${samples[i]}, ` +
          `expected ${expected.expected[i].toFixed(2)} ± ${TOLERANCE}`,
      );
  }
  if (bad > 5) problems.push(`... ${bad} samples out of tolerance in all`);
  return { problems, tile, maxError, east: expected.east };
}

await runPngSamples("layer", checkSample);
