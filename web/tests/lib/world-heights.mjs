// The heights strahler reports for a world, read back from its Terrain-RGB raster tiles (Web
// Mercator XYZ, pixel centres, height = −10000 + (R·65536 + G·256 + B) · 0.1 m), bilinearly
// interpolated: an independent reference for the heights of its quantized-mesh tiles.
import { PNG } from 'pngjs';
import { get } from './http.mjs';

const SIZE = 256;

/** heightAt(lon, lat) in m, from the tiles of zoom `zoom` of /worlds/{id}/tiles (fetched once each). */
export function worldHeights(baseUrl, worldId, zoom) {
  const tiles = new Map();
  const n = 2 ** zoom;
  async function tile(x, y) {
    const key = `${x}/${y}`;
    if (!tiles.has(key)) {
      tiles.set(key, (async () => {
        const r = await get(`${baseUrl}/worlds/${worldId}/tiles/${zoom}/${x}/${y}.png`);
        if (r.status !== 200) throw new Error(`tile ${zoom}/${key}: HTTP ${r.status}`);
        const { data } = PNG.sync.read(r.body);
        const heights = new Float64Array(SIZE * SIZE);
        for (let i = 0; i < heights.length; ++i) {
          heights[i] = -10000 + (data[4 * i] * 65536 + data[4 * i + 1] * 256 + data[4 * i + 2]) * 0.1;
        }
        return heights;
      })());
    }
    return tiles.get(key);
  }
  // The height of global pixel (px, py) of the zoom's whole raster (n · 256 pixels a side).
  async function pixel(px, py) {
    const [x, y] = [Math.floor(px / SIZE), Math.floor(py / SIZE)];
    return (await tile(x, y))[(py - y * SIZE) * SIZE + (px - x * SIZE)];
  }
  return async function heightAt(lon, lat) {
    const s = Math.sin(lat * Math.PI / 180);
    const gx = ((lon + 180) / 360) * n * SIZE - 0.5;
    const gy = (0.5 - Math.log((1 + s) / (1 - s)) / (4 * Math.PI)) * n * SIZE - 0.5;
    const [x0, y0] = [Math.floor(gx), Math.floor(gy)];
    const [fx, fy] = [gx - x0, gy - y0];
    const [a, b, c, d] = await Promise.all([pixel(x0, y0), pixel(x0 + 1, y0), pixel(x0, y0 + 1), pixel(x0 + 1, y0 + 1)]);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
  };
}
