#!/usr/bin/env node
// Independent decoder for strahler's vector tiles (.mvt, Mapbox Vector Tile 2.1).
//
// Reads every <name>.mvt in a folder (written by write_world_tile_samples) with
// @mapbox/vector-tile and pbf, and checks against <name>.json:
// - the layers contours and rivers are there (features when the world has a vector map, water
//   in at least one sample), version 2, extent 4096, with the geometry type and attributes of
//   each layer;
// - every vertex lies inside the tile and its buffer;
// - water polygons start with an exterior ring (positive area in tile coordinates, y down);
// - the rivers land where the world's rivers are: every vertex of the tile's rivers is within
//   RIVER_TOLERANCE tile units of a river line of the JSON (the world's full-resolution river
//   sections in degrees, projected here by our own Web Mercator), and every vertex of those
//   lines inside the tile is within RIVER_TOLERANCE of a line of the tile.
//
// A sample whose JSON has "exact" (the encoder's own sample: every geometry type and value
// type) must decode to exactly that: per layer, each feature's type, id, properties and
// geometry (rings closed, as loadGeometry gives them).
//
// Usage: node check_mvt.mjs <folder>. Exits 1 on any mismatch or if nothing was checked.

import fs from "node:fs";
import path from "node:path";
import { load } from "./decoders.mjs";

const EXTENT = 4096;
const RIVER_TOLERANCE = 3; // tile units: 1 of simplification, rounding, and slack

/** A function decoding MVT bytes with @mapbox/vector-tile over pbf (npm). */
async function loadDecoder() {
  const { VectorTile } = await load("@mapbox/vector-tile");
  const { PbfReader } = await load("pbf");
  return (bytes) => new VectorTile(new PbfReader(bytes));
}

/** Tile coordinates of a longitude/latitude in tile z/x/y (spherical Web Mercator). */
function toTile([lon, lat], { z, x, y }) {
  const n = 2 ** z;
  const phi = (lat * Math.PI) / 180;
  const mx = (lon + 180) / 360;
  const my = 0.5 - Math.log(Math.tan(Math.PI / 4 + phi / 2)) / (2 * Math.PI);
  return [(mx * n - x) * EXTENT, (my * n - y) * EXTENT];
}

function distanceToSegment(p, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const length2 = dx * dx + dy * dy;
  const t = length2 === 0 ? 0 : Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

function distanceToLines(p, lines) {
  let best = Infinity;
  for (const line of lines)
    for (let i = 0; i + 1 < line.length; ++i) best = Math.min(best, distanceToSegment(p, line[i], line[i + 1]));
  return best;
}

function ringArea2(ring) {
  let sum = 0;
  for (let i = 0; i < ring.length; ++i) {
    const a = ring[i], b = ring[(i + 1) % ring.length];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

const LAYERS = {
  water: { type: 3, fields: { kind: "string" } },
  contours: { type: 2, fields: { elevation: "number", index: "boolean" } },
  rivers: { type: 2, fields: { order: "number", flow: "number", width: "number", rosgen: "string" } },
  features: { type: null, fields: { kind: "string" } },
};

function checkExact(tile, exact) {
  const problems = [];
  const names = Object.keys(tile.layers).sort().join(",");
  if (names !== Object.keys(exact).sort().join(",")) problems.push(`layers ${names}`);
  for (const [id, features] of Object.entries(exact)) {
    const layer = tile.layers[id];
    if (!layer || layer.length !== features.length || layer.version !== 2) {
      problems.push(`${id}: ${layer?.length} features, version ${layer?.version}`);
      continue;
    }
    features.forEach((want, i) => {
      const f = layer.feature(i);
      const geometry = f.loadGeometry().map((part) => part.map((p) => [p.x, p.y]));
      const got = { type: f.type, ...(f.id ? { id: f.id } : {}), properties: f.properties, geometry };
      for (const key of ["type", "id", "properties", "geometry"])
        if (JSON.stringify(got[key]) !== JSON.stringify(want[key]))
          problems.push(`${id}[${i}].${key}: ${JSON.stringify(got[key])}, expected ${JSON.stringify(want[key])}`);
    });
  }
  return { problems, water: false, summary: `exactly the encoder's content (${names})` };
}

function checkSample(decode, dir, name) {
  const expected = JSON.parse(fs.readFileSync(path.join(dir, `${name}.json`), "utf8"));
  const tile = decode(fs.readFileSync(path.join(dir, `${name}.mvt`)));
  if (expected.exact) return checkExact(tile, expected.exact);
  const problems = [];
  const lo = -expected.buffer, hi = EXTENT + expected.buffer;
  // An all-land tile has no water layer (empty layers are left out); the folder needs one.
  const wanted = ["contours", "rivers", ...(expected.features ? ["features"] : [])];
  for (const id of wanted) if (!tile.layers[id]) problems.push(`layer ${id} is missing`);
  for (const id of Object.keys(tile.layers)) {
    const layer = tile.layers[id];
    const rule = LAYERS[id];
    if (!rule) {
      problems.push(`unexpected layer ${id}`);
      continue;
    }
    if (layer.version !== 2 || layer.extent !== EXTENT)
      problems.push(`${id}: version ${layer.version}, extent ${layer.extent}`);
    for (let i = 0; i < layer.length; ++i) {
      const f = layer.feature(i);
      if (rule.type !== null && f.type !== rule.type) problems.push(`${id}[${i}]: type ${f.type}`);
      for (const [key, kind] of Object.entries(rule.fields))
        if (typeof f.properties[key] !== kind) problems.push(`${id}[${i}]: ${key} is ${f.properties[key]}`);
      const rings = f.loadGeometry();
      for (const part of rings)
        for (const p of part)
          if (p.x < lo || p.x > hi || p.y < lo || p.y > hi) problems.push(`${id}[${i}]: vertex ${p.x},${p.y} outside`);
      if (id === "water" && rings.length && ringArea2(rings[0]) <= 0)
        problems.push(`water[${i}]: first ring is not an exterior (clockwise) ring`);
    }
  }
  const rivers = tile.layers.rivers;
  // The world's river lines near the tile (a line far outside it cannot be the nearest).
  const near = (p) => p[0] > lo - 64 && p[0] < hi + 64 && p[1] > lo - 64 && p[1] < hi + 64;
  const worldLines = expected.rivers
    .map((line) => line.map((p) => toTile(p, expected)))
    .filter((line) => line.some(near));
  const tileLines = [];
  for (let i = 0; rivers && i < rivers.length; ++i)
    for (const part of rivers.feature(i).loadGeometry()) tileLines.push(part.map((p) => [p.x, p.y]));
  let far = 0, missing = 0, inside = 0;
  for (const line of tileLines)
    for (const p of line) if (distanceToLines(p, worldLines) > RIVER_TOLERANCE) ++far;
  for (const line of worldLines)
    for (const p of line)
      if (p[0] >= 0 && p[0] <= EXTENT && p[1] >= 0 && p[1] <= EXTENT) {
        ++inside;
        if (distanceToLines(p, tileLines) > RIVER_TOLERANCE) ++missing;
      }
  if (far) problems.push(`${far} river vertices are more than ${RIVER_TOLERANCE} units from the world's rivers`);
  if (missing) problems.push(`${missing} of ${inside} world river points in the tile are not on its rivers`);
  if (inside === 0) problems.push("no river of the world in this tile: a sample that checks nothing");
  const counts = Object.keys(tile.layers).map((id) => `${id} ${tile.layers[id].length}`).join(", ");
  return { problems, water: Boolean(tile.layers.water), summary: `${counts}; ${tileLines.length} river lines, ${inside} world river points` };
}

const dir = process.argv[2];
if (!dir) {
  console.error("usage: node check_mvt.mjs <folder>");
  process.exit(2);
}
const decode = await loadDecoder();
const names = fs.readdirSync(dir).filter((f) => f.endsWith(".mvt")).map((f) => f.slice(0, -4)).sort();
let failed = 0;
let water = false;
for (const name of names) {
  const { problems, summary, water: hasWater } = checkSample(decode, dir, name);
  water ||= hasWater;
  if (problems.length) {
    ++failed;
    console.error(`FAIL ${name}: ${problems.slice(0, 10).join("; ")}`);
  } else console.log(`ok ${name}: ${summary}`);
}
if (names.length === 0) {
  console.error(`FAIL: no .mvt tiles in ${dir}`);
  process.exit(1);
}
if (!water) {
  console.error("FAIL: no sample has a water layer");
  process.exit(1);
}
process.exit(failed ? 1 : 0);
