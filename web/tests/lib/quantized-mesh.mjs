// Independent arithmetic for checking quantized-mesh-1.0 tiles: the TMS geographic tiling
// (EPSG:4326, 2 × 1 root tiles), WGS84 geodetic → ECEF, oct-encoded normals, Cesium's
// horizon-occlusion magnitude, and the tile decoded by two npm decoders that are not ours.
import hereDecoder from '@here/quantized-mesh-decoder';
import { QuantizedMeshLoader } from '@loaders.gl/terrain';

// The package is UMD: Node's CommonJS interop puts its exports under default.
const decodeHere = hereDecoder.default ?? hereDecoder;

export const WGS84 = { a: 6378137.0, b: 6356752.3142451793 };
const E2 = 1 - (WGS84.b * WGS84.b) / (WGS84.a * WGS84.a);
export const QMAX = 32767;

/** The tile's rectangle in degrees: {west, south, east, north}; y counts from the south (TMS). */
export function tileRect(z, x, y) {
  const size = 180 / 2 ** z;
  return { west: -180 + x * size, south: -90 + y * size, east: -180 + (x + 1) * size, north: -90 + (y + 1) * size };
}

/** The tile of level `z` that holds (lon, lat). */
export function tileAt(z, lon, lat) {
  const size = 180 / 2 ** z;
  return { z, x: Math.floor((lon + 180) / size), y: Math.floor((lat + 90) / size) };
}

/** ECEF [x, y, z] of a WGS84 geodetic position (degrees, metres above the ellipsoid). */
export function ecef(lon, lat, height) {
  const [l, p] = [lon * Math.PI / 180, lat * Math.PI / 180];
  const n = WGS84.a / Math.sqrt(1 - E2 * Math.sin(p) ** 2);
  return [(n + height) * Math.cos(p) * Math.cos(l), (n + height) * Math.cos(p) * Math.sin(l), (n * (1 - E2) + height) * Math.sin(p)];
}

export const sub = (a, b) => a.map((v, i) => v - b[i]);
export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const norm = (a) => Math.sqrt(dot(a, a));
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** A unit vector from its 2-byte oct encoding (the octvertexnormals extension). */
export function octDecode(xByte, yByte) {
  const fromSnorm = (v) => Math.max(-1, Math.min(1, v / 255 * 2 - 1));
  let [x, y] = [fromSnorm(xByte), fromSnorm(yByte)];
  const z = 1 - Math.abs(x) - Math.abs(y);
  if (z < 0) [x, y] = [(1 - Math.abs(y)) * Math.sign(x || 1), (1 - Math.abs(x)) * Math.sign(y || 1)];
  const v = [x, y, z];
  return v.map((c) => c / norm(v));
}

/**
 * The magnitude along the unit scaled-space direction `direction` at which a point hides the
 * scaled-space `position` below the horizon, as Cesium's EllipsoidalOccluder computes it (points
 * below the ellipsoid count as on it). A horizon occlusion point is valid when its magnitude is
 * at least this for every vertex.
 */
export function occlusionMagnitude(position, direction) {
  const magnitudeSquared = Math.max(1, dot(position, position));
  const magnitude = Math.max(1, Math.sqrt(dot(position, position)));
  const unit = position.map((c) => c / Math.sqrt(dot(position, position)));
  const cosAlpha = dot(unit, direction);
  const sinAlpha = norm(cross(unit, direction));
  const cosBeta = 1 / magnitude;
  const sinBeta = Math.sqrt(magnitudeSquared - 1) * cosBeta;
  return 1 / (cosAlpha * cosBeta - sinAlpha * sinBeta);
}

/**
 * ECEF → the ellipsoid-scaled space (divided by the radii) of the horizon occlusion point. For a
 * tile that reaches below the ellipsoid (minimumHeight < 0), CesiumJS tests the point against
 * the ellipsoid shrunk by that height (EllipsoidalOccluder's
 * isScaledSpacePointVisiblePossiblyUnderEllipsoid), so it is that ellipsoid's scaled space.
 */
export function scaled(p, minimumHeight = 0) {
  const shrink = minimumHeight < 0 && WGS84.b > -minimumHeight ? minimumHeight : 0;
  return [p[0] / (WGS84.a + shrink), p[1] / (WGS84.a + shrink), p[2] / (WGS84.b + shrink)];
}

/**
 * A .terrain body decoded by @here/quantized-mesh-decoder, with each vertex's longitude,
 * latitude and height in the tile `rect`, the normals decoded and the water mask as bytes.
 */
export function decodeTile(arrayBuffer, rect) {
  const d = decodeHere(arrayBuffer);
  const n = d.vertexData.length / 3;
  const { minHeight, maxHeight } = d.header;
  const vertices = [];
  for (let i = 0; i < n; ++i) {
    const [u, v, h] = [d.vertexData[i], d.vertexData[i + n], d.vertexData[i + 2 * n]];
    vertices.push({
      u, v, q: h,
      lon: rect.west + (u / QMAX) * (rect.east - rect.west),
      lat: rect.south + (v / QMAX) * (rect.north - rect.south),
      height: minHeight + (h / QMAX) * (maxHeight - minHeight),
    });
  }
  const ext = d.extensions ?? {};
  if (ext.vertexNormals) {
    for (let i = 0; i < n; ++i) vertices[i].normal = octDecode(ext.vertexNormals[2 * i], ext.vertexNormals[2 * i + 1]);
  }
  return {
    raw: d, header: d.header, vertices, triangles: d.triangleIndices,
    edges: { west: d.westIndices, south: d.southIndices, east: d.eastIndices, north: d.northIndices },
    waterMask: ext.waterMask ? new Uint8Array(ext.waterMask) : null,
    metadata: ext.metadata ?? null, normals: ext.vertexNormals ?? null,
    // One step of the height quantisation.
    step: (maxHeight - minHeight) / QMAX,
  };
}

/** The same body parsed by @loaders.gl/terrain's QuantizedMeshLoader: {positions (lon, lat, h), indices}. */
export async function decodeWithLoadersGl(arrayBuffer, rect) {
  const mesh = await QuantizedMeshLoader.parse(arrayBuffer, { 'quantized-mesh': { bounds: [rect.west, rect.south, rect.east, rect.north] } });
  return { positions: mesh.attributes.POSITION.value, indices: mesh.indices.value };
}

/**
 * The height of the mesh at (lon, lat), interpolated in the triangle that holds it (barycentric
 * in u, v), or null when no triangle does.
 */
export function meshHeightAt(tile, rect, lon, lat) {
  const u = ((lon - rect.west) / (rect.east - rect.west)) * QMAX;
  const v = ((lat - rect.south) / (rect.north - rect.south)) * QMAX;
  const t = tile.triangles, V = tile.vertices;
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [V[t[i]], V[t[i + 1]], V[t[i + 2]]];
    const det = (b.v - c.v) * (a.u - c.u) + (c.u - b.u) * (a.v - c.v);
    if (det === 0) continue;
    const l1 = ((b.v - c.v) * (u - c.u) + (c.u - b.u) * (v - c.v)) / det;
    const l2 = ((c.v - a.v) * (u - c.u) + (a.u - c.u) * (v - c.v)) / det;
    const l3 = 1 - l1 - l2;
    const eps = -1e-9;
    if (l1 >= eps && l2 >= eps && l3 >= eps) return l1 * a.height + l2 * b.height + l3 * c.height;
  }
  return null;
}
