// Decodes every <name>.drc that write_mesh_samples produced with npm draco3d (Google's
// Emscripten build, not our code) and compares it with <name>.json, the mesh we encoded:
// same point and triangle counts, every decoded point within maxPositionError + 1e-6 of a
// distinct expected vertex, NORMAL present, TEX_COORD present exactly when expected, and
// every decoded triangle one of ours with the same winding.
// Usage: node check_draco.mjs <folder>

import { readFile, readdir } from 'node:fs/promises';
import path from 'node:path';

const INSTALL_HINT = 'run `npm ci --prefix tests/node` in the repository root';

function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

async function loadDecoderModule() {
  let draco3d;
  try {
    draco3d = (await import('draco3d')).default;
  } catch (error) {
    fail(`cannot load npm draco3d (${error.message}): ${INSTALL_HINT}`);
  }
  return draco3d.createDecoderModule({});
}

function copyOut(draco, byteLength, write, ArrayType) {
  const pointer = draco._malloc(byteLength);
  try {
    write(pointer);
    return new ArrayType(draco.HEAPU8.buffer, pointer, byteLength / ArrayType.BYTES_PER_ELEMENT).slice();
  } finally {
    draco._free(pointer);
  }
}

function readFloatAttribute(draco, decoder, mesh, type) {
  const id = decoder.GetAttributeId(mesh, type);
  if (id < 0) return null;
  const attribute = decoder.GetAttribute(mesh, id);
  const count = mesh.num_points() * attribute.num_components();
  const values = copyOut(draco, count * 4, (pointer) =>
    decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, draco.DT_FLOAT32, count * 4, pointer),
    Float32Array);
  return { components: attribute.num_components(), values };
}

function decode(draco, bytes) {
  const decoder = new draco.Decoder();
  const buffer = new draco.DecoderBuffer();
  const mesh = new draco.Mesh();
  try {
    buffer.Init(new Int8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength), bytes.byteLength);
    if (decoder.GetEncodedGeometryType(buffer) !== draco.TRIANGULAR_MESH) {
      throw new Error('not a Draco triangular mesh');
    }
    const status = decoder.DecodeBufferToMesh(buffer, mesh);
    if (!status.ok()) throw new Error(`draco3d: ${status.error_msg()}`);
    const indexCount = mesh.num_faces() * 3;
    return {
      points: mesh.num_points(),
      indices: copyOut(draco, indexCount * 4, (pointer) =>
        decoder.GetTrianglesUInt32Array(mesh, indexCount * 4, pointer), Uint32Array),
      position: readFloatAttribute(draco, decoder, mesh, draco.POSITION),
      normal: readFloatAttribute(draco, decoder, mesh, draco.NORMAL),
      uv: readFloatAttribute(draco, decoder, mesh, draco.TEX_COORD),
    };
  } finally {
    draco.destroy(mesh);
    draco.destroy(buffer);
    draco.destroy(decoder);
  }
}

// Decoded point p -> the expected vertex it came from: the closest one in its grid cell.
function matchPoints(expected, decoded, tolerance) {
  const cellOf = (x, z) => `${Math.round(x / expected.spacing)},${Math.round(z / expected.spacing)}`;
  const cells = new Map();
  const want = expected.positions;
  for (let v = 0; v < want.length / 3; v++) {
    const key = cellOf(want[3 * v], want[3 * v + 2]);
    if (!cells.has(key)) cells.set(key, []);
    cells.get(key).push(v);
  }
  const got = decoded.position.values;
  const original = new Int32Array(decoded.points).fill(-1);
  const used = new Uint8Array(want.length / 3);
  let worst = 0;
  for (let p = 0; p < decoded.points; p++) {
    let best = -1;
    let bestError = Infinity;
    for (const v of cells.get(cellOf(got[3 * p], got[3 * p + 2])) ?? []) {
      const error = Math.max(...[0, 1, 2].map((c) => Math.abs(got[3 * p + c] - want[3 * v + c])));
      if (error < bestError) [best, bestError] = [v, error];
    }
    if (best < 0 || bestError > tolerance) {
      throw new Error(`point ${p} (${got.slice(3 * p, 3 * p + 3).join(', ')}) is ${bestError} m ` +
        `from the nearest expected vertex; tolerance ${tolerance} m`);
    }
    if (used[best]) throw new Error(`points decode onto expected vertex ${best} twice`);
    used[best] = 1;
    original[p] = best;
    worst = Math.max(worst, bestError);
  }
  return { original, worst };
}

const faceKey = (a, b, c) => {
  // Rotate so the smallest index leads: keeps the winding, forgets the starting corner.
  if (b < a && b < c) return `${b},${c},${a}`;
  if (c < a && c < b) return `${c},${a},${b}`;
  return `${a},${b},${c}`;
};

function checkTriangles(expected, decoded, original) {
  const ours = new Set();
  for (let k = 0; k < expected.indices.length; k += 3) {
    ours.add(faceKey(expected.indices[k], expected.indices[k + 1], expected.indices[k + 2]));
  }
  const got = decoded.indices;
  for (let k = 0; k < got.length; k += 3) {
    const key = faceKey(original[got[k]], original[got[k + 1]], original[got[k + 2]]);
    if (!ours.has(key)) throw new Error(`decoded triangle ${k / 3} (${key}) is not ours or is flipped`);
  }
}

function checkSample(draco, expected, bytes) {
  const decoded = decode(draco, bytes);
  const vertices = expected.positions.length / 3;
  if (decoded.points !== vertices) throw new Error(`${decoded.points} points, expected ${vertices}`);
  if (decoded.indices.length !== expected.indices.length) {
    throw new Error(`${decoded.indices.length / 3} triangles, expected ${expected.indices.length / 3}`);
  }
  if (decoded.position?.components !== 3) throw new Error('no xyz POSITION attribute');
  if (decoded.normal?.components !== 3) throw new Error('no xyz NORMAL attribute');
  if ((decoded.uv !== null) !== expected.hasUv) {
    throw new Error(`TEX_COORD ${decoded.uv ? 'present' : 'missing'}, expected hasUv=${expected.hasUv}`);
  }
  const tolerance = expected.maxPositionError + 1e-6;
  const { original, worst } = matchPoints(expected, decoded, tolerance);
  checkTriangles(expected, decoded, original);
  return `${vertices} points, ${decoded.indices.length / 3} triangles, ` +
    `worst position error ${worst.toExponential(3)} m <= ${tolerance} m`;
}

async function main() {
  const folder = process.argv[2];
  if (!folder) fail('usage: node check_draco.mjs <folder with .drc and .json samples>');
  const draco = await loadDecoderModule();
  const names = (await readdir(folder)).filter((name) => name.endsWith('.json')).sort();
  if (names.length === 0) fail(`no samples (.json) in ${folder}`);
  let failures = 0;
  for (const name of names) {
    const expected = JSON.parse(await readFile(path.join(folder, name), 'utf8'));
    try {
      const bytes = await readFile(path.join(folder, expected.drc));
      console.log(`ok   ${expected.drc}: ${checkSample(draco, expected, bytes)}`);
    } catch (error) {
      failures++;
      console.error(`FAIL ${expected.drc}: ${error.message}`);
    }
  }
  if (failures > 0) fail(`${failures} of ${names.length} Draco samples did not decode as expected`);
  console.log(`all ${names.length} Draco samples decode with npm draco3d as expected`);
}

await main();
