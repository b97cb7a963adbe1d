// Starts a real `strahler serve` for the browser tests, on an ephemeral port of 127.0.0.1,
// serving the built pages (web/dist) and the default world from a test cache directory.
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const STARTUP_MS = 60_000; // includes generating the default world when the cache is cold

/** The strahler program the tests run: $STRAHLER_BIN, else build/release/bin/strahler. */
export function strahlerBinary() {
  const binary = process.env.STRAHLER_BIN ?? join(repoRoot, 'build', 'release', 'bin', 'strahler');
  if (!existsSync(binary)) throw new Error(`${binary} is missing: build it first (scripts/build.sh release)`);
  return binary;
}

/**
 * Resolves to { url, stop() }. STRAHLER_TEST_SERVER=http://host:port tests a server that is
 * already running instead; STRAHLER_BIN overrides the program (default build/release/bin/strahler).
 * `extraArgs` go to `strahler serve` (e.g. --coast FILE --features FILE).
 */
export async function startServer(extraArgs = []) {
  if (process.env.STRAHLER_TEST_SERVER) {
    return { url: process.env.STRAHLER_TEST_SERVER.replace(/\/$/, ''), stop: async () => {} };
  }
  const binary = strahlerBinary();
  const webRoot = join(repoRoot, 'web', 'dist');
  if (!existsSync(join(webRoot, 'index.html'))) throw new Error(`${webRoot} is missing: run \`npm run build --prefix web\``);

  const child = spawn(binary, ['serve', '--host', '127.0.0.1', '--port', '0', '--quiet',
    '--cache-dir', join(tmpdir(), 'strahler-web-tests-cache'), '--web-root', webRoot, ...extraArgs], { stdio: ['ignore', 'pipe', 'pipe'] });
  const killNow = () => child.kill('SIGKILL');
  process.on('exit', killNow); // even if the test process dies without running after()
  for (const signal of ['SIGINT', 'SIGTERM']) process.once(signal, () => process.exit(1)); // runs killNow
  let output = '';
  child.stderr.on('data', (chunk) => { output += chunk; });

  const url = await new Promise((resolveUrl, reject) => {
    const timer = setTimeout(() => reject(new Error(`strahler serve did not start in ${STARTUP_MS} ms:\n${output}`)), STARTUP_MS);
    child.stdout.on('data', (chunk) => {
      output += chunk;
      const match = /serving .* at (http:\/\/[^\s/]+)\//.exec(output);
      if (match) { clearTimeout(timer); resolveUrl(match[1]); }
    });
    child.on('exit', (code) => { clearTimeout(timer); reject(new Error(`strahler serve exited with ${code}:\n${output}`)); });
  });

  const stop = () => new Promise((done) => {
    process.off('exit', killNow);
    if (child.exitCode !== null) return done();
    const force = setTimeout(() => child.kill('SIGKILL'), 5000); // it drains for up to 4 s on SIGTERM
    child.once('exit', () => { clearTimeout(force); done(); });
    child.kill('SIGTERM');
  });
  return { url, stop };
}
