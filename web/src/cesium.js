// The Cesium page (/cesium): a world's quantized-mesh terrain (GET /worlds/{id}/cesium/layer.json
// and its .terrain tiles, with vertex normals, water mask and availability metadata) in CesiumJS,
// draped with strahler's own colour-relief tiles, lit by the sun. No Cesium ion, no outside host.
// ?world=ID picks the world; ?ellipsoid=1 shows the bare ellipsoid instead (the tests' baseline);
// ?exaggeration=N scales the heights. Tests drive it through window.strahlerCesium.
import {
  BoundingSphere, Cartesian3, Cartographic, CesiumTerrainProvider, Color, EllipsoidTerrainProvider, HeadingPitchRange, ImageryLayer,
  JulianDate, Math as CesiumMath, Rectangle, UrlTemplateImageryProvider, Viewer,
} from 'cesium';
import { loadWorlds, rememberWorld, withVersion, worldUrl } from './api.js';
import { TileTimings, observeResourceTimings, showTimings } from './tile-timing.js';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);

/** The colour-relief raster tiles (Web Mercator XYZ PNG) of a world, as a URL template. */
export const RELIEF_TILES = 'tiles/{z}/{x}/{y}.relief';
/** The Cesium terrain of a world: layer.json and {z}/{x}/{y}.terrain below it. */
export const CESIUM_TERRAIN = 'cesium/';

/** Draped imagery: the world's relief tiles when the server has them (a probe tile), else none. */
async function reliefLayer(world) {
  // worldUrl() would escape the braces; the version makes the URLs those of this world's content.
  const template = withVersion(worldUrl(world, '') + RELIEF_TILES, world);
  const probe = await fetch(template.replace('{z}', '0').replace('{x}', '0').replace('{y}', '0'));
  if (!probe.ok) return null;
  const provider = new UrlTemplateImageryProvider({
    url: template, maximumLevel: world.web?.maxzoom ?? 18, credit: 'strahler colour relief',
  });
  return new ImageryLayer(provider);
}

async function terrainProvider(world) {
  if (params.get('ellipsoid')) return new EllipsoidTerrainProvider();
  return CesiumTerrainProvider.fromUrl(worldUrl(world, CESIUM_TERRAIN), {
    requestVertexNormals: true, requestWaterMask: true, requestMetadata: true,
  });
}

/** A view of the whole world from the south, pitched down 40°. */
function flyToWorld(viewer, world) {
  const rectangle = Rectangle.fromDegrees(...world.bounds);
  const sphere = BoundingSphere.fromRectangle3D(rectangle);
  viewer.camera.flyToBoundingSphere(sphere, {
    offset: new HeadingPitchRange(0, CesiumMath.toRadians(-40), 2.2 * sphere.radius), duration: 0,
  });
}

/** Puts the camera `height` m above the loaded terrain at (lon, lat), looking north 30° down. */
function lookAt(viewer, lon, lat, height) {
  const ground = viewer.scene.globe.getHeight(Cartographic.fromDegrees(lon, lat)) ?? 0;
  viewer.camera.setView({
    destination: Cartesian3.fromDegrees(lon, lat, Math.max(0, ground) + height),
    orientation: { heading: 0, pitch: CesiumMath.toRadians(-30), roll: 0 },
  });
}

/** A fixed mid-morning sun over the world (lighting is on; the real clock may put it at night). */
function morningSun(viewer, world) {
  const [lon] = world.center ?? [0];
  const hours = 9.5 - lon / 15; // 09:30 local solar time, in UTC
  const time = JulianDate.addHours(JulianDate.fromIso8601('2026-06-21T00:00:00Z'), hours, new JulianDate());
  viewer.clock.currentTime = time;
  viewer.clock.shouldAnimate = false;
}

/** Writes `url` into `element` with line breaks allowed only after its slashes, never mid-word. */
function showUrl(element, url) {
  element.replaceChildren(...url.split(/(?<=\/)/).flatMap((part) => [part, document.createElement('wbr')]));
}

async function main() {
  const { selected: world } = await loadWorlds();
  rememberWorld(world);
  const area = Number(world.areaKm2);
  $('world-info').textContent = `${world.name ?? world.id}${Number.isFinite(area) ? ` · ${area.toFixed(0)} km²` : ''}`;
  showUrl($('layer-url'), `${worldUrl(world, CESIUM_TERRAIN)}layer.json`);
  $('viewer-link').href = `./?world=${encodeURIComponent(world.id)}`;

  const timings = new TileTimings();
  observeResourceTimings(/\.terrain(\?|$)/, timings);
  showTimings($('timings'), timings);

  const [terrain, relief] = await Promise.all([terrainProvider(world), reliefLayer(world)]);
  const viewer = new Viewer('globe', {
    terrainProvider: terrain,
    baseLayer: relief ?? false,
    baseLayerPicker: false, geocoder: false, homeButton: false, sceneModePicker: false,
    navigationHelpButton: false, animation: false, timeline: false, fullscreenButton: false,
    infoBox: false, selectionIndicator: false,
    // Keeps the last frame readable (screenshots, tests).
    contextOptions: { webgl: { preserveDrawingBuffer: true } },
  });
  const { globe } = viewer.scene;
  globe.enableLighting = true;
  globe.showWaterEffect = true;
  globe.baseColor = Color.fromCssColorString('#2b5d8a'); // the sea, where no imagery is draped
  viewer.scene.verticalExaggeration = Number(params.get('exaggeration') ?? 1);
  morningSun(viewer, world);
  flyToWorld(viewer, world);

  window.strahlerCesium = {
    viewer, world, timings, relief: relief !== null, lookAt: (lon, lat, height) => lookAt(viewer, lon, lat, height),
  };
}

main().catch((error) => {
  $('world-info').textContent = `Cannot show the globe: ${error.message}`;
  console.error(error);
});
