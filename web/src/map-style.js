// The MapLibre style of one world, built from the server's own resources only (no base map,
// no glyphs, no sprites), so the viewer works offline.
import { tileUrl, worldUrl } from './api.js';
import { FEATURES_SOURCE, featureStyle } from './features-overlay.js';
import { VECTOR_SOURCE, contourStyle, defaultOverlayState, overlayStyle } from './layer-switcher.js';

export const RIVER_LAYER = 'rivers';
export const TERRAIN_SOURCE = 'terrain-dem';

/** Rosgen stream types (Génevaux et al. use B, E, D and deltas) and their colours. */
export const ROSGEN_COLOURS = {
  B: '#0b4f9c',       // steep, step-pool mountain streams
  E: '#1fa3c4',       // low-gradient meandering channels
  D: '#6a3fb5',       // braided channels
  'D-delta': '#c2338a', // distributaries at the mouth
};

/** The Rosgen types in plain words, for legends and popups; the letters stay in the details. */
export const RIVER_TYPES = {
  B: 'mountain stream', E: 'meandering river', D: 'braided river', 'D-delta': 'delta channel',
};

// Hypsometric tint: sea floor in blues, then beach, lowland greens, browns, rock and snow.
const RELIEF = [
  -400, '#0b3a5e', -40, '#1f6592', -0.5, '#5a9bc2', 0, '#d9cf9e', 20, '#a8c98a', 200, '#6fa35a',
  600, '#8e8b4f', 1000, '#9c7652', 1500, '#b3aaa0', 2200, '#ffffff',
];

// The open sea floor's depth: the shelf tends to it away from the shore
// (CoastShape::kShelfDepth in core/construction/include/strahler/construction/world.h).
const OPEN_SEA_M = -120;

/** The colour RELIEF gives `elevation` (linear between its stops, as MapLibre interpolates). */
export function reliefColour(elevation) {
  const rgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
  for (let i = 2; i < RELIEF.length; i += 2) {
    if (elevation <= RELIEF[i] || i === RELIEF.length - 2) {
      const t = Math.min(1, Math.max(0, (elevation - RELIEF[i - 2]) / (RELIEF[i] - RELIEF[i - 2])));
      const [a, b] = [rgb(RELIEF[i - 1]), rgb(RELIEF[i + 1])];
      return `#${a.map((v, k) => Math.round(v + t * (b[k] - v)).toString(16).padStart(2, '0')).join('')}`;
    }
  }
  return RELIEF[1];
}

// The GeoJSON's rivers carry their order as `strahler`, the vector tiles' as `order`.
function riverWidth(scale) {
  return ['interpolate', ['linear'], ['coalesce', ['get', 'strahler'], ['get', 'order'], 1], 1, 0.4 * scale, 6, 4 * scale];
}

// Up to this land area the viewer reads the whole network as rivers.geojson (one request, every
// river at every zoom); above it, the rivers of the vector tiles in view (Iceland's GeoJSON is
// 54 MB). ?rivers=vector or ?rivers=geojson overrides the choice.
const RIVERS_GEOJSON_MAX_KM2 = 5000;

/** Whether the viewer takes `world`'s rivers from its vector tiles rather than rivers.geojson. */
export function riversFromVectorTiles(world, search = location.search) {
  if (world.demSource) return false; // a static archive: no vector tiles
  const wanted = new URLSearchParams(search).get('rivers');
  if (wanted === 'vector' || wanted === 'geojson') return wanted === 'vector';
  return Number(world.areaKm2) > RIVERS_GEOJSON_MAX_KM2;
}

/**
 * The style of `world`; `showFeatures`: draw its artist's vector map (features-overlay.js),
 * `overlays`: the layer switcher's state (layer-switcher.js). Worlds of a static archive have
 * neither, nor vector tiles.
 */
export function worldStyle(world, exaggeration, showFeatures = false, overlays = defaultOverlayState()) {
  // A world read from a static archive (pmtiles-source.js) brings its own source, no rivers.
  const dem = world.demSource ?? { type: 'raster-dem', url: worldUrl(world, 'tilejson.json'), tileSize: 256 };
  const served = !world.demSource;
  const features = served ? featureStyle(world, showFeatures) : null;
  const derived = served ? overlayStyle(world, overlays) : { sources: {}, layers: [] };
  const vectorRivers = riversFromVectorTiles(world);
  const riverSource = vectorRivers ? { source: VECTOR_SOURCE, 'source-layer': 'rivers' } : { source: 'rivers' };
  return {
    version: 8,
    // Two sources of the same tiles: MapLibre renders 3D terrain and hillshade better when they
    // do not share one (and warns otherwise). The second fetch is served by the HTTP cache.
    sources: {
      [TERRAIN_SOURCE]: { ...dem },
      shade: { ...dem },
      ...(vectorRivers ? {} : { rivers: { type: 'geojson', data: world.riversData ?? tileUrl(world, 'rivers.geojson') } }),
      ...(served ? { [VECTOR_SOURCE]: { type: 'vector', url: worldUrl(world, 'vector/tilejson.json') } } : {}),
      ...derived.sources,
      ...(features ? { [FEATURES_SOURCE]: features.source } : {}),
    },
    terrain: { source: TERRAIN_SOURCE, exaggeration },
    layers: [
      // The open sea beyond the tiles' bounds, in the colour the tiles give the open sea floor,
      // so the bounds leave no seam.
      { id: 'background', type: 'background', paint: { 'background-color': reliefColour(OPEN_SEA_M) } },
      {
        id: 'relief', type: 'color-relief', source: 'shade',
        paint: { 'color-relief-color': ['interpolate', ['linear'], ['elevation'], ...RELIEF] },
      },
      {
        id: 'hillshade', type: 'hillshade', source: 'shade',
        paint: {
          'hillshade-exaggeration': 0.6,
          'hillshade-shadow-color': 'rgba(20, 24, 40, 0.7)',
          'hillshade-highlight-color': 'rgba(255, 255, 240, 0.35)',
          'hillshade-accent-color': 'rgba(60, 50, 35, 0.4)',
        },
      },
      ...derived.layers,
      ...(served ? contourStyle(overlays) : []),
      {
        id: RIVER_LAYER, type: 'line', ...riverSource,
        filter: ['==', ['geometry-type'], 'LineString'],
        layout: { 'line-join': 'round', 'line-cap': 'round' },
        paint: {
          // Width grows with Strahler order and with zoom (zoom must be the outer interpolation).
          'line-width': ['interpolate', ['exponential', 1.6], ['zoom'], 8, riverWidth(1), 14, riverWidth(4)],
          'line-color': ['match', ['get', 'rosgen'], ...Object.entries(ROSGEN_COLOURS).flat(), '#1565c0'],
        },
      },
      // The vector tiles mark no mouths.
      ...(vectorRivers ? [] : [{
        id: 'mouths', type: 'circle', source: 'rivers',
        filter: ['==', ['get', 'mouth'], true],
        paint: { 'circle-radius': 3, 'circle-color': '#ffffff', 'circle-stroke-color': '#0b4f9c', 'circle-stroke-width': 1.5 },
      }]),
      ...(features ? features.layers : []),
    ],
  };
}
