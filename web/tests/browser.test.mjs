// The map viewer and the game client in a real browser (Debian's chromium, SwiftShader WebGL2)
// against a real `strahler serve`. Screenshots go to web/tests/screenshots/.
import assert from 'node:assert/strict';
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import { launchBrowser, openPage } from './lib/browser.mjs';
import { changedShare, pixelAt, pixelStats } from './lib/pixels.mjs';
import { exportDefaultWorld } from './lib/archive.mjs';
import { startServer } from './lib/server.mjs';
import { startStaticServer } from './lib/static-server.mjs';

const SCREENSHOTS = join(dirname(fileURLToPath(import.meta.url)), 'screenshots');
const TOTAL_MS = 420_000; // the whole file, server start to browser close: ~4.6 min at load 5 on 2 cores
const STEP_MS = 60_000;   // any one wait in a page

// A blank or single-colour canvas has a luminance spread near 0 and a handful of colours.
function assertNotBlank(png, what) {
  const stats = pixelStats(png);
  assert.ok(stats.stdDev > 8 && stats.colours > 64, `${what} looks blank: ${JSON.stringify(stats)}`);
}

// No console error, no HTTP error, and nothing fetched from anywhere but our server (offline).
function assertNoErrors(record, origin = server.url) {
  assert.deepEqual(record.errors, [], 'console errors, exceptions or failed requests');
  const bad = record.responses.filter((r) => r.status >= 400);
  assert.deepEqual(bad, [], 'HTTP error responses');
  const foreign = record.responses.filter((r) => /^https?:/.test(r.url) && !r.url.startsWith(`${origin}/`));
  assert.deepEqual(foreign, [], 'requests to other servers');
}

let server, browser;

// Every tile URL a page fetches carries the world's content version (`v`, from GET /worlds), so
// that caches may keep it for good and a regenerated world's tiles have other URLs.
async function assertVersioned(responses, what) {
  const worlds = await (await fetch(`${server.url}/worlds`)).json();
  const versions = new Set(worlds.map((w) => w.version));
  assert.ok(versions.size === worlds.length && !versions.has(undefined), 'GET /worlds names each version');
  for (const r of responses) {
    assert.ok(versions.has(new URL(r.url.replace(/^[a-z]+:\/\/(?=https?:)/, '')).searchParams.get('v')),
      `${what} without the world's version: ${r.url}`);
  }
}

// The popup's river line: the type in plain words (the legend's), then the Strahler order.
const RIVER_IN_WORDS = /Nearest river: (mountain stream|meandering river|braided river|delta channel), Strahler order \d/;

// Waits for window.strahlerMap, then until it is idle: style and every tile loaded, no transition.
async function waitForIdleMap(page) {
  await page.waitForFunction(() => window.strahlerMap, null, { timeout: STEP_MS });
  await page.evaluate((ms) => new Promise((resolve, reject) => {
    const map = window.strahlerMap;
    setTimeout(() => reject(new Error('the map never became idle')), ms);
    if (map.loaded() && map.areTilesLoaded() && !map.isMoving()) resolve();
    else map.once('idle', resolve);
  }), STEP_MS);
}

// Clicks a vertex of a rendered river right of `minX` px (clear of the panel on the left) and
// returns the text of the popup it opens.
async function clickRiver(page, minX) {
  const point = await page.evaluate((left) => {
    const map = window.strahlerMap;
    const { width, height } = map.getCanvas().getBoundingClientRect();
    for (const f of map.queryRenderedFeatures({ layers: ['rivers'] })) {
      for (const c of f.geometry.type === 'LineString' ? f.geometry.coordinates : f.geometry.coordinates.flat()) {
        const p = map.project(c);
        if (p.x > left && p.x < width - 60 && p.y > 60 && p.y < height - 60) return { x: p.x, y: p.y };
      }
    }
    return null;
  }, minX);
  assert.ok(point, 'no river vertex on screen');
  await page.mouse.click(point.x, point.y);
  return page.locator('.maplibregl-popup-content').innerText({ timeout: 10_000 });
}

const watchdog = setTimeout(() => {
  console.error(`browser tests exceeded ${TOTAL_MS} ms`);
  process.exit(1); // the server is killed by its exit hook, chromium when its pipe closes
}, TOTAL_MS);
watchdog.unref();

before(async () => {
  mkdirSync(SCREENSHOTS, { recursive: true });
  server = await startServer();
  browser = await launchBrowser();
}, { timeout: 90_000 });

after(async () => {
  await browser?.close();
  await server?.stop();
  clearTimeout(watchdog);
});

describe('map viewer', () => {
  let page, record;

  before(async () => {
    ({ page, record } = await openPage(browser, `${server.url}/`));
    await waitForIdleMap(page);
  }, { timeout: 2 * STEP_MS });

  after(() => page?.close());

  test('loads its tiles, TileJSON and rivers without errors', async () => {
    assertNoErrors(record);
    const of = (pattern) => record.responses.filter((r) => pattern.test(r.url));
    assert.ok(of(/\/worlds$/).length === 1, 'GET /worlds');
    assert.ok(of(/\/tilejson\.json$/).length >= 1, 'GET tilejson.json');
    assert.ok(of(/\/rivers\.geojson\?v=[0-9a-f]{16}$/).length === 1, 'GET rivers.geojson by the world version');
    assert.equal(of(/\/rivers\.geojson\?v=/)[0].encoding, 'gzip', 'rivers.geojson comes gzipped');
    const tiles = of(/\/tiles\/\d+\/\d+\/\d+\.png(\?|$)/);
    assert.ok(tiles.length >= 1, 'no heightmap tile was requested');
    for (const tile of tiles) assert.match(tile.type, /^image\/png/, tile.url);
    await assertVersioned(tiles, 'a heightmap tile');
  });

  test('frames the whole island beside the panel at its default view', async () => {
    // Opened without a hash, the page frames the world's land bounds (GET /worlds) under its
    // pitch. The box's corners are its extremes on screen (its edges are straight lines over
    // the sea): all four on the canvas, right of the panel, and the box fills the free width or
    // height at least half-way (framed, not lost in the distance).
    const [west, south, east, north] = (await (await fetch(`${server.url}/worlds`)).json())[0].bounds;
    const view = await page.evaluate((corners) => {
      const map = window.strahlerMap;
      const canvas = map.getCanvas().getBoundingClientRect();
      return {
        corners: corners.map((c) => map.project(c)).map(({ x, y }) => [Math.round(x), Math.round(y)]),
        free: { left: Math.max(canvas.left, document.getElementById('panel').getBoundingClientRect().right),
          right: canvas.right, top: canvas.top, bottom: canvas.bottom },
        hash: location.hash,
      };
    }, [[west, south], [east, south], [east, north], [west, north]]);
    const { corners, free } = view;
    for (const [x, y] of corners) {
      assert.ok(x >= free.left && x <= free.right && y >= free.top && y <= free.bottom,
        `the corner (${x}, ${y}) is not on the map beside the panel: ${JSON.stringify(view)}`);
    }
    const spread = (k) => Math.max(...corners.map((c) => c[k])) - Math.min(...corners.map((c) => c[k]));
    assert.ok(spread(0) > 0.5 * (free.right - free.left) || spread(1) > 0.5 * (free.bottom - free.top),
      `the island is small in the view: ${JSON.stringify(view)}`);
  });

  test('has 3D terrain, colour relief, hillshade and the river layer', async () => {
    const state = await page.evaluate(() => {
      const map = window.strahlerMap;
      return {
        terrain: map.getTerrain(),
        layers: Object.fromEntries(['relief', 'hillshade', 'rivers', 'mouths'].map((id) => [id, map.getLayer(id)?.type])),
        rivers: map.queryRenderedFeatures({ layers: ['rivers'] }).length,
      };
    });
    assert.equal(state.terrain?.source, 'terrain-dem');
    assert.deepEqual(state.layers, { relief: 'color-relief', hillshade: 'hillshade', rivers: 'line', mouths: 'circle' });
    assert.ok(state.rivers > 0, 'no river feature is rendered');
  });

  test('shows river types in plain words, and timings and counts only in its details', async () => {
    const s = await page.evaluate(() => window.strahlerTimings.summary());
    assert.ok(s.count >= 1 && Number.isFinite(s.eval) && Number.isFinite(s.encode), JSON.stringify(s));
    const legend = await page.locator('#legend').innerText();
    assert.match(legend, /mountain stream/);
    assert.doesNotMatch(legend, /Rosgen/);
    assert.doesNotMatch(await page.locator('#world-info').innerText(), /mouths/);
    // The default island has no drawn features: no checkbox for them.
    assert.equal(await page.locator('#show-features').isVisible(), false);
    // Collapsed, the details hide the timings; opened, they show them and the counts.
    assert.equal(await page.locator('#timings').isVisible(), false);
    await page.click('#details summary');
    assert.equal(await page.locator('#timings').isVisible(), true);
    assert.match(await page.locator('#timings').innerText(), /evaluate \d/);
    assert.match(await page.locator('#world-details').innerText(), /\d+ river mouths/);
    assert.match(await page.locator('#legend-codes').innerText(), /Rosgen types: B mountain stream/);
    await page.click('#details summary'); // collapsed again for the tests that follow
  });

  test('click on a river: popup with elevation, river type in plain words, order, flow and width', async () => {
    const text = await clickRiver(page, 320);
    assert.match(text, /Elevation ≈ -?\d+ m/);
    assert.match(text, RIVER_IN_WORDS);
    assert.match(text, /Flow [\d.]+ m³\/s/);
    assert.match(text, /Channel \d+(–\d+)? m wide/);
    assert.doesNotMatch(text, /Rosgen/, 'the Rosgen letters only with the details open');
  });

  test('draws a terrain that is not blank (screenshot)', async () => {
    assertNotBlank(await page.locator('#map canvas').screenshot(), 'the map canvas');
    writeFileSync(join(SCREENSHOTS, 'viewer.png'), await page.screenshot());
  });

  test('the open sea has no seam where the tiles end', async () => {
    // Just inside and just outside the south edge of the tiles' bounds, a quarter of the way
    // across (open sea; the island's southern tip is in the middle): the open sea floor in the
    // tiles, then the background, in one colour.
    const [west, south, east, north] = (await (await fetch(`${server.url}/worlds`)).json())[0].bounds;
    const [inside, outside] = await page.evaluate(([lon, lats]) => {
      document.querySelectorAll('.maplibregl-popup').forEach((popup) => popup.remove()); // the click test's
      return lats.map((lat) => {
        const p = window.strahlerMap.project([lon, lat]);
        return [p.x, p.y];
      });
    }, [west + 0.25 * (east - west), [south + 0.02 * (north - south), south - 0.02 * (north - south)]]);
    const canvas = await page.locator('#map canvas').screenshot();
    const { width, height } = pixelStats(canvas);
    for (const [x, y] of [inside, outside]) assert.ok(x > 0 && x < width && y > 0 && y < height, `(${x}, ${y}) is off the canvas`);
    const [a, b] = [pixelAt(canvas, ...inside), pixelAt(canvas, ...outside)];
    assert.ok(a.every((v, k) => Math.abs(v - b[k]) <= 6), `sea inside the bounds ${a} at ${inside}, outside ${b} at ${outside}`);
  });

  test('the exaggeration slider changes the terrain', async () => {
    // The rendered pixels, not the setting read back: under the 50° pitch, a relief three times
    // as tall moves its ridges and shading on screen. A second look at the still map first: the
    // comparison sees no change where there is none.
    const canvas = page.locator('#map canvas');
    const before = await canvas.screenshot();
    const still = changedShare(before, await canvas.screenshot());
    assert.ok(still < 0.001, `${(100 * still).toFixed(2)} % of the still canvas changed`);
    await page.evaluate(() => {
      window.strahlerIdleAgain = new Promise((resolve) => window.strahlerMap.once('idle', resolve));
    });
    await page.locator('#exaggeration').fill('3');
    await page.evaluate((ms) => Promise.race([window.strahlerIdleAgain,
      new Promise((resolve, reject) => setTimeout(() => reject(new Error('the map never became idle')), ms))]), STEP_MS);
    const after = await canvas.screenshot();
    writeFileSync(join(SCREENSHOTS, 'viewer-exaggeration-3.png'), after);
    const changed = changedShare(before, after);
    assert.ok(changed > 0.05, `only ${(100 * changed).toFixed(2)} % of the canvas changed`);
    assertNoErrors(record);
  });
});

describe('map viewer with drawn features (serve --features)', { skip: process.env.STRAHLER_TEST_SERVER ? 'needs its own server' : false }, () => {
  let drawn, page, record;

  before(async () => {
    const data = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'tests', 'data');
    drawn = await startServer(['--coast', join(data, 'corsica.geojson'), '--features', join(data, 'corsica-features.geojson')]);
    ({ page, record } = await openPage(browser, `${drawn.url}/`));
    await waitForIdleMap(page);
  }, { timeout: 2 * STEP_MS });

  after(async () => {
    await page?.close();
    await drawn?.stop();
  });

  test('the "Drawn features" checkbox draws the mountains, the ridge and the rivers', async () => {
    await page.waitForFunction(() => !document.getElementById('show-features').disabled, null, { timeout: STEP_MS });
    assert.equal(await page.textContent('#features-note'), '(8)');
    const hidden = await page.evaluate(() => window.strahlerMap.getLayoutProperty('drawn-rivers', 'visibility'));
    assert.equal(hidden, 'none');
    await page.click('#show-features');
    await waitForIdleMap(page);
    const state = await page.evaluate(() => {
      const map = window.strahlerMap;
      return {
        visibility: ['drawn-rivers', 'drawn-ridges'].map((id) => map.getLayoutProperty(id, 'visibility')),
        lines: map.queryRenderedFeatures({ layers: ['drawn-rivers', 'drawn-ridges'] }).length,
        mountains: document.querySelectorAll('.drawn-mountain').length,
        names: [...document.querySelectorAll('.drawn-river-name')].map((e) => e.textContent),
      };
    });
    assert.deepEqual(state.visibility, ['visible', 'visible']);
    assert.ok(state.lines > 0, 'no drawn line is rendered');
    assert.equal(state.mountains, 5);
    assert.deepEqual(state.names, ['Golo', 'Tavignano']);
    await page.screenshot({ path: join(SCREENSHOTS, 'viewer-features.png') });
    assertNoErrors(record, drawn.url);
  });
});

describe('map viewer camera in the URL', () => {
  let page, record;
  after(() => page?.close());

  test('opens at the #zoom/lat/lon/bearing/pitch it is given and keeps the hash current', async () => {
    const [lon, lat] = (await (await fetch(`${server.url}/worlds`)).json())[0].center;
    ({ page, record } = await openPage(browser, `${server.url}/#12.5/${lat.toFixed(4)}/${lon.toFixed(4)}/30/60`));
    // The camera is set when the map is made; no need to wait for its tiles.
    await page.waitForFunction(() => window.strahlerMap, null, { timeout: STEP_MS });
    const camera = await page.evaluate(() => {
      const map = window.strahlerMap;
      return { zoom: map.getZoom(), center: map.getCenter().toArray(), bearing: map.getBearing(), pitch: map.getPitch() };
    });
    assert.ok(Math.abs(camera.zoom - 12.5) < 1e-6, JSON.stringify(camera));
    assert.ok(Math.abs(camera.center[0] - lon) < 1e-3 && Math.abs(camera.center[1] - lat) < 1e-3, JSON.stringify(camera));
    assert.ok(Math.abs(camera.bearing - 30) < 1e-6 && Math.abs(camera.pitch - 60) < 1e-6, JSON.stringify(camera));

    // Moving the camera rewrites the hash (MapLibre throttles it), and the world stays in the query.
    await page.evaluate(([x, y]) => window.strahlerMap.jumpTo({ center: [x, y], zoom: 11, bearing: -45, pitch: 20 }), [lon + 0.01, lat - 0.01]);
    await page.waitForFunction(() => /^#11\/[-\d.]+\/[-\d.]+\/-45\/20$/.test(location.hash), null, { timeout: 10_000 });
    const url = new URL(await page.evaluate(() => location.href));
    assert.ok(url.searchParams.get('world'), `the world is not in ${url}`);
    const [, hashLat, hashLon] = url.hash.slice(1).split('/').map(Number);
    assert.ok(Math.abs(hashLat - (lat - 0.01)) < 1e-3 && Math.abs(hashLon - (lon + 0.01)) < 1e-3, url.hash);
    assert.deepEqual(record.errors, [], 'console errors, exceptions or failed requests');
  });
});

describe('map viewer over a PMTiles archive (?pmtiles=URL, any static server)', () => {
  let page, record, archive, files;

  before(async () => {
    archive = exportDefaultWorld('0-12');
    // The pages and the archive from one plain static server with Range support: no strahler.
    const webRoot = join(dirname(fileURLToPath(import.meta.url)), '..', 'dist');
    files = await startStaticServer([webRoot, archive.dir]);
    ({ page, record } = await openPage(browser, `${files.url}/?pmtiles=${archive.file}`));
    await waitForIdleMap(page);
  }, { timeout: 2 * STEP_MS });

  after(async () => {
    await page?.close();
    await files?.stop();
    if (archive) rmSync(archive.dir, { recursive: true, force: true });
  });

  test('reads its tiles from the archive by byte ranges, without errors', () => {
    assertNoErrors(record, files.url);
    const ranges = record.responses.filter((r) => r.url.endsWith(`/${archive.file}`));
    assert.ok(ranges.length >= 3, `header, directory and tiles come by range requests: ${ranges.length}`);
    for (const r of ranges) assert.equal(r.status, 206, r.url);
    assert.equal(record.responses.filter((r) => /\/worlds/.test(r.url)).length, 0, 'asked a strahler server');
  });

  test('shows the archive as terrain and hillshade with elevations', async () => {
    const state = await page.evaluate(() => {
      const map = window.strahlerMap;
      const centre = map.getCenter();
      return {
        terrain: map.getTerrain()?.source,
        dem: map.getSource('terrain-dem')?.url,
        encoding: map.getSource('shade')?.encoding,
        loaded: map.isSourceLoaded('shade') && map.isSourceLoaded('terrain-dem'),
        hillshade: map.getLayer('hillshade')?.type,
        elevation: map.queryTerrainElevation(centre),
        info: document.getElementById('world-info').textContent,
      };
    });
    assert.equal(state.terrain, 'terrain-dem');
    assert.match(state.dem, /^pmtiles:\/\/http:\/\/127\.0\.0\.1:\d+\/island\.pmtiles$/);
    assert.equal(state.encoding, 'mapbox');
    assert.ok(state.loaded, 'the archive sources are not loaded');
    assert.equal(state.hillshade, 'hillshade');
    assert.ok(Number.isFinite(state.elevation), `no terrain elevation at the centre: ${state.elevation}`);
    assert.match(state.info, /^default · \d+ km²/, 'the name and land area from the archive metadata');
    assert.equal(await page.isVisible('#layers'), false, 'an archive has no layer or vector tiles: no switcher');
    assertNotBlank(await page.locator('#map canvas').screenshot(), 'the map canvas');
    writeFileSync(join(SCREENSHOTS, 'viewer-pmtiles.png'), await page.screenshot());
  });
});

describe('map viewer layers, contours and rivers from the vector tiles (?rivers=vector)', () => {
  let page, record;
  const OVERLAYS = ['slope', 'illumination', 'humidity', 'vegetation-tree', 'vegetation-bush', 'water'];

  // Runs `action` (clicks in the page), then waits until the map is idle again.
  async function thenIdle(action) {
    await page.evaluate(() => {
      window.strahlerIdleAgain = new Promise((resolve) => window.strahlerMap.once('idle', resolve));
    });
    await action();
    await page.evaluate((ms) => Promise.race([window.strahlerIdleAgain,
      new Promise((resolve, reject) => setTimeout(() => reject(new Error('the map never became idle')), ms))]), STEP_MS);
  }

  before(async () => {
    // The default world is small enough for rivers.geojson; ?rivers=vector takes the large
    // worlds' path. Zoom 12 over the centre: contours every 50 m, every river order. A small
    // window, seen from above, keeps the layer tiles to compute few (6 layers × ~12 tiles).
    const [lon, lat] = (await (await fetch(`${server.url}/worlds`)).json())[0].center;
    ({ page, record } = await openPage(browser, `${server.url}/?rivers=vector#12/${lat.toFixed(4)}/${(lon - 0.01).toFixed(4)}/0/0`,
      { width: 800, height: 560 }));
    await waitForIdleMap(page);
  }, { timeout: 2 * STEP_MS });

  after(() => page?.close());

  test('draws the rivers of the vector tiles, not rivers.geojson', async () => {
    assertNoErrors(record);
    const mvt = record.responses.filter((r) => /\/vector\/\d+\/\d+\/\d+\.mvt(\?|$)/.test(r.url));
    assert.ok(mvt.length >= 1, 'no vector tile was requested');
    for (const tile of mvt) assert.equal(tile.status, 200, tile.url);
    await assertVersioned(mvt, 'a vector tile');
    assert.equal(record.responses.filter((r) => /rivers\.geojson/.test(r.url)).length, 0, 'fetched rivers.geojson');
    const state = await page.evaluate(() => {
      const map = window.strahlerMap;
      const rivers = map.queryRenderedFeatures({ layers: ['rivers'] });
      return { source: map.getLayer('rivers')?.source, count: rivers.length, orders: rivers.map((f) => f.properties.order) };
    });
    assert.equal(state.source, 'vector');
    assert.ok(state.count > 0, 'no river of the vector tiles is rendered');
    assert.ok(state.orders.every(Number.isInteger), `rivers without an order: ${state.orders}`);
  });

  test('click on a river of the vector tiles: popup with its type, order, flow and width; Rosgen type with the details open', async () => {
    await page.click('#details summary');
    const text = await clickRiver(page, 300);
    await page.click('#details summary'); // collapsed again for the tests that follow
    assert.match(text, RIVER_IN_WORDS);
    assert.match(text, /Flow [\d.]+ m³\/s/);
    assert.match(text, /Channel \d+ m wide/);
    const [, words] = RIVER_IN_WORDS.exec(text);
    const letter = { 'mountain stream': 'B', 'meandering river': 'E', 'braided river': 'D', 'delta channel': 'D-delta' }[words];
    assert.match(text, new RegExp(`Rosgen type ${letter}$`, 'm'));
    await page.evaluate(() => document.querySelectorAll('.maplibregl-popup').forEach((popup) => popup.remove()));
  });

  test('each derived layer: its tiles answer 200, carry more than one value and colour the map', async () => {
    assert.equal(await page.isVisible('#layers'), true, 'the layer switcher is hidden');
    const canvas = page.locator('#map canvas');
    const before = await canvas.screenshot(); // no overlay; each one is switched off after its turn
    let previous = null;
    for (const id of OVERLAYS) {
      await thenIdle(async () => {
        if (previous) await page.click(`#overlay-${previous}`);
        await page.click(`#overlay-${id}`);
      });
      previous = id;
      const after = await canvas.screenshot();
      writeFileSync(join(SCREENSHOTS, `viewer-layer-${id}.png`), after);
      const changed = changedShare(before, after);
      // Inland, water is the rivers and lakes only: a smaller share of the view.
      const least = id === 'water' ? 0.003 : 0.02;
      assert.ok(changed > least, `${id}: only ${(100 * changed).toFixed(2)} % of the canvas changed`);
      const stats = await page.evaluate((key) => window.strahlerLayerStats[key], id);
      assert.ok(stats?.tiles >= 1 && stats.high > stats.low, `${id}: ${JSON.stringify(stats)}`);
      assert.equal(await page.locator('.layer-legend:visible').count(), 1, `${id}: one legend`);
    }
    await thenIdle(() => page.click(`#overlay-${previous}`));
    const tiles = record.responses.filter((r) => /\/layers\/[a-z]+\/\d+\/\d+\/\d+\.png/.test(r.url));
    for (const tile of tiles) assert.equal(tile.status, 200, tile.url);
    for (const name of ['slope', 'illumination', 'humidity', 'vegetation', 'water']) {
      assert.ok(tiles.some((t) => t.url.includes(`/layers/${name}/`)), `no ${name} tile was requested`);
    }
    assert.ok(tiles.some((t) => new URL(t.url).searchParams.get('species') === 'bush'), 'no bush tile was requested');
    await assertVersioned(tiles, 'a layer tile');
    assertNoErrors(record);
  });

  test('a 16-bit slope tile reaches the page as its high byte, as the slope legend says', async () => {
    const { z, x, y } = await page.evaluate(() => {
      const { lng, lat } = window.strahlerMap.getCenter();
      const n = 2 ** 12, r = (lat * Math.PI) / 180;
      return { z: 12, x: Math.floor(((lng + 180) / 360) * n), y: Math.floor(((1 - Math.asinh(Math.tan(r)) / Math.PI) / 2) * n) };
    });
    const [world] = await (await fetch(`${server.url}/worlds`)).json();
    const url = `${server.url}/worlds/${world.id}/layers/slope/${z}/${x}/${y}.png`;
    const png = PNG.sync.read(Buffer.from(await (await fetch(url)).arrayBuffer()), { skipRescale: true });
    assert.equal(png.depth, 16);
    const codes = await page.evaluate(async (tile) => {
      const { readGrey } = await import('./src/layer-ramps.js');
      const { image } = await readGrey(await (await fetch(tile)).blob());
      return Array.from(image.data.filter((_, i) => i % 4 === 0));
    }, url);
    assert.equal(codes.length, png.width * png.height);
    const wrong = codes.findIndex((code, i) => code !== png.data[4 * i] >> 8);
    assert.equal(wrong, -1, `pixel ${wrong}: ${png.data[4 * wrong]} read as ${codes[wrong]}`);
    assert.ok(Math.max(...codes) > 0, 'a flat tile says nothing');
  });

  test('contours from the vector tiles, index contours among them', async () => {
    const canvas = page.locator('#map canvas');
    const before = await canvas.screenshot();
    await thenIdle(() => page.click('#show-contours'));
    const after = await canvas.screenshot();
    writeFileSync(join(SCREENSHOTS, 'viewer-contours.png'), after);
    const counts = await page.evaluate(() => ['contours', 'contours-index']
      .map((id) => window.strahlerMap.queryRenderedFeatures({ layers: [id] }).length));
    assert.ok(counts[0] > 0 && counts[1] > 0, `contours drawn (plain, index): ${counts}`);
    const changed = changedShare(before, after);
    assert.ok(changed > 0.005, `only ${(100 * changed).toFixed(2)} % of the canvas changed`);
    assertNoErrors(record);
  });
});

describe('game client', () => {
  let page, record;
  const stats = () => page.evaluate(() => ({ ...window.strahlerGame.stats, frames: window.strahlerGame.frames }));

  before(async () => {
    ({ page, record } = await openPage(browser, `${server.url}/game.html`));
    // Settled: some frames drawn, tiles loaded and nothing left in flight for a moment. A failed
    // tile ends the wait too: the tests below then report which request failed and why.
    await page.waitForFunction(() => {
      const g = window.strahlerGame;
      if (g?.stats.failed > 0) return true;
      if (!g || g.frames < 30 || g.stats.loaded < 1 || g.stats.inFlight > 0) return false;
      g.quietSince ??= g.frames;
      return g.frames - g.quietSince > 20;
    }, null, { timeout: 2 * STEP_MS, polling: 100 });
  }, { timeout: 2 * STEP_MS + 10_000 });

  after(() => page?.close());

  test('streams Draco mesh tiles without errors and refines the quadtree', async () => {
    assertNoErrors(record);
    const meshes = record.responses.filter((r) => /\/local\/\d+\/\d+\/\d+\.glb/.test(r.url));
    assert.ok(meshes.length >= 1, 'no mesh tile was requested');
    for (const mesh of meshes) assert.match(mesh.type, /^model\/gltf-binary/, mesh.url);
    await assertVersioned(meshes, 'a mesh tile');
    const s = await stats();
    assert.ok(s.loaded >= 1 && s.visible >= 1 && s.failed === 0, JSON.stringify(s));
    const minZoom = await page.evaluate(() => window.strahlerGame.streamer.minZoom);
    assert.ok(s.maxVisibleZoom > minZoom, `no tile finer than the roots is drawn: ${JSON.stringify(s)}`);
  });

  test('draws a terrain that is not blank (screenshot)', async () => {
    // Sky, fog and sea alone already vary: the terrain must be among what is drawn.
    assert.ok((await stats()).visible >= 1, 'no terrain tile is drawn');
    assertNotBlank(await page.locator('#scene').screenshot(), 'the game canvas');
    writeFileSync(join(SCREENSHOTS, 'game.png'), await page.screenshot());
  });

  test('flies with the keyboard and evicts tiles it no longer needs', async () => {
    const before = await page.evaluate(() => window.strahlerGame.camera.position.toArray());
    await page.keyboard.down('KeyW');
    await page.waitForFunction((z) => window.strahlerGame.camera.position.z < z - 1, before[2], { timeout: 10_000 });
    await page.keyboard.up('KeyW');
    // With no cache budget, tiles that leave the selection are evicted at once: turn around.
    await page.evaluate(() => {
      const g = window.strahlerGame;
      g.streamer.maxCached = 0;
      g.camera.rotation.y += Math.PI;
    });
    await page.waitForFunction(() => window.strahlerGame.stats.evicted > 0, null, { timeout: 10_000 });
    assertNoErrors(record);
  });
});

describe('game client vegetation', () => {
  let page, record;
  const vegetation = () => page.evaluate(() => ({ ...window.strahlerGame.vegetation.stats }));

  before(async () => {
    ({ page, record } = await openPage(browser, `${server.url}/game.html`));
    await page.waitForFunction(() => window.strahlerGame?.stats.loaded > 0 && window.strahlerGame.stats.inFlight === 0,
      null, { timeout: STEP_MS, polling: 100 });
  }, { timeout: STEP_MS + 10_000 });

  after(() => page?.close());

  test('instances trees and bushes near the ground from vegetation tiles, without errors', async () => {
    // Low land near the world's centre, where the vegetation layer puts forests (valleys), found
    // on the loaded terrain: the camera 25 m above it, looking along the ground.
    const spots = await page.evaluate(() => {
      const g = window.strahlerGame;
      const { rootSide, rootSouthWest: [west, south] } = g.world.local;
      const out = [];
      for (let j = 1; j < 12; j += 1) {
        for (let i = 1; i < 12; i += 1) {
          const x = west + (rootSide * i) / 12, z = -(south + (rootSide * j) / 12);
          const h = g.groundAt(x, z);
          if (h !== null && h > 15 && h < 400) out.push([x, h, z]);
        }
      }
      return out.sort((a, b) => a[1] - b[1]);
    });
    assert.ok(spots.length > 0, 'no low land found on the terrain');
    let stats;
    // Wait for a dozen frames at a new position (update() has seen it with the ground under it,
    // sampled every ten frames) and every vegetation tile it wants loaded: waiting for the first
    // answers alone raced the later requests (trees missed one run in three).
    const settleAt = async (x, y, z) => {
      const frame = await page.evaluate(([x, y, z]) => {
        const { camera, frames } = window.strahlerGame;
        camera.position.set(x, y, z);
        camera.rotation.set(-0.15, 0.4, 0, 'YXZ');
        return frames;
      }, [x, y, z]);
      await page.waitForFunction((frame) => {
        const g = window.strahlerGame;
        return g.frames > frame + 12 && g.vegetation.settled && g.vegetation.stats.requested > 0 &&
          g.vegetation.inFlight === 0 && g.stats.inFlight === 0;
      }, frame, { timeout: STEP_MS, polling: 200 });
    };
    for (const [x, h, z] of spots.slice(0, 6)) {
      await settleAt(x, h + 25, z);
      // The finer tiles loaded there may raise the ground by tens of metres (the camera then
      // stood among the trunks): 25 m above the ground as loaded now, until it holds.
      for (let again = 0; again < 3; again += 1) {
        const ground = await page.evaluate(([x, z]) => window.strahlerGame.groundAt(x, z), [x, z]);
        const y = await page.evaluate(() => window.strahlerGame.camera.position.y);
        if (ground === null || Math.abs(ground + 25 - y) < 5) break;
        await settleAt(x, ground + 25, z);
      }
      stats = await vegetation();
      if (stats.tree > 0 && stats.bush > 0) break;
    }
    assert.ok(stats.tree > 0 && stats.failed === 0, `no tree drawn: ${JSON.stringify(stats)}`);
    assert.ok(stats.bush > 0, `no bush drawn: ${JSON.stringify(stats)}`);
    const tiles = record.responses.filter((r) => /\/vegetation\/1[67]\/\d+\/\d+\.json/.test(r.url));
    assert.ok(tiles.length > 0, 'no vegetation tile was requested');
    // Trees come from zoom-16 tiles, bushes from zoom-17 ones (vegetation.js): both were asked.
    for (const z of [16, 17]) {
      assert.ok(tiles.some((t) => t.url.includes(`/vegetation/${z}/`)), `no zoom-${z} vegetation tile`);
    }
    for (const tile of tiles) assert.match(tile.type, /^application\/json/, tile.url);
    await assertVersioned(tiles, 'a vegetation tile');
    const drawn = await page.evaluate(() => window.strahlerGame.vegetation.group.children
      .map((mesh) => ({ name: mesh.name, count: mesh.count, instanced: mesh.isInstancedMesh })));
    assert.ok(drawn.some((m) => m.name === 'trees' && m.instanced && m.count === stats.tree), JSON.stringify(drawn));
    // vegetation.js names each kind's meshes `${kind.name}s`.
    assert.ok(drawn.some((m) => m.name === 'bushs' && m.instanced && m.count === stats.bush), JSON.stringify(drawn));
    await page.waitForTimeout(500);
    assertNotBlank(await page.locator('#scene').screenshot(), 'the game canvas near the ground');
    writeFileSync(join(SCREENSHOTS, 'game-vegetation.png'), await page.screenshot());
    assertNoErrors(record);
  });
});
