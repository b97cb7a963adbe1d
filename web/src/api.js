// The server's world list, shared by the map viewer and the game client.
// URLs are relative to the page, so the pages also work behind a path prefix (a proxy).

export async function fetchJson(path) {
  const response = await fetch(new URL(path, location.href));
  if (!response.ok) throw new Error(`GET ${path}: HTTP ${response.status}`);
  return response.json();
}

/** The worlds the server offers (GET /worlds), and the one named by ?world=ID, else the first. */
export async function loadWorlds() {
  const worlds = await fetchJson('worlds');
  if (!Array.isArray(worlds) || worlds.length === 0) throw new Error('the server offers no world');
  const wanted = new URLSearchParams(location.search).get('world');
  return { worlds, selected: worlds.find((w) => w.id === wanted) ?? worlds[0] };
}

/** Absolute URL of a resource of a world, e.g. worldUrl(w, 'rivers.geojson'). */
export function worldUrl(world, path) {
  return new URL(`worlds/${encodeURIComponent(world.id)}/${path}`, location.href).href;
}

/**
 * Absolute URL of a tile of a world: worldUrl() plus the world's content version (`v`, from
 * GET /worlds), so that the URL names one content and may be cached for good; a regenerated
 * world has another version, so its tiles have other URLs.
 */
export function tileUrl(world, path) {
  return withVersion(worldUrl(world, path), world);
}

/** `url` (a URL or a URL template) with the world's content version as its `v` parameter. */
export function withVersion(url, world) {
  if (!world.version) return url;
  return `${url}${url.includes('?') ? '&' : '?'}v=${encodeURIComponent(world.version)}`;
}

/** Remembers the chosen world in the address bar, so that a reload keeps it. */
export function rememberWorld(world) {
  const url = new URL(location.href);
  url.searchParams.set('world', world.id);
  history.replaceState(null, '', url);
}
