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
// Slope and hillshade are also computed here, independently of core/layers, from the bordered
// heights their JSON carries (the evaluator's, at the tile's samples and its border): central
// differences over the row's spacing, slope = atan|∇h| in hundredths of a degree, hillshade =
// 255 × the Lambertian light of the ground (relief exaggerated 2×) under a sun at azimuth 315°
// and altitude 45°, clamped to 0 … 1. Each must be checked this way at least once.
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

/** Slope (hundredths of a degree) or hillshade (0 … 255) from bordered heights, per pixel. */
function ownLayer(kind, { width, height, border, rowSpacing, heights }) {
  const stride = width + 2 * border;
  const at = (x, y) => heights[(y + border) * stride + x + border];
  const toRadians = Math.PI / 180;
  const [az, alt] = [315 * toRadians, 45 * toRadians];
  const light = [Math.sin(az) * Math.cos(alt), Math.cos(az) * Math.cos(alt), Math.sin(alt)];
  const out = new Array(width * height);
  for (let y = 0; y < height; ++y) {
    const spacing = rowSpacing[y + border];
    for (let x = 0; x < width; ++x) {
      const east = (at(x + 1, y) - at(x - 1, y)) / (2 * spacing);
      const north = (at(x, y - 1) - at(x, y + 1)) / (2 * spacing); // rows run south
      if (kind === "slope") {
        out[y * width + x] = 100 * Math.atan(Math.hypot(east, north)) / toRadians;
      } else {
        const [nx, ny] = [-2 * east, -2 * north]; // the ground's normal, relief exaggerated 2×
        const lit = (nx * light[0] + ny * light[1] + light[2]) / Math.sqrt(nx * nx + ny * ny + 1);
        out[y * width + x] = 255 * Math.min(1, Math.max(0, lit));
      }
    }
  }
  return out;
}

const ownChecks = { slope: 0, hillshade: 0 };

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
  const kind = name.split(".").pop();
  if (expected.heights && (kind === "slope" || kind === "hillshade")) {
    const own = ownLayer(kind, expected);
    let wrong = 0;
    for (let i = 0; i < samples.length; ++i) {
      const error = Math.abs(samples[i] - own[i]);
      maxError = Math.max(maxError, error);
      if (error > TOLERANCE && ++wrong <= 5)
        problems.push(
          `pixel (${i % png.width}, ${Math.floor(i / png.width)}): ${samples[i]}, ` +
            `this script's ${kind} ${own[i].toFixed(2)} ± ${TOLERANCE}`,
        );
    }
    if (wrong > 5) problems.push(`... ${wrong} samples away from this script's ${kind} in all`);
    ownChecks[kind] += 1;
  }
  return { problems, tile, maxError, east: expected.east };
}

await runPngSamples("layer", checkSample, () => {
  const missing = Object.entries(ownChecks).filter(([, n]) => n === 0).map(([kind]) => kind);
  return missing.length ? [`no ${missing.join(" or ")} tile was computed independently here`] : [];
});
