// The derived layers the viewer can lay over the terrain (GET /worlds/{id}/layers/{name}/…),
// each with the colour ramp that draws it and the legend of that ramp.
//
// Layer tiles are grey PNGs (docs/http.md, "Layer tiles"). MapLibre cannot colour a raster by value
// (no `raster-color` in MapLibre GL JS 6), so their tiles go through the "grey" protocol: the
// browser decodes the PNG, each grey code is looked up in a 256-entry table built from the
// ramp, and the coloured image goes to MapLibre. The legend is drawn from the same table, so it
// shows exactly the colours on the map.
//
// A canvas holds 8 bits per channel: a 16-bit PNG (slope) reaches the page as its high byte,
// 256 of its units per grey code. Slope (degrees × 100) therefore arrives in steps of 2.56°,
// and the legend draws those steps as they are.

const PROTOCOL = 'grey';

// Linear interpolation between [value, [r, g, b, a]] stops (a in 0..1), clamped at the ends.
function ramp(stops) {
  return (value) => {
    if (value <= stops[0][0]) return stops[0][1];
    for (let i = 1; i < stops.length; i++) {
      const [v1, c1] = stops[i];
      if (value <= v1) {
        const [v0, c0] = stops[i - 1];
        const t = (value - v0) / (v1 - v0);
        return c0.map((c, k) => c + t * (c1[k] - c));
      }
    }
    return stops[stops.length - 1][1];
  };
}

const share = (code) => code / 255;

/**
 * The overlays: `layer` and `query` name the tiles, `value(code)` turns a decoded grey code
 * into the layer's unit, `colour(value)` is the ramp, `codes` the codes the layer can take,
 * `ticks` the values labelled on the legend.
 */
export const OVERLAYS = [
  {
    id: 'slope', layer: 'slope', query: '', label: 'Slope', unit: '°', opacity: 0.7,
    note: '16-bit PNG read as its high byte: steps of 2.56° (below 2.56°: clear)',
    // The high byte c covers degrees × 100 in [256 c, 256 c + 255]: its middle.
    value: (code) => (256 * code + 128) / 100, codes: 36, ticks: [0, 15, 30, 45, 60, 90],
    colour: ramp([[1.28, [255, 255, 212, 0]], [3, [255, 255, 212, 0.5]], [5, [254, 227, 145, 1]], [15, [254, 153, 41, 1]],
      [30, [217, 72, 1, 1]], [45, [140, 45, 4, 1]], [90, [60, 10, 40, 1]]]),
  },
  {
    id: 'illumination', layer: 'illumination', query: '', label: 'Illumination (sky view)', unit: '', opacity: 0.7,
    note: 'share of the sky seen',
    value: share, codes: 256, ticks: [0, 0.6, 0.8, 1],
    // Most ground sees more than half its sky: the ramp spends its contrast there.
    colour: ramp([[0, [20, 20, 60, 1]], [0.6, [70, 60, 110, 1]], [0.8, [170, 150, 150, 1]], [0.9, [235, 215, 165, 1]],
      [1, [255, 250, 225, 1]]]),
  },
  {
    id: 'humidity', layer: 'humidity', query: '', label: 'Humidity', unit: '', opacity: 0.7,
    note: 'wetness 0…1 (1 below sea level)',
    value: share, codes: 256, ticks: [0, 0.5, 1],
    colour: ramp([[0, [247, 251, 255, 0.2]], [0.3, [158, 202, 225, 0.8]], [0.7, [33, 113, 181, 1]], [1, [8, 48, 107, 1]]]),
  },
  {
    id: 'vegetation-tree', layer: 'vegetation', query: '?species=tree', label: 'Trees', unit: '', opacity: 0.75,
    note: 'density of trees 0…1',
    value: share, codes: 256, ticks: [0, 0.5, 1],
    colour: ramp([[0, [255, 255, 229, 0.1]], [0.25, [173, 221, 142, 0.9]], [0.6, [49, 163, 84, 1]], [1, [0, 69, 41, 1]]]),
  },
  {
    id: 'vegetation-bush', layer: 'vegetation', query: '?species=bush', label: 'Bushes', unit: '', opacity: 0.75,
    note: 'density of bushes 0…1',
    value: share, codes: 256, ticks: [0, 0.5, 1],
    colour: ramp([[0, [255, 255, 229, 0.1]], [0.25, [217, 240, 163, 0.9]], [0.6, [161, 161, 52, 1]], [1, [102, 84, 18, 1]]]),
  },
  {
    id: 'water', layer: 'water', query: '', label: 'Water', unit: '', opacity: 0.8,
    note: 'sea, lakes and rivers at least a pixel wide',
    value: (code) => (code >= 128 ? 1 : 0), codes: 256, ticks: [],
    colour: (value) => (value ? [0, 90, 255, 1] : [0, 0, 0, 0]),
  },
];

const tables = new Map();

/** The RGBA table (4 bytes per grey code 0…255) that draws `overlay`. */
export function colourTable(overlay) {
  if (!tables.has(overlay.id)) {
    const table = new Uint8ClampedArray(256 * 4);
    for (let code = 0; code < 256; code++) {
      const [r, g, b, a] = overlay.colour(overlay.value(Math.min(code, overlay.codes - 1)));
      table.set([r, g, b, 255 * a], 4 * code);
    }
    tables.set(overlay.id, table);
  }
  return tables.get(overlay.id);
}

/** The overlay whose tiles `url` names (…/layers/{name}/{z}/{x}/{y}.png[?species=…][&v=…]), or null. */
export function overlayOfUrl(url) {
  const match = /\/layers\/([a-z]+)\/\d+\/\d+\/\d+\.png(\?[^#]*)?$/.exec(url);
  if (!match) return null;
  const [, layer, given = ''] = match;
  // The world's version (`v`, which the TileJSON's tile URLs carry) does not name the overlay.
  const params = new URLSearchParams(given);
  params.delete('v');
  const query = params.toString() ? `?${params}` : '';
  return OVERLAYS.find((o) => o.layer === layer && (o.query === query || (!query && o.query === '?species=tree'))) ?? null;
}

/**
 * Decodes a grey PNG as the browser does onto an OffscreenCanvas: { canvas, context, image },
 * the grey codes in the red channel of `image` (8-bit: the value; 16-bit: its high byte, as
 * the browser test checks against pngjs).
 */
export async function readGrey(blob) {
  // No colour management and no premultiplication: the grey codes must arrive unchanged.
  const bitmap = await createImageBitmap(blob, { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d', { willReadFrequently: true });
  context.drawImage(bitmap, 0, 0);
  bitmap.close();
  return { canvas, context, image: context.getImageData(0, 0, canvas.width, canvas.height) };
}

/** The URL MapLibre should request for a layer tile at `url` (use it in transformRequest). */
export const greyUrl = (url) => `${PROTOCOL}://${url}`;

/**
 * Registers the "grey" protocol. `stats[overlay.id]` counts the tiles drawn and the lowest and
 * highest grey codes seen (tests read it: a layer that draws tiles of one grey says nothing).
 */
export function registerGreyProtocol(maplibregl, stats = {}) {
  maplibregl.addProtocol(PROTOCOL, async (params, abortController) => {
    const url = params.url.slice(PROTOCOL.length + 3);
    const overlay = overlayOfUrl(url);
    if (!overlay) throw new Error(`not a layer tile: ${url}`);
    const response = await fetch(url, { signal: abortController.signal });
    if (!response.ok) throw new Error(`layer tile ${url}: HTTP ${response.status}`);
    const { canvas, context, image } = await readGrey(await response.blob());
    const pixels = image.data;
    const table = colourTable(overlay);
    let low = 255, high = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      const code = pixels[i];
      if (code < low) low = code;
      if (code > high) high = code;
      pixels.set(table.subarray(4 * code, 4 * code + 4), i);
    }
    context.putImageData(image, 0, 0);
    const s = (stats[overlay.id] ??= { tiles: 0, low: 255, high: 0 });
    Object.assign(s, { tiles: s.tiles + 1, low: Math.min(s.low, low), high: Math.max(s.high, high) });
    return { data: canvas.transferToImageBitmap() };
  });
  return stats;
}

/** A legend for `overlay`: its label, a bar of the colours of its grey codes, value ticks, a note. */
export function legendOf(overlay) {
  const box = document.createElement('div');
  box.className = 'layer-legend';
  const title = document.createElement('div');
  title.textContent = `${overlay.label}${overlay.unit ? ` (${overlay.unit})` : ''}`;
  const bar = document.createElement('canvas');
  const table = colourTable(overlay);
  if (overlay.ticks.length === 0) {
    // Two classes (water): a swatch of each.
    bar.width = 2;
    bar.height = 1;
    bar.className = 'legend-classes';
  } else {
    bar.width = overlay.codes;
    bar.height = 1;
    bar.className = 'legend-bar';
  }
  const context = bar.getContext('2d');
  const image = context.createImageData(bar.width, 1);
  const codes = overlay.ticks.length === 0 ? [0, 255] : [...Array(overlay.codes).keys()];
  codes.forEach((code, i) => image.data.set(table.subarray(4 * code, 4 * code + 4), 4 * i));
  context.putImageData(image, 0, 0);
  const ticks = document.createElement('div');
  ticks.className = 'legend-ticks';
  const [first, last] = [overlay.value(0), overlay.value(overlay.codes - 1)];
  for (const tick of overlay.ticks) {
    const span = document.createElement('span');
    span.textContent = `${tick}${overlay.unit}`;
    span.style.left = `${(100 * (Math.min(Math.max(tick, first), last) - first)) / (last - first)}%`;
    ticks.append(span);
  }
  if (overlay.ticks.length === 0) ticks.textContent = 'land · water';
  const note = document.createElement('div');
  note.className = 'legend-note';
  note.textContent = overlay.note;
  box.append(title, bar, ticks, note);
  return box;
}
