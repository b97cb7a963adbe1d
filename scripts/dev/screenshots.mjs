// Close-up pictures of a world as its users see it: the map viewer pitched at zoom 13 and the
// game demo near the ground, over one spot, in Debian's chromium against a real `strahler serve`.
//   node scripts/dev/screenshots.mjs LON LAT OUT_PREFIX [strahler serve arguments...]
// e.g. node scripts/dev/screenshots.mjs 2.93 39.70 /tmp/mallorca --coast tests/data/mallorca.geojson
// writes OUT_PREFIX-viewer.png and OUT_PREFIX-game.png, and the same view with the layer
// switcher's slope, illumination and contours (OUT_PREFIX-viewer-slope.png, -illumination.png,
// -contours.png). Needs `npm ci --prefix web`, the web build and build/release/bin/strahler
// (what scripts/test makes).
import { spawn } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { tmpdir } from 'node:os';
import { fileURLToPath } from 'node:url';
import { launchBrowser, openPage } from '../../web/tests/lib/browser.mjs';

const [lon, lat] = process.argv.slice(2, 4).map(Number);
const prefix = process.argv[4];
if (!Number.isFinite(lon) || !Number.isFinite(lat) || !prefix) {
  console.error('usage: node scripts/dev/screenshots.mjs LON LAT OUT_PREFIX [serve arguments...]');
  process.exit(2);
}
const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const WAIT_MS = 120_000;

function serve(args) {
  const child = spawn(join(repo, 'build/release/bin/strahler'),
    ['serve', '--host', '127.0.0.1', '--port', '0', '--quiet', '--web-root', join(repo, 'web/dist'),
      '--cache-dir', join(tmpdir(), 'strahler-screenshots-cache'), ...args], { stdio: ['ignore', 'pipe', 'inherit'] });
  process.on('exit', () => child.kill('SIGKILL'));
  return new Promise((done, fail) => {
    let out = '';
    child.stdout.on('data', (chunk) => {
      out += chunk;
      const m = /serving .* at (http:\/\/[^\s/]+)\//.exec(out);
      if (m) done(m[1]);
    });
    child.on('exit', (code) => fail(new Error(`strahler serve exited with ${code}`)));
  });
}

// The world's local metres of (lon, lat): Lambert azimuthal equal-area on the sphere about the
// world's centre, as core/geometry LocalProjection.
function toLocal([lon0, lat0], lon1, lat1) {
  const r = Math.PI / 180, R = 6371008.8;
  const [l, p, l0, p0] = [lon1 * r, lat1 * r, lon0 * r, lat0 * r];
  const k = Math.sqrt(2 / (1 + Math.sin(p0) * Math.sin(p) + Math.cos(p0) * Math.cos(p) * Math.cos(l - l0)));
  return [R * k * Math.cos(p) * Math.sin(l - l0),
    R * k * (Math.cos(p0) * Math.sin(p) - Math.sin(p0) * Math.cos(p) * Math.cos(l - l0))];
}

const url = await serve(process.argv.slice(5));
const browser = await launchBrowser();
try {
  const viewer = (await openPage(browser, `${url}/`)).page;
  await viewer.waitForFunction(() => window.strahlerMap?.loaded(), null, { timeout: WAIT_MS });
  await viewer.evaluate(([lo, la]) => window.strahlerMap.jumpTo({ center: [lo, la], zoom: 13, pitch: 60, bearing: 20 }), [lon, lat]);
  await viewer.waitForFunction(() => {
    const m = window.strahlerMap;
    return m.loaded() && m.areTilesLoaded() && !m.isMoving();
  }, null, { timeout: WAIT_MS, polling: 250 });
  await viewer.waitForTimeout(1500);
  writeFileSync(`${prefix}-viewer.png`, await viewer.screenshot());
  // The same view with one switch of the layer switcher on at a time (each switched off after).
  for (const [name, checkbox] of [['slope', '#overlay-slope'], ['illumination', '#overlay-illumination'], ['contours', '#show-contours']]) {
    await viewer.click(checkbox);
    await viewer.waitForTimeout(500);
    await viewer.waitForFunction(() => {
      const m = window.strahlerMap;
      return m.loaded() && m.areTilesLoaded() && !m.isMoving();
    }, null, { timeout: WAIT_MS, polling: 250 });
    await viewer.waitForTimeout(1000);
    writeFileSync(`${prefix}-viewer-${name}.png`, await viewer.screenshot());
    await viewer.click(checkbox);
  }
  const ground = await viewer.evaluate(([lo, la]) => {
    const m = window.strahlerMap;
    return (m.queryTerrainElevation([lo, la]) ?? 0) / (m.getTerrain()?.exaggeration ?? 1);
  }, [lon, lat]);

  const game = (await openPage(browser, `${url}/game.html`)).page;
  await game.waitForFunction(() => window.strahlerGame?.frames > 5, null, { timeout: WAIT_MS });
  const centre = await game.evaluate(() => window.strahlerGame.world.center);
  const [x, y] = toLocal(centre, lon, lat);
  // 1.5 km south of the spot, 250 m above the higher of the spot and the loaded terrain under
  // the camera (so that a slope rising south of the spot does not swallow it), looking north.
  await game.evaluate(([gx, gz, h]) => {
    const g = window.strahlerGame;
    const under = g.groundAt(gx, gz + 1500) ?? h;
    g.camera.position.set(gx, Math.max(h, under) + 250, gz + 1500);
    g.camera.lookAt(gx, h, gz - 500);
  }, [x, -y, ground]);
  const quiet = game.waitForFunction(() => {
    const g = window.strahlerGame;
    // Quiet for 3 s and 3 frames: software GL on a loaded host draws about one frame a second.
    if (g.stats.inFlight > 0) { g.quietSince = undefined; return false; }
    g.quietSince ??= { frames: g.frames, at: performance.now() };
    return g.frames - g.quietSince.frames >= 3 && performance.now() - g.quietSince.at > 3000;
  }, null, { timeout: WAIT_MS, polling: 100 });
  // A busy host may never let the streamer go quiet: shoot anyway, and say what was pending.
  await quiet.catch(async () => {
    const s = await game.evaluate(() => {
      const g = window.strahlerGame;
      return { frames: g.frames, tiles: g.stats.inFlight, plants: g.vegetation.inFlight };
    });
    console.warn(`screenshots: the game was not quiet after ${WAIT_MS / 1000} s ` +
      `(${s.frames} frames, ${s.tiles} tiles and ${s.plants} vegetation tiles in flight)`);
  });
  writeFileSync(`${prefix}-game.png`, await game.screenshot());
  console.log(`wrote ${prefix}-viewer.png and ${prefix}-game.png (ground ${ground.toFixed(0)} m)`);
} catch (error) {
  console.error(`screenshots: ${error.message}`);
  process.exitCode = 1;
} finally {
  await browser.close();
  process.exit(process.exitCode ?? 0);
}
