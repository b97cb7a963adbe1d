// A PMTiles archive of the default world made by the real `strahler export`, for the viewer's
// ?pmtiles=URL test.
import { execFileSync } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { strahlerBinary } from './server.mjs';

/** Writes the default island's tiles of zooms `zooms` ("A-B") to a fresh folder; resolves to { dir, file }. */
export function exportDefaultWorld(zooms) {
  const binary = strahlerBinary();
  const dir = mkdtempSync(join(tmpdir(), 'strahler-web-pmtiles-'));
  const world = join(dir, 'island.world');
  // The same cache as the server's (lib/server.mjs): the world is loaded, not generated again.
  execFileSync(binary, ['generate', '--quiet', '--cache-dir', join(tmpdir(), 'strahler-web-tests-cache'), '-o', world]);
  const file = 'island.pmtiles';
  execFileSync(binary, ['export', world, '--zooms', zooms, '--quiet', '-o', join(dir, file)]);
  return { dir, file };
}
