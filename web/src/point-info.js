// What the viewer says about a clicked point: its elevation and the nearest river.
import { RIVER_LAYER, RIVER_TYPES } from './map-style.js';

const SEARCH_RADIUS_PX = 12;

function distanceToSegment(p, a, b) {
  const dx = b.x - a.x, dy = b.y - a.y;
  const lengthSq = dx * dx + dy * dy;
  const t = lengthSq === 0 ? 0 : Math.max(0, Math.min(1, ((p.x - a.x) * dx + (p.y - a.y) * dy) / lengthSq));
  return Math.hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/** The rendered river feature closest to the screen point, within SEARCH_RADIUS_PX, or null. */
export function nearestRiver(map, point) {
  const r = SEARCH_RADIUS_PX;
  const features = map.queryRenderedFeatures([[point.x - r, point.y - r], [point.x + r, point.y + r]], { layers: [RIVER_LAYER] });
  let best = null, bestDistance = Infinity;
  for (const feature of features) {
    const lines = feature.geometry.type === 'LineString' ? [feature.geometry.coordinates] : feature.geometry.coordinates;
    for (const line of lines) {
      // Distances are measured on screen, where the user clicked (map.project follows the terrain).
      const projected = line.map((c) => map.project(c));
      for (let i = 1; i < projected.length; i++) {
        const d = distanceToSegment(point, projected[i - 1], projected[i]);
        if (d < bestDistance) [best, bestDistance] = [feature, d];
      }
    }
  }
  return best;
}

/**
 * Elevation in metres at lngLat, from the loaded terrain tiles, or null without terrain.
 * MapLibre returns it multiplied by the exaggeration, so divide that out.
 */
export function elevationAt(map, lngLat) {
  const elevation = map.queryTerrainElevation(lngLat);
  const exaggeration = map.getTerrain()?.exaggeration ?? 1;
  return elevation === null || exaggeration === 0 ? null : elevation / exaggeration;
}

/**
 * A DOM node for the popup: elevation, then the nearest river's type in plain words, order, flow
 * and width. `codes` (the panel's details are open) adds the river's Rosgen type.
 */
export function describePoint(map, point, lngLat, { codes = false } = {}) {
  const lines = [];
  const elevation = elevationAt(map, lngLat);
  lines.push(elevation === null ? 'Elevation: unknown (no terrain)' : `Elevation ≈ ${elevation.toFixed(0)} m`);
  const river = nearestRiver(map, point);
  if (river) {
    // rivers.geojson: `strahler`, widths at both ends; vector tiles: `order`, `width` downstream.
    const { strahler, order, flow, rosgen, widthUpM, widthDownM, width } = river.properties;
    lines.push(`Nearest river: ${RIVER_TYPES[rosgen] ?? 'river'}, Strahler order ${strahler ?? order}`);
    lines.push(`Flow ${Number(flow).toFixed(flow < 10 ? 2 : 0)} m³/s`);
    if (widthUpM !== undefined && widthDownM !== undefined) {
      const [up, down] = [widthUpM, widthDownM].map((w) => Number(w).toFixed(0));
      lines.push(`Channel ${up === down ? up : `${up}–${down}`} m wide`);
    } else if (width !== undefined) {
      lines.push(`Channel ${Number(width).toFixed(0)} m wide`);
    }
    if (codes) lines.push(`Rosgen type ${rosgen}`);
  } else {
    lines.push(`No river within ${SEARCH_RADIUS_PX} px`);
  }
  const node = document.createElement('div');
  node.className = 'point-info';
  for (const text of lines) node.appendChild(document.createElement('div')).textContent = text;
  return node;
}
