// Debian's chromium driven by playwright-core (a browser download does not work here), with
// the software WebGL2 (SwiftShader) that MapLibre needs; see the PLATFORM notes.
import { chromium } from 'playwright-core';
import { existsSync } from 'node:fs';

const CHROMIUM = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
const FLAGS = ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];

export async function launchBrowser() {
  if (!existsSync(CHROMIUM)) throw new Error(`${CHROMIUM} is missing: install Debian's chromium (apt-get install chromium)`);
  return chromium.launch({ executablePath: CHROMIUM, headless: true, args: FLAGS, timeout: 30_000 });
}

/**
 * Opens `url` in a fresh page and records what the tests assert on: console errors, uncaught
 * exceptions, failed requests and every response (url, status, content type). `viewport`
 * defaults to 1280 × 800.
 */
export async function openPage(browser, url, viewport = { width: 1280, height: 800 }) {
  const page = await browser.newPage({ viewport });
  const record = { errors: [], responses: [] };
  page.on('console', (message) => {
    if (message.type() === 'error') record.errors.push(`console: ${message.text()} (${message.location().url})`);
  });
  page.on('pageerror', (error) => record.errors.push(`exception: ${error.message}`));
  page.on('requestfailed', (request) => {
    // Requests cancelled by the page itself (MapLibre aborts tiles that left the view) are fine.
    const reason = request.failure()?.errorText ?? '';
    if (!reason.includes('ERR_ABORTED')) record.errors.push(`request failed: ${request.url()} ${reason}`);
  });
  page.on('response', (response) => record.responses.push({
    url: response.url(), status: response.status(), type: response.headers()['content-type'] ?? '',
    encoding: response.headers()['content-encoding'] ?? '',
  }));
  await page.goto(url, { waitUntil: 'load', timeout: 30_000 });
  return { page, record };
}
