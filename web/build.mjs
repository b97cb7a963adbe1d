// Builds web/dist without a bundler: our pages and ES modules are copied as they are, and
// the vendor modules they import are copied next to them. The import maps in index.html,
// game.html and cesium.html resolve the bare names ("maplibre-gl", "pmtiles", "three",
// "three/addons/", "cesium") to these copies,
// so the pages work offline from any static file server, including `strahler serve`.
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, copyFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const dist = join(here, 'dist');
const modules = join(here, 'node_modules');

function copy(from, to) {
  if (!existsSync(from)) throw new Error(`build: missing ${from} (run \`npm ci\` in web/ first)`);
  mkdirSync(dirname(to), { recursive: true });
  copyFileSync(from, to);
}

// Copies an ES module and, recursively, every module it imports by a relative path
// ('./three.core.js', '../utils/BufferGeometryUtils.js'). Bare imports ('three') are left to
// the import map. Listing only the entry points keeps this in step with three's releases.
function copyModule(from, to, seen = new Set()) {
  if (seen.has(from)) return;
  seen.add(from);
  copy(from, to);
  const text = readFileSync(from, 'utf8');
  const relative = /(?:\bfrom\s*|\bimport\s*\(?\s*)['"`](\.{1,2}\/[^'"`]+)['"`]/g;
  for (const [, spec] of text.matchAll(relative)) {
    copyModule(resolve(dirname(from), spec), resolve(dirname(to), spec), seen);
  }
}

rmSync(dist, { recursive: true, force: true });
mkdirSync(dist, { recursive: true });

for (const page of ['index.html', 'game.html', 'cesium.html']) copy(join(here, page), join(dist, page));
cpSync(join(here, 'src'), join(dist, 'src'), { recursive: true });

// MapLibre GL JS 6 ships ES modules; the main module starts its worker from the sibling
// file maplibre-gl-worker.mjs (found through import.meta.url), so both must sit together.
const maplibre = join(modules, 'maplibre-gl', 'dist');
for (const file of ['maplibre-gl.mjs', 'maplibre-gl-worker.mjs', 'maplibre-gl.css']) {
  copy(join(maplibre, file), join(dist, 'vendor', 'maplibre-gl', file));
}

// pmtiles (?pmtiles=URL in the viewer: src/pmtiles-source.js) and fflate, the one module it
// imports (bare 'fflate', resolved by the import map); both are single-file ES modules.
copy(join(modules, 'pmtiles', 'dist', 'esm', 'index.js'), join(dist, 'vendor', 'pmtiles', 'index.js'));
copy(join(modules, 'fflate', 'esm', 'browser.js'), join(dist, 'vendor', 'fflate', 'browser.js'));

// three.js core, the glTF + Draco loaders (and what they import), and the Draco decoder
// (the glTF variant: it decodes only what KHR_draco_mesh_compression needs, so it is smaller).
const three = join(modules, 'three');
const threeOut = join(dist, 'vendor', 'three');
copyModule(join(three, 'build', 'three.module.js'), join(threeOut, 'three.module.js'));
for (const loader of ['GLTFLoader.js', 'DRACOLoader.js']) {
  copyModule(join(three, 'examples', 'jsm', 'loaders', loader), join(threeOut, 'addons', 'loaders', loader));
}
for (const file of ['draco_decoder.js', 'draco_decoder.wasm', 'draco_wasm_wrapper.js']) {
  copy(join(three, 'examples', 'jsm', 'libs', 'draco', 'gltf', file), join(threeOut, 'draco', file));
}

// CesiumJS: its prebuilt ES module and the files it loads at run time from CESIUM_BASE_URL
// (cesium.html sets it to vendor/cesium/): web workers, the draco/basis decoders, textures
// (sky box, water normals, moon), the widgets' CSS and icons. Natural Earth II, the offline
// imagery we never show (the page drapes strahler's own relief tiles), is left out (~1 MB).
const cesium = join(modules, 'cesium', 'Build', 'Cesium');
const cesiumOut = join(dist, 'vendor', 'cesium');
copy(join(cesium, 'index.js'), join(cesiumOut, 'index.js'));
for (const folder of ['Workers', 'ThirdParty', 'Assets', 'Widgets']) {
  cpSync(join(cesium, folder), join(cesiumOut, folder), {
    recursive: true, filter: (from) => !from.includes(`${join('Assets', 'Textures', 'NaturalEarthII')}`),
  });
}

console.log(`build: wrote ${dist}`);
