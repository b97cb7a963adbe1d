// The Cesium page (/cesium: CesiumJS on the world's quantized-mesh terrain) in a real browser
// (Debian's chromium, SwiftShader WebGL) against a real `strahler serve`. Screenshots go to
// web/tests/screenshots/.
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { launchBrowser, openPage } from './lib/browser.mjs';
import { changedShare, pixelStats } from './lib/pixels.mjs';
import { startServer } from './lib/server.mjs';

const SCREENSHOTS = join(dirname(fileURLToPath(import.meta.url)), 'screenshots');
const TOTAL_MS = 420_000; // the whole file, server start to browser close (2–3 min here when idle)
const STEP_MS = 150_000;  // any one wait in a page (SwiftShader draws a globe slowly, slower on a busy machine)
// Smaller than the other pages' 1280 × 800: SwiftShader's cost goes with the pixels.
const VIEWPORT = { width: 960, height: 600 };

let server, browser;
const watchdog = setTimeout(() => {
  console.error(`cesium page tests exceeded ${TOTAL_MS} ms`);
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

/**
 * Waits until the globe has drawn frames and loaded every tile it wants, and has stayed so for
 * a moment (CesiumJS loads tiles over several frames).
 */
async function waitForSettledGlobe(page) {
  await page.waitForFunction(() => window.strahlerCesium, null, { timeout: STEP_MS });
  await page.evaluate(() => {
    const { viewer } = window.strahlerCesium;
    window.strahlerFrames = 0;
    viewer.scene.postRender.addEventListener(() => { window.strahlerFrames += 1; });
  });
  await page.waitForFunction(() => {
    const { viewer } = window.strahlerCesium;
    if (window.strahlerFrames < 10 || !viewer.scene.globe.tilesLoaded) {
      window.strahlerQuietSince = undefined;
      return false;
    }
    window.strahlerQuietSince ??= window.strahlerFrames;
    return window.strahlerFrames - window.strahlerQuietSince > 10;
  }, null, { timeout: STEP_MS, polling: 200 });
}

// The test's own server (web/tests/lib/server.mjs) always serves colour-relief tiles: the page
// must drape them. Only a server under test from outside (STRAHLER_TEST_SERVER) may lack them.
const OWN_SERVER = !process.env.STRAHLER_TEST_SERVER;

// No console error, no HTTP error, and nothing fetched from anywhere but our server (offline, no Ion).
// A server without colour-relief tiles answers the page's one probe for them with an error (the
// page then shows the terrain without imagery): that answer alone is allowed, only then, and
// never from the test's own server.
function assertNoErrors(record, relief) {
  const probe = (text) => !OWN_SERVER && !relief && /\/tiles\/0\/0\/0\.relief/.test(text);
  assert.deepEqual(record.errors.filter((e) => !probe(e)), [], 'console errors, exceptions or failed requests');
  assert.deepEqual(record.responses.filter((r) => r.status >= 400 && !probe(r.url)), [], 'HTTP error responses');
  const foreign = record.responses.filter((r) => !r.url.startsWith(`${server.url}/`) && !/^(data|blob):/.test(r.url));
  assert.deepEqual(foreign, [], 'requests to other servers');
  assert.ok(server.url.startsWith('http://127.0.0.1:') || process.env.STRAHLER_TEST_SERVER, server.url);
}

const terrainLevels = (record) => record.responses
  .map((r) => /\/cesium\/(\d+)\/\d+\/\d+\.terrain/.exec(r.url)).filter(Boolean).map((m) => Number(m[1]));

describe('Cesium page', () => {
  let page, record, ellipsoid, relief;

  before(async () => {
    // The baseline: the same page and view over the bare ellipsoid (no terrain).
    const bare = await openPage(browser, `${server.url}/cesium?ellipsoid=1`, VIEWPORT);
    await waitForSettledGlobe(bare.page);
    ellipsoid = await bare.page.locator('#globe canvas').screenshot();
    assert.equal(terrainLevels(bare.record).length, 0, 'the ellipsoid page fetched terrain');
    await bare.page.close();

    ({ page, record } = await openPage(browser, `${server.url}/cesium`, VIEWPORT));
    await waitForSettledGlobe(page);
    relief = await page.evaluate(() => window.strahlerCesium.relief);
  }, { timeout: 2.5 * STEP_MS });

  after(() => page?.close());

  test('loads layer.json and quantized-mesh tiles from our server only, without errors', async () => {
    assertNoErrors(record, relief);
    if (OWN_SERVER) assert.equal(relief, true, 'the relief probe failed on a server that serves relief');
    const { version } = (await (await fetch(`${server.url}/worlds`)).json())[0];
    if (relief) {
      const imagery = record.responses.filter((r) => /\/tiles\/\d+\/\d+\/\d+\.relief/.test(r.url));
      assert.ok(imagery.length >= 2 && imagery.every((r) => r.status === 200 && /^image\/png/.test(r.type)), JSON.stringify(imagery.slice(0, 3)));
      // Every URL carries the world's content version, so caches may keep the tiles for good.
      for (const r of imagery) assert.equal(new URL(r.url).searchParams.get('v'), version, r.url);
    }
    const layer = record.responses.filter((r) => /\/worlds\/[^/]+\/cesium\/layer\.json$/.test(r.url));
    assert.equal(layer.length, 1, 'GET layer.json');
    const terrain = record.responses.filter((r) => /\/cesium\/\d+\/\d+\/\d+\.terrain/.test(r.url));
    assert.ok(terrain.length >= 4, `${terrain.length} terrain tiles`);
    for (const r of terrain) {
      assert.equal(r.status, 200, r.url);
      assert.equal(r.type, 'application/vnd.quantized-mesh', r.url);
      assert.equal(new URL(r.url).searchParams.get('v'), version, r.url); // layer.json's {version}
    }
    const state = await page.evaluate(() => {
      const { viewer } = window.strahlerCesium;
      const { globe } = viewer.scene;
      return {
        normals: viewer.terrainProvider.hasVertexNormals, water: viewer.terrainProvider.hasWaterMask,
        metadata: viewer.terrainProvider.hasMetadata, lighting: globe.enableLighting, waterEffect: globe.showWaterEffect,
        imagery: viewer.imageryLayers.length, relief: window.strahlerCesium.relief,
      };
    });
    assert.deepEqual(state, { normals: true, water: true, metadata: true, lighting: true, waterEffect: true, imagery: state.relief ? 1 : 0, relief: state.relief });
  });

  test('draws terrain: not blank, and not the bare ellipsoid (screenshots)', async () => {
    const shot = await page.locator('#globe canvas').screenshot();
    const stats = pixelStats(shot);
    assert.ok(stats.stdDev > 8 && stats.colours > 64, `the globe looks blank: ${JSON.stringify(stats)}`);
    const changed = changedShare(ellipsoid, shot);
    assert.ok(changed > 0.05, `only ${(100 * changed).toFixed(2)} % of the canvas differs from the bare ellipsoid`);
    writeFileSync(join(SCREENSHOTS, 'cesium.png'), await page.screenshot());
    writeFileSync(join(SCREENSHOTS, 'cesium-ellipsoid.png'), ellipsoid);
  });

  test('reports the server timing of its terrain tiles', async () => {
    const s = await page.evaluate(() => window.strahlerCesium.timings.summary());
    assert.ok(s.count >= 1 && Number.isFinite(s.fetch), JSON.stringify(s));
    assert.equal(await page.locator('#timings').isVisible(), false); // behind "Details"
    await page.click('#details summary');
    assert.match(await page.locator('#timings').innerText(), /\d+ tiles/);
    // The layer.json URL breaks only after a slash: no "htt p://".
    const url = await page.locator('#layer-url').evaluate((code) => ({
      text: code.textContent, breaks: code.querySelectorAll('wbr').length,
      style: getComputedStyle(code).wordBreak,
    }));
    assert.match(url.text, /^http:\/\/127\.0\.0\.1:\d+\/worlds\/[\w-]+\/cesium\/layer\.json$/);
    assert.equal(url.breaks, url.text.split('/').length);
    assert.equal(url.style, 'normal');
  });

  test('refines when the camera comes close to the ground', async () => {
    const before = Math.max(...terrainLevels(record));
    // 2.5 km above the ground at the world's centre, looking north 30° down.
    await page.evaluate(() => window.strahlerCesium.lookAt(...window.strahlerCesium.world.center, 2500));
    await page.waitForFunction(() => window.strahlerCesium.viewer.scene.globe.tilesLoaded === false, null, { timeout: 10_000, polling: 50 })
      .catch(() => { /* it may have loaded them at once */ });
    await waitForSettledGlobe(page);
    const afterLevel = Math.max(...terrainLevels(record));
    assert.ok(afterLevel >= before + 3, `deepest terrain level ${before} before, ${afterLevel} after the fly-to`);
    const height = await page.evaluate(() => window.strahlerCesium.viewer.camera.positionCartographic.height);
    assert.ok(height < 20_000, `the camera is ${height} m up`);
    writeFileSync(join(SCREENSHOTS, 'cesium-close.png'), await page.screenshot());
    assertNoErrors(record, relief);
  });
});
