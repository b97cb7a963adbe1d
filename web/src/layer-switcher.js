// The viewer's layer switcher: derived layers (layer-ramps.js) as raster overlays, any number
// at once, each with its opacity and legend, and contour lines from the world's vector tiles.
// Worlds from a static archive (pmtiles-source.js) have neither: the switcher hides itself.
import { worldUrl } from './api.js';
import { OVERLAYS, legendOf } from './layer-ramps.js';

/** The id of the world's vector-tile source in the style (contours; rivers of large worlds). */
export const VECTOR_SOURCE = 'vector';
/** The style's contour layers: plain, then index contours. */
export const CONTOUR_LAYERS = ['contours', 'contours-index'];
const overlayLayer = (overlay) => `overlay-${overlay.id}`;

/** What is shown: overlay id → opacity for each overlay switched on, and the contours. */
export function defaultOverlayState() {
  return { on: {}, contours: false };
}

/** The raster sources and layers of the overlays for `world`'s style, per `state`. */
export function overlayStyle(world, state) {
  const sources = {};
  const layers = [];
  for (const overlay of OVERLAYS) {
    sources[overlayLayer(overlay)] = {
      type: 'raster', tileSize: 256,
      url: worldUrl(world, `layers/${overlay.layer}/tilejson.json${overlay.query}`),
    };
    const opacity = state.on[overlay.id];
    layers.push({
      id: overlayLayer(overlay), type: 'raster', source: overlayLayer(overlay),
      layout: { visibility: opacity === undefined ? 'none' : 'visible' },
      // Nearest: each pixel keeps a colour of the legend (no blends of two codes).
      paint: { 'raster-opacity': opacity ?? overlay.opacity, 'raster-resampling': 'nearest' },
    });
  }
  return { sources, layers };
}

/** The contour layers (vector tiles' `contours`: index contours thicker), per `state`. */
export function contourStyle(state) {
  const visibility = state.contours ? 'visible' : 'none';
  const common = { type: 'line', source: VECTOR_SOURCE, 'source-layer': 'contours', layout: { visibility, 'line-join': 'round' } };
  return [
    {
      ...common, id: CONTOUR_LAYERS[0], filter: ['!=', ['get', 'index'], true],
      paint: { 'line-color': 'rgba(90, 60, 30, 0.55)', 'line-width': 0.6 },
    },
    {
      ...common, id: CONTOUR_LAYERS[1], filter: ['==', ['get', 'index'], true],
      paint: { 'line-color': 'rgba(80, 50, 20, 0.8)', 'line-width': 1.4 },
    },
  ];
}

/** The panel's layer switcher: checkboxes, opacity sliders and legends in `element`. */
export class LayerSwitcher {
  constructor(map, element) {
    this.map = map;
    this.element = element;
    this.state = defaultOverlayState();
    this.#build();
  }

  /** Shows the switcher for a world with layer and vector tiles, hides it for an archive's. */
  show(world) {
    this.element.hidden = Boolean(world.demSource);
  }

  #build() {
    const list = document.createElement('div');
    list.className = 'overlays';
    const legends = document.createElement('div');
    legends.className = 'layer-legends';
    for (const overlay of OVERLAYS) {
      const row = document.createElement('label');
      row.className = 'overlay';
      const box = Object.assign(document.createElement('input'), { type: 'checkbox', id: `overlay-${overlay.id}` });
      const slider = Object.assign(document.createElement('input'), {
        type: 'range', min: '0', max: '1', step: '0.05', value: String(overlay.opacity), title: 'opacity', disabled: true,
      });
      const legend = legendOf(overlay);
      legend.hidden = true;
      legends.append(legend);
      const update = () => {
        slider.disabled = !box.checked;
        legend.hidden = !box.checked;
        if (box.checked) this.state.on[overlay.id] = Number(slider.value);
        else delete this.state.on[overlay.id];
        this.map.setLayoutProperty(overlayLayer(overlay), 'visibility', box.checked ? 'visible' : 'none');
        this.map.setPaintProperty(overlayLayer(overlay), 'raster-opacity', Number(slider.value));
      };
      box.addEventListener('change', update);
      slider.addEventListener('input', update);
      row.append(box, ` ${overlay.label} `, slider);
      list.append(row);
    }
    const contours = document.createElement('label');
    const box = Object.assign(document.createElement('input'), { type: 'checkbox', id: 'show-contours' });
    box.addEventListener('change', () => {
      this.state.contours = box.checked;
      for (const id of CONTOUR_LAYERS) this.map.setLayoutProperty(id, 'visibility', box.checked ? 'visible' : 'none');
    });
    contours.append(box, ' Contours (thick: every fifth)');
    list.append(contours);
    this.element.append(list, legends);
  }
}
