// Is a screenshot more than a blank canvas? Luminance spread and colour count of a PNG.
import { PNG } from 'pngjs';

export function pixelStats(pngBytes) {
  const { data, width, height } = PNG.sync.read(pngBytes);
  let sum = 0, sumSq = 0;
  const colours = new Set();
  for (let i = 0; i < data.length; i += 4) {
    const luminance = 0.2126 * data[i] + 0.7152 * data[i + 1] + 0.0722 * data[i + 2];
    sum += luminance;
    sumSq += luminance * luminance;
    colours.add((data[i] >> 3) << 10 | (data[i + 1] >> 3) << 5 | data[i + 2] >> 3); // 15-bit colour
  }
  const n = width * height;
  const mean = sum / n;
  return { width, height, mean, stdDev: Math.sqrt(Math.max(0, sumSq / n - mean * mean)), colours: colours.size };
}

/** The [r, g, b] of pixel (x, y) of a PNG (coordinates rounded). */
export function pixelAt(pngBytes, x, y) {
  const { data, width } = PNG.sync.read(pngBytes);
  const i = 4 * (Math.round(y) * width + Math.round(x));
  return [data[i], data[i + 1], data[i + 2]];
}

/** The share of pixels of two same-sized PNGs whose colour differs by more than `tolerance` in a channel. */
export function changedShare(pngA, pngB, tolerance = 8) {
  const a = PNG.sync.read(pngA), b = PNG.sync.read(pngB);
  if (a.width !== b.width || a.height !== b.height) throw new Error(`${a.width}×${a.height} vs ${b.width}×${b.height}`);
  let changed = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if ([0, 1, 2].some((k) => Math.abs(a.data[i + k] - b.data[i + k]) > tolerance)) ++changed;
  }
  return changed / (a.width * a.height);
}
