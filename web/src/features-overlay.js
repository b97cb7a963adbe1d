// The artist's vector map of a world (GET /worlds/{id}/features.geojson) drawn over the terrain:
// mountains as triangles labelled with their elevation, ridges as dashed lines, drawn rivers as
// blue lines named at their middle. A checkbox shows or hides it; it is disabled when the world
// has no features (or comes from a static archive, which has none).
import * as maplibregl from 'maplibre-gl';
import { worldUrl } from './api.js';

export const FEATURES_SOURCE = 'drawn-features';
export const FEATURE_LAYERS = ['drawn-ridges', 'drawn-rivers'];

/** The source and layers of a world's features for its style (hidden unless `visible`). */
export function featureStyle(world, visible) {
  const visibility = visible ? 'visible' : 'none';
  return {
    source: { type: 'geojson', data: worldUrl(world, 'features.geojson') },
    layers: [
      {
        id: 'drawn-ridges', type: 'line', source: FEATURES_SOURCE,
        filter: ['==', ['get', 'kind'], 'ridge'],
        layout: { visibility, 'line-join': 'round' },
        paint: { 'line-color': '#5b3a1a', 'line-width': 2.5, 'line-dasharray': [2, 1.5] },
      },
      {
        id: 'drawn-rivers', type: 'line', source: FEATURES_SOURCE,
        filter: ['==', ['get', 'kind'], 'river'],
        layout: { visibility, 'line-join': 'round', 'line-cap': 'round' },
        paint: { 'line-color': '#0d47ff', 'line-width': 3, 'line-opacity': 0.85 },
      },
    ],
  };
}

function label(className, text) {
  const element = document.createElement('div');
  element.className = className;
  element.textContent = text;
  return element;
}

/** The HTML markers of mountains and river names (the style has no glyphs for text). */
function featureMarkers(collection) {
  const markers = [];
  for (const feature of collection.features) {
    const { kind, elevation, name } = feature.properties ?? {};
    const coordinates = feature.geometry?.coordinates;
    if (kind === 'mountain') {
      const text = `▲${Number.isFinite(elevation) ? ` ${Math.round(elevation)} m` : ''}`;
      markers.push(new maplibregl.Marker({ element: label('drawn-mountain', text), anchor: 'bottom' })
        .setLngLat(coordinates));
    } else if (kind === 'river' && name) {
      markers.push(new maplibregl.Marker({ element: label('drawn-river-name', name) })
        .setLngLat(coordinates[Math.floor(coordinates.length / 2)]));
    }
  }
  return markers;
}

export class FeaturesOverlay {
  constructor(map, checkbox, note) {
    this.map = map;
    this.checkbox = checkbox;
    this.note = note;
    this.markers = [];
    this.request = 0;
    checkbox.addEventListener('change', () => this.apply());
  }

  /** True when the features are to be drawn (for worldStyle on a change of world). */
  get visible() {
    return this.checkbox.checked && !this.checkbox.disabled;
  }

  /** Loads the features of `world` (after its style is set) and enables the checkbox if any. */
  async show(world) {
    const request = ++this.request;
    this.setMarkers([]);
    this.checkbox.disabled = true;
    this.setShown(false);
    this.note.textContent = '';
    if (world.demSource) return; // a static archive: no features document
    let collection = null;
    try {
      const response = await fetch(worldUrl(world, 'features.geojson'));
      if (response.ok) collection = await response.json();
    } catch (error) {
      console.warn('features.geojson:', error);
    }
    if (request !== this.request) return; // another world was chosen meanwhile
    const count = collection?.features?.length ?? 0;
    this.note.textContent = count ? `(${count})` : '(none)';
    if (!count) {
      this.checkbox.checked = false;
      return;
    }
    this.checkbox.disabled = false;
    this.setShown(true);
    this.setMarkers(featureMarkers(collection));
    this.apply();
  }

  /** The checkbox appears only for a world that has drawn features: no control for nothing. */
  setShown(shown) {
    const label = this.checkbox.closest('label');
    if (label) label.hidden = !shown;
  }

  setMarkers(markers) {
    for (const marker of this.markers) marker.remove();
    this.markers = markers;
  }

  apply() {
    const visible = this.visible;
    for (const id of FEATURE_LAYERS) {
      if (this.map.getLayer(id)) this.map.setLayoutProperty(id, 'visibility', visible ? 'visible' : 'none');
    }
    for (const marker of this.markers) {
      if (visible) marker.addTo(this.map);
      else marker.remove();
    }
  }
}
