// strahler's Cesium terrain (layer.json and quantized-mesh-1.0 .terrain tiles) against a real
// `strahler serve`, decoded by three decoders that are not ours: @here/quantized-mesh-decoder,
// @loaders.gl/terrain and CesiumJS's own CesiumTerrainProvider (it runs under Node). The header
// is checked against our own ECEF arithmetic, the heights against the world's Terrain-RGB tiles.
// No browser.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { after, before, describe, test } from 'node:test';
import { gunzipSync } from 'node:zlib';
import { arrayBufferOf, get } from './lib/http.mjs';
import {
  QMAX, decodeTile, decodeWithLoadersGl, dot, ecef, meshHeightAt, norm, occlusionMagnitude, scaled, sub, tileAt, tileRect,
} from './lib/quantized-mesh.mjs';
import { startServer } from './lib/server.mjs';
import { worldHeights } from './lib/world-heights.mjs';

const TOTAL_MS = 240_000;
const ACCEPT_ALL = 'application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,application/octet-stream;q=0.9,*/*;q=0.01';
// Cesium's geometric error of a level of the geographic pyramid: the equator's quarter over 65
// samples and 2 root tiles, halved per level (≈ 77 km at level 0).
const geometricError = (level) => (6378137 * 2 * Math.PI * 0.25) / (65 * 2) / 2 ** level;

let server, world, base, layer;
const watchdog = setTimeout(() => {
  console.error(`cesium terrain tests exceeded ${TOTAL_MS} ms`);
  process.exit(1);
}, TOTAL_MS);
watchdog.unref();

before(async () => {
  server = await startServer();
  world = (await (await fetch(`${server.url}/worlds`)).json())[0];
  base = `${server.url}/worlds/${world.id}/cesium`;
  const r = await get(`${base}/layer.json`);
  assert.equal(r.status, 200, `layer.json: ${r.body}`);
  layer = JSON.parse(r.body.toString('utf8'));
}, { timeout: 90_000 });

after(async () => {
  await server?.stop();
  clearTimeout(watchdog);
});

/** GET a tile with every extension (CesiumJS's Accept header); its bytes and decoded forms. */
const tiles = new Map();
function fetchTile(z, x, y, headers = { Accept: ACCEPT_ALL }) {
  const key = `${z}/${x}/${y} ${JSON.stringify(headers)}`;
  if (!tiles.has(key)) {
    tiles.set(key, (async () => {
      const r = await get(`${base}/${z}/${x}/${y}.terrain`, headers);
      assert.equal(r.status, 200, `${z}/${x}/${y}.terrain: ${r.status} ${r.body}`);
      const rect = tileRect(z, x, y);
      return { z, x, y, rect, response: r, tile: decodeTile(arrayBufferOf(r.body), rect) };
    })());
  }
  return tiles.get(key);
}

// Tiles over the world: the one holding its centre at a middle level, its east and north
// neighbours, its four children, and the deepest level's tile at the centre.
function centreTile(level) {
  return tileAt(level, world.center[0], world.center[1]);
}
const MID = 11;

describe('layer.json', () => {
  test('has every field cesium-native\'s LayerJsonTerrainLoader and CesiumJS read', () => {
    assert.equal(layer.format, 'quantized-mesh-1.0');
    assert.equal(layer.scheme, 'tms');
    assert.equal(layer.projection, 'EPSG:4326');
    assert.equal(typeof layer.version, 'string');
    assert.ok(Array.isArray(layer.tiles) && layer.tiles.length >= 1, JSON.stringify(layer.tiles));
    assert.ok(layer.tiles.every((t) => t.includes('{z}') && t.includes('{x}') && t.includes('{y}') && t.includes('.terrain')), JSON.stringify(layer.tiles));
    assert.deepEqual([...layer.extensions].sort(), ['metadata', 'octvertexnormals', 'watermask']);
    assert.ok(Number.isInteger(layer.minzoom) && Number.isInteger(layer.maxzoom) && layer.minzoom === 0 && layer.maxzoom >= MID + 2,
      `minzoom ${layer.minzoom}, maxzoom ${layer.maxzoom}`);
    assert.ok(Array.isArray(layer.bounds) && layer.bounds.length === 4 && layer.bounds.every(Number.isFinite), JSON.stringify(layer.bounds));
    assert.equal(typeof layer.attribution, 'string');
    assert.ok(Number.isInteger(layer.metadataAvailability) && layer.metadataAvailability > 0, `${layer.metadataAvailability}`);
    // `available`: per level, ranges of TMS tiles; level 0 is both root tiles.
    assert.ok(Array.isArray(layer.available) && layer.available.length >= 1);
    assert.deepEqual(layer.available[0], [{ startX: 0, startY: 0, endX: 1, endY: 0 }]);
    const centre = (level) => centreTile(level);
    for (let level = 0; level < layer.available.length; ++level) {
      const { x, y } = centre(level);
      const ranges = layer.available[level];
      assert.ok(ranges.every((r) => ['startX', 'startY', 'endX', 'endY'].every((k) => Number.isInteger(r[k]))), `level ${level}`);
      assert.ok(ranges.some((r) => x >= r.startX && x <= r.endX && y >= r.startY && y <= r.endY),
        `level ${level}: the world's centre tile ${x}/${y} is not available: ${JSON.stringify(ranges)}`);
    }
  });
});

describe('.terrain responses', () => {
  test('extensions by CesiumJS\'s Accept header or cesium-native\'s ?extensions=, in any order: the same bytes', async () => {
    const { x, y } = centreTile(MID);
    const url = `${base}/${MID}/${x}/${y}.terrain`;
    const byHeader = await get(url, { Accept: ACCEPT_ALL });
    const byQuery = await get(`${url}?extensions=octvertexnormals-watermask-metadata`);
    const reordered = await get(`${url}?extensions=metadata-watermask-octvertexnormals`);
    const headerReordered = await get(url, { Accept: 'application/vnd.quantized-mesh;extensions=watermask-metadata-octvertexnormals' });
    for (const r of [byHeader, byQuery, reordered, headerReordered]) {
      assert.equal(r.status, 200);
      assert.equal(r.headers['content-type'], 'application/vnd.quantized-mesh');
      assert.equal(r.headers['content-encoding'], undefined, 'gzip although the client did not accept it');
      assert.ok(r.headers.etag, 'no ETag');
      assert.match(r.headers['server-timing'] ?? '', /dur=/);
      assert.equal(r.headers['access-control-allow-origin'], '*');
    }
    assert.ok(byHeader.body.equals(byQuery.body), 'Accept header and ?extensions= differ');
    assert.ok(byQuery.body.equals(reordered.body) && byHeader.body.equals(headerReordered.body), 'the order of the extensions matters');
    assert.equal(byHeader.headers.etag, byQuery.headers.etag);

    // Fewer extensions: a different, smaller tile; cesium-native's set (no metadata) too.
    const none = await get(url);
    const nativeSet = await get(`${url}?extensions=octvertexnormals-watermask`);
    assert.equal(none.status, 200);
    assert.ok(none.body.length < nativeSet.body.length && nativeSet.body.length <= byHeader.body.length,
      `${none.body.length} < ${nativeSet.body.length} <= ${byHeader.body.length}`);
    assert.notEqual(none.headers.etag, byHeader.headers.etag);
    const plain = decodeTile(arrayBufferOf(none.body), tileRect(MID, x, y));
    assert.deepEqual(plain.raw.extensions, {}, 'extensions nobody asked for');
    const native = decodeTile(arrayBufferOf(nativeSet.body), tileRect(MID, x, y)).raw.extensions;
    assert.deepEqual(Object.keys(native).sort(), ['vertexNormals', 'waterMask']);
    // The response depends on Accept (the extensions) and Accept-Encoding: caches must know.
    const vary = (byHeader.headers.vary ?? '').toLowerCase();
    assert.ok(/\baccept\b/.test(vary) && /accept-encoding/.test(vary), `Vary: ${byHeader.headers.vary}`);

    const again = await get(url, { Accept: ACCEPT_ALL, 'If-None-Match': byHeader.headers.etag });
    assert.equal(again.status, 304);

    // The metadata extension where layer.json says it is: every metadataAvailability levels.
    const m = centreTile(layer.metadataAvailability);
    const murl = `${base}/${m.z}/${m.x}/${m.y}.terrain`;
    const [withMetadata, withoutMetadata] = [await get(murl, { Accept: ACCEPT_ALL }), await get(`${murl}?extensions=octvertexnormals-watermask`)];
    assert.ok(withMetadata.body.length > withoutMetadata.body.length, `${withMetadata.body.length} vs ${withoutMetadata.body.length}`);
    const metadata = decodeTile(arrayBufferOf(withMetadata.body), tileRect(m.z, m.x, m.y)).metadata;
    assert.ok(Array.isArray(metadata?.available), `level ${m.z}: ${JSON.stringify(metadata)}`);
  });

  test('gzip only when accepted, as Content-Encoding, inflating to the same tile', async () => {
    let gzipped = 0;
    for (const level of [0, MID, layer.maxzoom]) {
      const { x, y } = centreTile(level);
      const url = `${base}/${level}/${x}/${y}.terrain`;
      const identity = await get(url, { Accept: ACCEPT_ALL });
      const gzip = await get(url, { Accept: ACCEPT_ALL, 'Accept-Encoding': 'gzip, deflate, br' });
      assert.equal(gzip.status, 200);
      assert.equal(gzip.headers['content-type'], 'application/vnd.quantized-mesh');
      if (gzip.headers['content-encoding'] !== undefined) {
        assert.equal(gzip.headers['content-encoding'], 'gzip');
        assert.ok(gunzipSync(gzip.body).equals(identity.body), `${level}/${x}/${y}: the gzipped tile differs`);
        assert.notEqual(gzip.headers.etag, identity.headers.etag, 'one strong ETag for two encodings');
        gzipped += 1;
      } else {
        assert.ok(gzip.body.equals(identity.body));
      }
    }
    assert.ok(gzipped >= 1, 'no tile came gzipped');
  });

  test('bad requests get definite 4xx answers with a JSON error', async () => {
    const { x, y } = centreTile(MID);
    const cases = [
      `${MID}/${x}/${y}.terrain?extensions=octvertexnormals-contours`, // unknown extension
      `0${MID}/${x}/${y}.terrain`, // leading zero
      `a/0/0.terrain`,
      `0/-1/0.terrain`,
      `0/2/0.terrain`, // level 0 has x 0..1
      `0/0/1.terrain`, // and y 0
      `${layer.maxzoom + 1}/0/0.terrain`, // past maxzoom
      `${MID}/${x}/${y}.terrain?size=64`, // a parameter the endpoint does not take
      `${MID}/${x}/${y}`,
    ];
    for (const path of cases) {
      const r = await get(`${base}/${path}`, { Accept: ACCEPT_ALL });
      assert.ok(r.status >= 400 && r.status < 500, `${path}: ${r.status}`);
      assert.equal(typeof JSON.parse(r.body.toString('utf8')).error, 'string', `${path}: ${r.body}`);
    }
  });
});

describe('tiles decoded by @here/quantized-mesh-decoder, @loaders.gl/terrain and CesiumJS', () => {
  let sample;
  before(async () => {
    const c = centreTile(MID);
    const d = centreTile(layer.maxzoom);
    const [coast, meta] = [centreTile(9), centreTile(layer.metadataAvailability)];
    const coords = [[0, 0, 0], [0, 1, 0], [coast.z, coast.x, coast.y], [meta.z, meta.x, meta.y], [MID, c.x, c.y], [MID, c.x + 1, c.y], [MID, c.x, c.y + 1],
      [MID + 1, 2 * c.x, 2 * c.y], [MID + 1, 2 * c.x + 1, 2 * c.y], [MID + 1, 2 * c.x, 2 * c.y + 1], [MID + 1, 2 * c.x + 1, 2 * c.y + 1],
      [layer.maxzoom, d.x, d.y]];
    sample = await Promise.all(coords.map(([z, x, y]) => fetchTile(z, x, y)));
  }, { timeout: 60_000 });

  test('the two npm decoders agree: vertices, triangles, heights', async () => {
    for (const { z, x, y, rect, response, tile } of sample) {
      const where = `${z}/${x}/${y}`;
      const other = await decodeWithLoadersGl(arrayBufferOf(response.body), rect);
      assert.equal(other.positions.length / 3, tile.vertices.length, where);
      assert.deepEqual(Array.from(other.indices), Array.from(tile.triangles), where);
      tile.vertices.forEach((v, i) => {
        const [lon, lat, h] = other.positions.subarray(3 * i, 3 * i + 3);
        assert.ok(Math.abs(lon - v.lon) < 1e-4 && Math.abs(lat - v.lat) < 1e-4 && Math.abs(h - v.height) <= 1e-3 * Math.max(1, Math.abs(v.height)),
          `${where} vertex ${i}: ${[lon, lat, h]} vs ${[v.lon, v.lat, v.height]}`);
      });
    }
  });

  test('CesiumJS\'s CesiumTerrainProvider reads the same tiles (as the globe does)', async () => {
    const { CesiumTerrainProvider } = await import('cesium');
    const provider = await CesiumTerrainProvider.fromUrl(`${base}/`, { requestVertexNormals: true, requestWaterMask: true, requestMetadata: true });
    assert.ok(provider.hasVertexNormals && provider.hasWaterMask && provider.hasMetadata);
    // Coarse to fine, as the globe loads them: the availability of levels past layer.json's
    // comes with the metadata of the tiles at multiples of metadataAvailability.
    for (const { z, x, y, tile } of [...sample].sort((a, b) => a.z - b.z)) {
      const where = `${z}/${x}/${y}`;
      // CesiumJS counts rows from the north; the URL it fetches is the TMS one.
      const data = await provider.requestTileGeometry(x, 2 ** z - 1 - y, z);
      assert.ok(data, `${where}: no terrain data`);
      assert.deepEqual(Array.from(data._quantizedVertices), Array.from(tile.raw.vertexData), `${where}: vertices`);
      assert.deepEqual(Array.from(data._indices), Array.from(tile.triangles), `${where}: triangles`);
      assert.equal(data._minimumHeight, tile.header.minHeight);
      assert.equal(data._maximumHeight, tile.header.maxHeight);
      assert.equal(data._boundingSphere.radius, tile.header.boundingSphereRadius);
      assert.deepEqual(Array.from(data._encodedNormals), Array.from(tile.normals), `${where}: normals`);
      assert.ok(data._waterMask && data._waterMask.length === tile.waterMask.length, `${where}: water mask`);
      // Availability of the children (the metadata extension and layer.json): the tile
      // holding the world's centre has children where the deepest level is not reached.
      const c = centreTile(z);
      if (z < layer.maxzoom && c.x === x && c.y === y) assert.notEqual(data._childTileMask, 0, `${where}: no child available`);
      const probe = tile.vertices[Math.floor(tile.vertices.length / 2)];
      const { Rectangle } = await import('cesium');
      const h = data.interpolateHeight(Rectangle.fromDegrees(...Object.values(tileRectOf(z, x, y))), probe.lon * Math.PI / 180, probe.lat * Math.PI / 180);
      assert.ok(Math.abs(h - probe.height) < 1e-2 + tile.step, `${where}: CesiumJS's height ${h} at a vertex of height ${probe.height}`);
    }
  });

  test('header: heights, bounding sphere and horizon occlusion point against our own ECEF arithmetic', () => {
    for (const { z, x, y, tile } of sample) checkHeader(tile, `${z}/${x}/${y}`, 0.01, geometricError(z));
  });

  test('mesh: counter-clockwise triangles, every vertex used, complete edge lists, normals up', () => {
    for (const { z, x, y, tile } of sample) checkMesh(tile, `${z}/${x}/${y}`);
  });

  test('neighbours share their edges: same positions, heights within a quantisation step, normals alike', () => {
    const at = (z, x, y) => sample.find((s) => s.z === z && s.x === x && s.y === y);
    const c = centreTile(MID);
    const [centre, east, north] = [at(MID, c.x, c.y), at(MID, c.x + 1, c.y), at(MID, c.x, c.y + 1)];
    checkSharedEdge(centre, east, 'east');
    checkSharedEdge(centre, north, 'north');
    // The children of one tile share their edges too.
    checkSharedEdge(at(MID + 1, 2 * c.x, 2 * c.y), at(MID + 1, 2 * c.x + 1, 2 * c.y), 'east');
    checkSharedEdge(at(MID + 1, 2 * c.x, 2 * c.y), at(MID + 1, 2 * c.x, 2 * c.y + 1), 'north');
  });

  test('across levels: a tile\'s edge vertices are on its children\'s edges, heights within its error', () => {
    const at = (z, x, y) => sample.find((s) => s.z === z && s.x === x && s.y === y);
    const c = centreTile(MID);
    const parent = at(MID, c.x, c.y);
    let compared = 0;
    const diffs = [];
    for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]]) {
      const child = at(MID + 1, 2 * c.x + dx, 2 * c.y + dy);
      for (const v of parent.tile.vertices) {
        const onOuterEdge = (dx === 0 && v.u === 0) || (dx === 1 && v.u === QMAX) || (dy === 0 && v.v === 0) || (dy === 1 && v.v === QMAX);
        const inside = v.lon >= child.rect.west - 1e-12 && v.lon <= child.rect.east + 1e-12 && v.lat >= child.rect.south - 1e-12 && v.lat <= child.rect.north + 1e-12;
        if (!onOuterEdge || !inside) continue;
        const match = nearestVertex(child.tile, v.lon, v.lat);
        const tolerance = 1.5 * (parent.rect.east - parent.rect.west) / QMAX;
        assert.ok(match.distance <= tolerance, `parent vertex (${v.lon}, ${v.lat}) has no vertex of child ${child.z}/${child.x}/${child.y} within ${tolerance}°`);
        diffs.push(Math.abs(match.vertex.height - v.height));
        compared += 1;
      }
    }
    assert.ok(compared >= 8, `only ${compared} edge vertices compared`);
    diffs.sort((a, b) => a - b);
    const [median, max] = [diffs[diffs.length >> 1], diffs[diffs.length - 1]];
    console.log(`edge heights, level ${MID} against its children: median ${median.toFixed(2)} m, max ${max.toFixed(2)} m over ${compared} vertices`);
    // Each level samples the terrain with the detail its grid resolves (the world's LOD), so the
    // heights differ by what the finer level adds: never more than the coarser level's error,
    // which CesiumJS's skirts cover.
    assert.ok(max <= geometricError(MID), `edge heights differ by up to ${max} m across levels (level ${MID}'s error ${geometricError(MID)} m)`);
  });

  test('heights agree with the world\'s own (Terrain-RGB tiles) within the level\'s error', async () => {
    const failures = [];
    for (const { z, x, y, rect, tile } of sample.filter((s) => s.z >= MID)) {
      const where = `${z}/${x}/${y}`;
      // Reference tiles about 8 times finer than the Cesium tile's grid spacing.
      const zoom = Math.min(world.web?.maxzoom ?? 18, z + 4);
      const heightAt = worldHeights(server.url, world.id, zoom);
      // The sea is drawn at its surface (0 m: Cesium puts its water there), not at its floor.
      // At the vertices (grid samples): the world's height there, to within the quantisation
      // and the reference's own interpolation.
      const vertexErrors = [];
      for (const v of tile.vertices) vertexErrors.push(Math.abs(v.height - Math.max(0, await heightAt(v.lon, v.lat))));
      // Anywhere: the mesh is within the level's error of the terrain.
      const pointErrors = [];
      for (let i = 0; i < 400; ++i) {
        const [fu, fv] = [(i % 20 + 0.5) / 20, (Math.floor(i / 20) + 0.5) / 20];
        const lon = rect.west + fu * (rect.east - rect.west), lat = rect.south + fv * (rect.north - rect.south);
        pointErrors.push(Math.abs(meshHeightAt(tile, rect, lon, lat) - Math.max(0, await heightAt(lon, lat))));
      }
      const stats = (e) => { const s = [...e].sort((a, b) => a - b); return { median: s[s.length >> 1], p95: s[Math.floor(0.95 * s.length)], max: s[s.length - 1] }; };
      const [atVertices, anywhere] = [stats(vertexErrors), stats(pointErrors)];
      const error = geometricError(z);
      console.log(`${where}: |mesh − world| at vertices ${JSON.stringify(atVertices)}, anywhere ${JSON.stringify(anywhere)}, level error ${error.toFixed(1)} m`);
      // Only where the reference is 4 levels finer: at the deepest level it is 1 level finer, and
      // its own interpolation is as large as the level's error (z17: a vertex 0.99 m off where
      // the median is 0.01 m).
      if (zoom - z >= 4 && !(atVertices.max <= error + tile.step)) failures.push(`${where} at vertices: ${JSON.stringify(atVertices)} (level error ${error} m)`);
      if (!(anywhere.p95 <= error && anywhere.max <= 2 * error)) failures.push(`${where} anywhere: ${JSON.stringify(anywhere)} (level error ${error} m)`);
    }
    assert.deepEqual(failures, []);
  });

  test('normals follow the terrain\'s gradient', async () => {
    for (const { z, x, y, rect, tile } of sample.filter((s) => s.z >= MID)) {
      const heightAt = worldHeights(server.url, world.id, Math.min(world.web?.maxzoom ?? 18, z + 4));
      const spacing = (rect.north - rect.south) / 64; // the tile's grid, in degrees of latitude
      const angles = [];
      for (const v of tile.vertices.filter((_, i) => i % 4 === 0)) {
        const [l, p] = [v.lon * Math.PI / 180, v.lat * Math.PI / 180];
        const up = [Math.cos(p) * Math.cos(l), Math.cos(p) * Math.sin(l), Math.sin(p)];
        const east = [-Math.sin(l), Math.cos(l), 0];
        const northDir = [-Math.sin(p) * Math.cos(l), -Math.sin(p) * Math.sin(l), Math.cos(p)];
        const dLat = spacing, dLon = spacing / Math.cos(p);
        const metres = 6378137 * spacing * Math.PI / 180;
        const dhdx = (await heightAt(v.lon + dLon, v.lat) - await heightAt(v.lon - dLon, v.lat)) / (2 * metres);
        const dhdy = (await heightAt(v.lon, v.lat + dLat) - await heightAt(v.lon, v.lat - dLat)) / (2 * metres);
        const n = up.map((c, k) => c - dhdx * east[k] - dhdy * northDir[k]);
        angles.push(Math.acos(Math.min(1, dot(n, v.normal) / norm(n))) * 180 / Math.PI);
      }
      angles.sort((a, b) => a - b);
      const [median, p90] = [angles[angles.length >> 1], angles[Math.floor(0.9 * angles.length)]];
      console.log(`${z}/${x}/${y}: normal vs the world's gradient: median ${median.toFixed(2)}°, p90 ${p90.toFixed(2)}°`);
      assert.ok(median < 3 && p90 < 10, `${z}/${x}/${y}: median ${median}°, p90 ${p90}°`);
    }
  });

  test('water mask: land and water on the coast, land on the hills, water on the sea', () => {
    const c = sample.find((s) => s.z === 9);
    let wetSea = 0, sea = 0;
    for (const { z, x, y, tile } of sample.filter((s) => s.z >= 9)) {
      const mask = tile.waterMask;
      assert.ok(mask.length === 1 || mask.length === 256 * 256, `${z}/${x}/${y}: mask of ${mask.length} bytes`);
      if (mask.length === 1) continue;
      // Row 0 north, column 0 west.
      const cell = (v) => mask[Math.min(255, Math.floor((1 - v.v / QMAX) * 256)) * 256 + Math.min(255, Math.floor((v.u / QMAX) * 256))];
      // The sea is drawn at 0 m; rivers and lakes are water above it, so only the hills are sure land.
      const surface = tile.vertices.filter((v) => v.height === 0);
      const high = tile.vertices.filter((v) => v.height > 50);
      const dry = high.filter((v) => cell(v) <= 127).length;
      sea += surface.length;
      wetSea += surface.filter((v) => cell(v) > 127).length;
      assert.ok(high.length === 0 || dry >= 0.95 * high.length, `${z}/${x}/${y}: ${dry} of ${high.length} vertices above 50 m are land`);
    }
    assert.ok(sea > 0 && wetSea >= 0.8 * sea, `${wetSea} of ${sea} vertices at sea level are water`);
    // The level-9 tile at the world's centre holds much of the island: land and sea.
    const mask = c.tile.waterMask;
    assert.ok(mask.length === 256 * 256 && mask.some((b) => b === 0) && mask.some((b) => b === 255), `${c.z}/${c.x}/${c.y}: the mask is not a coast`);
  });

  test('metadata: the tiles of level 0 give the availability of the next levels', () => {
    for (const { z, x, y, tile } of sample.filter((s) => s.z % layer.metadataAvailability === 0)) {
      const available = tile.metadata?.available;
      assert.ok(Array.isArray(available) && available.length >= 1, `${z}/${x}/${y}: ${JSON.stringify(tile.metadata)}`);
      assert.ok(available.length <= layer.metadataAvailability);
      // Level z + 1 + i: the tiles under this one that hold the world's centre are listed.
      available.forEach((ranges, i) => {
        const level = z + 1 + i;
        const t = centreTile(level);
        if (t.x >> (level - z) !== x || t.y >> (level - z) !== y) return;
        assert.ok(ranges.some((r) => t.x >= r.startX && t.x <= r.endX && t.y >= r.startY && t.y <= r.endY),
          `${z}/${x}/${y}: level ${level}'s centre tile ${t.x}/${t.y} missing from ${JSON.stringify(ranges)}`);
      });
    }
  });
});

describe('outside the world', () => {
  test('a tile away from the world is the ellipsoid under an all-water mask', async () => {
    const [west, south] = world.bounds;
    // Far away at a coarse level, just off the world's south-west corner, and at the deepest level.
    const away = [[3, 0, 0], Object.values(tileAt(MID, west - 0.5, south - 0.5)), Object.values(tileAt(layer.maxzoom, west - 0.2, south))];
    for (const coords of away) await checkEllipsoidTile(await fetchTile(...coords));
  });
});

/** The ellipsoid under an all-water mask: heights 0, the ellipsoid's normals, a valid header. */
async function checkEllipsoidTile({ tile, z, x, y }) {
  const where = `${z}/${x}/${y}`;
  assert.equal(tile.header.minHeight, 0, where);
  assert.equal(tile.header.maxHeight, 0, where);
  assert.ok(tile.vertices.every((v) => v.height === 0), where);
  assert.ok(tile.waterMask.every((b) => b === 255), `${where}: not all water`);
  checkHeader(tile, where, 0.01, 0);
  checkMesh(tile, where);
  for (const v of tile.vertices) {
    const [l, p] = [v.lon * Math.PI / 180, v.lat * Math.PI / 180];
    const up = [Math.cos(p) * Math.cos(l), Math.cos(p) * Math.sin(l), Math.sin(p)];
    assert.ok(dot(up, v.normal) > Math.cos(2 * Math.PI / 180), `${where}: normal ${v.normal} at (${v.lon}, ${v.lat})`);
  }
}

describe('the checks themselves', () => {
  test('accept a tile of Cesium World Terrain at its own coordinates, and reject it elsewhere', () => {
    // @here/quantized-mesh-decoder's sample, a tile of Cesium World Terrain: TMS 11/3035/1345.
    const require = createRequire(import.meta.url);
    const file = require.resolve('@here/quantized-mesh-decoder/src/assets/tile-with-extensions.terrain');
    const bytes = arrayBufferOf(readFileSync(file));
    const cwt = decodeTile(bytes.slice(0), tileRect(11, 3035, 1345));
    checkHeader(cwt, 'Cesium World Terrain 11/3035/1345', 0.5);
    checkMesh(cwt, 'Cesium World Terrain 11/3035/1345');
    assert.throws(() => checkHeader(decodeTile(bytes.slice(0), tileRect(11, 3036, 1345)), 'one tile east', 0.5), /from the sphere's centre/);
    assert.throws(() => checkHeader(decodeTile(bytes.slice(0), tileRect(11, 3035, 1346)), 'one tile north', 0.5), /from the sphere's centre/);
  });
});

// ---- the checks --------------------------------------------------------------------------

function tileRectOf(z, x, y) {
  const r = tileRect(z, x, y);
  return { west: r.west, south: r.south, east: r.east, north: r.north };
}

/**
 * Header against our own arithmetic: heights within [min, max] and reaching both, the bounding
 * sphere holding every vertex (ECEF) and not much larger than needed, the centre inside it, the
 * horizon occlusion point hiding no vertex and no farther out than the vertices need.
 * `slack` (m) allows for tiles that were not made from exactly their decoded vertices.
 */
function checkHeader(tile, where, slack = 0.01, reach = Infinity) {
  const h = tile.header;
  assert.ok(h.minHeight <= h.maxHeight, `${where}: min ${h.minHeight} > max ${h.maxHeight}`);
  // The quantised heights span [min, max]; the extremes of the area are no farther than `reach`
  // (the mesh's error) from the vertices' (Cesium World Terrain's are of the whole area).
  const heights = tile.vertices.map((v) => v.height);
  assert.ok(Math.min(...heights) - h.minHeight <= reach && h.maxHeight - Math.max(...heights) <= reach,
    `${where}: vertices span [${Math.min(...heights)}, ${Math.max(...heights)}], the header [${h.minHeight}, ${h.maxHeight}]`);
  const centre = [h.boundingSphereCenterX, h.boundingSphereCenterY, h.boundingSphereCenterZ];
  const points = tile.vertices.map((v) => ecef(v.lon, v.lat, v.height));
  const farthest = Math.max(...points.map((p) => norm(sub(p, centre))));
  assert.ok(farthest <= h.boundingSphereRadius + slack + tile.step, `${where}: a vertex ${farthest} m from the sphere's centre, radius ${h.boundingSphereRadius}`);
  // The smallest sphere is at least half the box's diagonal; the box's own sphere is an upper bound.
  const lo = [0, 1, 2].map((k) => Math.min(...points.map((p) => p[k])));
  const hi = [0, 1, 2].map((k) => Math.max(...points.map((p) => p[k])));
  const boxRadius = norm(sub(hi, lo)) / 2;
  assert.ok(h.boundingSphereRadius <= 1.01 * boxRadius + slack + tile.step, `${where}: radius ${h.boundingSphereRadius} m, the box's sphere ${boxRadius} m`);
  const tileCentre = [h.centerX, h.centerY, h.centerZ];
  assert.ok(norm(sub(tileCentre, centre)) <= h.boundingSphereRadius, `${where}: the tile's centre is outside its bounding sphere`);

  const hop = [h.horizonOcclusionPointX, h.horizonOcclusionPointY, h.horizonOcclusionPointZ];
  const magnitude = norm(hop);
  const direction = hop.map((c) => c / magnitude);
  const candidates = points.map((p) => occlusionMagnitude(scaled(p, h.minHeight), direction));
  if (candidates.some((m) => !(m > 0) || !Number.isFinite(m) || m > 1e6)) {
    // No point along this direction sees the whole tile (one as wide as a hemisphere): Cesium's
    // own construction gives none. Then a point far out towards the tile, which only the far
    // side of the globe hides, is the one that culls nothing visible.
    const towards = scaled(tileCentre);
    assert.ok(magnitude >= 1e3 && dot(direction, towards) / norm(towards) > 0.5,
      `${where}: no horizon point can hide this tile's vertices, yet it is at magnitude ${magnitude}`);
    return;
  }
  const needed = Math.max(...candidates);
  // Relative 1e-7 ≈ 0.6 m at the Earth's radius: the decoded vertices are quantised.
  assert.ok(magnitude >= needed * (1 - 1e-7), `${where}: the horizon occlusion point (magnitude ${magnitude}) hides vertices that need ${needed}`);
  assert.ok(magnitude <= needed * (1 + 1e-4), `${where}: the horizon occlusion point (magnitude ${magnitude}) is farther than needed (${needed}): tiles drawn that could be culled`);
}

/** Triangles counter-clockwise and not degenerate, every vertex used, edge lists exact, normals up. */
function checkMesh(tile, where) {
  const V = tile.vertices, t = tile.triangles;
  assert.ok(t.length >= 6 && t.length % 3 === 0, `${where}: ${t.length / 3} triangles`);
  const used = new Uint8Array(V.length);
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [V[t[i]], V[t[i + 1]], V[t[i + 2]]];
    assert.ok(a && b && c, `${where}: triangle ${i / 3} indexes past the vertices`);
    const area2 = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
    assert.ok(area2 > 0, `${where}: triangle ${i / 3} is clockwise or degenerate (${area2})`);
    used[t[i]] = used[t[i + 1]] = used[t[i + 2]] = 1;
  }
  assert.ok(used.every((u) => u === 1), `${where}: vertices no triangle uses`);
  // High-water-mark order: the first use of vertex k comes after the first use of k − 1.
  let highest = -1;
  for (const index of t) {
    assert.ok(index <= highest + 1, `${where}: vertices not in order of first use`);
    highest = Math.max(highest, index);
  }
  const expect = { west: (v) => v.u === 0, east: (v) => v.u === QMAX, south: (v) => v.v === 0, north: (v) => v.v === QMAX };
  for (const [side, on] of Object.entries(expect)) {
    const listed = new Set(tile.edges[side]);
    assert.ok(listed.size >= 2, `${where}: ${side} edge list has ${listed.size} vertices`);
    const onEdge = new Set(V.map((v, i) => (on(v) ? i : -1)).filter((i) => i >= 0));
    assert.deepEqual([...listed].sort((a, b) => a - b), [...onEdge].sort((a, b) => a - b), `${where}: the ${side} edge list`);
  }
  assert.ok(tile.normals && tile.normals.length === 2 * V.length, `${where}: ${tile.normals?.length} normal bytes for ${V.length} vertices`);
  for (const v of V) {
    const [l, p] = [v.lon * Math.PI / 180, v.lat * Math.PI / 180];
    const up = [Math.cos(p) * Math.cos(l), Math.cos(p) * Math.sin(l), Math.sin(p)];
    assert.ok(Math.abs(norm(v.normal) - 1) < 1e-9 && dot(up, v.normal) > 0.05, `${where}: normal ${v.normal} at (${v.lon}, ${v.lat}) points down`);
  }
}

/** A's edge towards `side` ('east' or 'north') against B's opposite edge. */
function checkSharedEdge(a, b, side) {
  const where = `${a.z}/${a.x}/${a.y} ${side} of it ${b.z}/${b.x}/${b.y}`;
  const [mine, theirs, key] = side === 'east' ? ['east', 'west', 'v'] : ['north', 'south', 'u'];
  const edgeA = [...a.tile.edges[mine]].map((i) => a.tile.vertices[i]).sort((p, q) => p[key] - q[key]);
  const edgeB = [...b.tile.edges[theirs]].map((i) => b.tile.vertices[i]).sort((p, q) => p[key] - q[key]);
  assert.deepEqual(edgeA.map((v) => v[key]), edgeB.map((v) => v[key]), `${where}: the edges' vertices are not at the same places`);
  const step = a.tile.step + b.tile.step + 1e-3;
  edgeA.forEach((v, i) => {
    const w = edgeB[i];
    assert.ok(Math.abs(v.height - w.height) <= step, `${where}: ${v.height} m vs ${w.height} m at ${key} ${v[key]}`);
    const angle = Math.acos(Math.min(1, dot(v.normal, w.normal))) * 180 / Math.PI;
    assert.ok(angle < 2, `${where}: normals ${angle.toFixed(2)}° apart at ${key} ${v[key]}`);
  });
}

function nearestVertex(tile, lon, lat) {
  let best = { distance: Infinity, vertex: null };
  for (const v of tile.vertices) {
    const d = Math.max(Math.abs(v.lon - lon), Math.abs(v.lat - lat));
    if (d < best.distance) best = { distance: d, vertex: v };
  }
  return best;
}
