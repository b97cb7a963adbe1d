// ?pmtiles=URL: the viewer shows a PMTiles archive written by `strahler export` instead of a
// strahler server's worlds. Any static HTTP server that answers Range requests can serve it
// (object storage, a CDN, `npx http-server`); the pmtiles library reads only the byte ranges
// it needs. The archive holds no rivers, so the river layers stay empty.
import { PMTiles, Protocol } from 'pmtiles';

const NO_RIVERS = { type: 'FeatureCollection', features: [] };

/** The absolute URL of the archive named by ?pmtiles=, or null when there is none. */
export function pmtilesArchiveUrl(search = location.search) {
  const url = new URLSearchParams(search).get('pmtiles');
  return url ? new URL(url, location.href).href : null;
}

/**
 * Registers the pmtiles:// protocol with MapLibre and describes the archive at `url` as the
 * viewer's only world: { worlds, selected }, with its own raster-dem source (`demSource`) and
 * no rivers (`riversData`).
 */
export async function archiveWorlds(maplibregl, url) {
  const protocol = new Protocol();
  maplibregl.addProtocol('pmtiles', protocol.tile);
  const archive = new PMTiles(url);
  protocol.add(archive);
  const [header, metadata] = await Promise.all([archive.getHeader(), archive.getMetadata()]);
  const demSource = {
    type: 'raster-dem',
    url: `pmtiles://${url}`,
    tileSize: Number(metadata?.tileSize) || 256,
    encoding: metadata?.encoding === 'terrarium' ? 'terrarium' : 'mapbox',
  };
  const world = {
    id: metadata?.worldId ?? 'archive',
    name: metadata?.name ?? url,
    areaKm2: metadata?.areaKm2, // the world's land, as `strahler export` records it
    bounds: [header.minLon, header.minLat, header.maxLon, header.maxLat],
    demSource,
    riversData: NO_RIVERS,
  };
  return { worlds: [world], selected: world };
}
