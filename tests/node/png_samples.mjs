// What check_relief.mjs and check_layers.mjs share: loading pngjs, walking a folder of
// <name>.png samples written by write_world_tile_samples, and the seam check between a sample
// and its "east" neighbour.

import fs from "node:fs";
import { load } from "./decoders.mjs";

/** pngjs's PNG, or exit 1 with how to install it. */
export async function loadPng() {
  return (await load("pngjs")).PNG;
}

/**
 * A decoded tile's samples for the seam check: `channels` values per pixel, read from pngjs's
 * RGBA data (grey PNGs repeat the value in R, G and B, so channel 0 is the grey value).
 */
export function seamTile(png, channels) {
  return { width: png.width, height: png.height, channels, data: png.data };
}

/** The mean absolute step between column `a` of `left` and column `b` of `right`. */
function columnStep(left, a, right, b) {
  let sum = 0;
  for (let y = 0; y < left.height; ++y)
    for (let k = 0; k < left.channels; ++k)
      sum += Math.abs(left.data[4 * (y * left.width + a) + k] - right.data[4 * (y * right.width + b) + k]);
  return sum / (left.channels * left.height);
}

/** The largest column step inside a tile. */
function largestInsideStep(tile) {
  let largest = 0;
  for (let x = 0; x + 1 < tile.width; ++x) largest = Math.max(largest, columnStep(tile, x, tile, x + 1));
  return largest;
}

/**
 * Checks every <name>.png of process.argv[2] with `checkSample(PNG, dir, name)`, which returns
 * { problems, tile (seamTile), maxError, east }; then each sample whose `east` neighbour was
 * written must join it without a seam: the mean step across the shared edge no larger than the
 * largest step between two columns inside either tile. Prints a line per check and exits 1 on
 * any failure, or when there were no samples or no neighbours. `what` names the tiles;
 * `finalCheck()` returns the problems left after every sample was read (none by default).
 */
export async function runPngSamples(what, checkSample, finalCheck = () => []) {
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
    console.error(`FAIL: no ${what} samples (or no neighbours) in ${dir}`);
    process.exit(1);
  }
  for (const problem of finalCheck()) {
    console.log(`FAIL ${problem}`);
    ++failures;
  }
  console.log(`${names.length - failures}/${names.length} ${what} tiles decode as expected`);
  process.exit(failures === 0 ? 0 : 1);
}
