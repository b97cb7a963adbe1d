// The map viewer: a world's Terrain-RGB tiles as 3D terrain, colour relief and hillshade, with
// its river network on top, its camera in the URL's hash. Tests drive it through
// window.strahlerMap (the maplibregl.Map).
import * as maplibregl from 'maplibre-gl';
import { loadWorlds, rememberWorld } from './api.js';
import { RIVER_TYPES, ROSGEN_COLOURS, TERRAIN_SOURCE, worldStyle } from './map-style.js';
import { FeaturesOverlay } from './features-overlay.js';
import { frameBounds } from './framing.js';
import { describePoint } from './point-info.js';
import { archiveWorlds, pmtilesArchiveUrl } from './pmtiles-source.js';
import { TileTimings, registerTimedProtocol, showTimings, timedUrl } from './tile-timing.js';
import { greyUrl, registerGreyProtocol } from './layer-ramps.js';
import { LayerSwitcher } from './layer-switcher.js';

const $ = (id) => document.getElementById(id);
// The whole island in view beside the panel (250 px wide, 10 px from the left edge).
const PADDING = { top: 40, bottom: 40, right: 40, left: 300 };

function describeWorld(world) {
  const area = Number(world.areaKm2);
  return `${world.name ?? world.id}${Number.isFinite(area) ? ` · ${area.toFixed(0)} km²` : ''}`;
}

function describeWorldDetails(world) {
  return world.mouths !== undefined ? `${world.mouths} river mouths` : '';
}

function showLegend(element, codes) {
  element.replaceChildren(...Object.entries(ROSGEN_COLOURS).map(([type, colour]) => {
    const item = document.createElement('span');
    item.className = 'legend-item';
    item.style.setProperty('--swatch', colour);
    item.textContent = RIVER_TYPES[type] ?? type;
    return item;
  }));
  codes.textContent = `Rosgen types: ${Object.keys(ROSGEN_COLOURS)
    .map((type) => `${type} ${RIVER_TYPES[type] ?? ''}`.trim()).join(', ')}`;
}

function setupWorldPicker(worlds, selected, onChange) {
  const select = $('world');
  for (const w of worlds) select.add(new Option(w.name ?? w.id, w.id, false, w === selected));
  $('world-picker').hidden = worlds.length < 2;
  select.addEventListener('change', () => onChange(worlds.find((w) => w.id === select.value)));
}

function setupExaggeration(map) {
  const input = $('exaggeration');
  const update = () => {
    const exaggeration = Number(input.value);
    $('exaggeration-value').textContent = `${exaggeration.toFixed(1)}×`;
    map.setTerrain({ source: TERRAIN_SOURCE, exaggeration });
  };
  input.addEventListener('input', update);
  return () => Number(input.value);
}

async function main() {
  const archive = pmtilesArchiveUrl(); // ?pmtiles=URL: a static archive instead of the server
  const { worlds, selected } = archive ? await archiveWorlds(maplibregl, archive) : await loadWorlds();
  const timings = new TileTimings();
  registerTimedProtocol(maplibregl, timings);
  window.strahlerLayerStats = registerGreyProtocol(maplibregl);
  showTimings($('timings'), timings);
  showLegend($('legend'), $('legend-codes'));

  const exaggeration = Number($('exaggeration').value);
  // The camera lives in the URL (#zoom/lat/lon/bearing/pitch, with ?world=ID), so a view can be
  // shared or bookmarked; a hash given on load wins over the world's bounds. (A hash that is
  // not a camera leaves MapLibre's own fit of the bounds, which ignores the pitch.)
  const cameraInUrl = location.hash.length > 1;
  const map = new maplibregl.Map({
    container: 'map',
    style: worldStyle(selected, exaggeration),
    bounds: selected.bounds,
    fitBoundsOptions: { padding: PADDING },
    pitch: 50,
    maxPitch: 80,
    hash: true,
    // Keeps the last frame readable (screenshots, tests); no fade so "idle" means drawn.
    canvasContextAttributes: { preserveDrawingBuffer: true },
    fadeDuration: 0,
    attributionControl: { compact: true },
    // Heightmap tiles go through the "timed" protocol, which records their Server-Timing;
    // layer tiles through the "grey" one, which colours them (layer-ramps.js).
    transformRequest: (url, resourceType) => {
      if (resourceType !== 'Tile') return undefined;
      if (/\/tiles\/\d+\/\d+\/\d+\.png/.test(url)) return { url: timedUrl(url) };
      if (/\/layers\/[a-z]+\/\d+\/\d+\/\d+\.png/.test(url)) return { url: greyUrl(url) };
      return undefined;
    },
  });
  if (!cameraInUrl) frameBounds(map, selected.bounds, PADDING);
  map.addControl(new maplibregl.NavigationControl({ visualizePitch: true }));
  map.addControl(new maplibregl.ScaleControl());
  window.strahlerMap = map;
  window.strahlerTimings = timings;
  const features = new FeaturesOverlay(map, $('show-features'), $('features-note'));
  window.strahlerFeatures = features;
  const switcher = new LayerSwitcher(map, $('layers'));
  switcher.show(selected);

  const currentExaggeration = setupExaggeration(map);
  const showWorld = (world) => {
    $('world-info').textContent = describeWorld(world);
    $('world-details').textContent = describeWorldDetails(world);
    if (!archive) rememberWorld(world);
  };
  showWorld(selected);
  features.show(selected);
  setupWorldPicker(worlds, selected, (world) => {
    map.setStyle(worldStyle(world, currentExaggeration(), features.visible, switcher.state));
    frameBounds(map, world.bounds, PADDING);
    showWorld(world);
    features.show(world);
    switcher.show(world);
  });

  map.on('click', (e) => {
    const info = describePoint(map, e.point, e.lngLat, { codes: $('details').open });
    new maplibregl.Popup({ maxWidth: '280px' }).setLngLat(e.lngLat).setDOMContent(info).addTo(map);
  });
}

main().catch((error) => {
  $('world-info').textContent = `Cannot show the map: ${error.message}`;
  console.error(error);
});
