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

import { runPngSamples, seamTile } from "./png_samples.mjs";

const TOLERANCE = 1; // per channel: heights from two evaluators may truncate differently

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
  if (problems.length) return { problems };
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
  return { problems, tile: seamTile(png, 3), maxError, east: expected.east };
}

await runPngSamples("relief", checkSample);
