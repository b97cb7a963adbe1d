// Trees and bushes for the game client: strahler's vegetation tiles
// (GET /worlds/{id}/vegetation/{z}/{x}/{y}.json, Web Mercator) drawn with one THREE.InstancedMesh
// per part and species, coloured by the vegetation layer (layers/vegetation/...png?species=).
//
// Level of detail by distance: trees come from the zoom-16 tiles within TREES.radius of the
// camera (horizontally), bushes from the zoom-17 tiles within BUSHES.radius (zoom 17 tiles also
// list the trees; only their bushes are used), and only while the camera is at most
// maxAltitude above the ground. Tiles farther than 1.5 × the radius are dropped.
// Each instance carries its local metres (e, n) and ground height h: the game's frame is
// x east, y up, z south, so it stands at (e, h, −n).
import * as THREE from 'three';

const EARTH_RADIUS = 6371008.8; // m, the sphere of strahler's local projection
const EQUATOR = 40075016.686; // m, Web Mercator's world width at the equator

const TREES = { name: 'tree', species: 0, zoom: 16, radius: 700, maxAltitude: 900, capacity: 40000 };
const BUSHES = { name: 'bush', species: 1, zoom: 17, radius: 260, maxAltitude: 350, capacity: 40000 };

// Sparse → dense canopy colours per species (the layer's density picks between them).
const COLOURS = {
  tree: [new THREE.Color('#7d9b4a'), new THREE.Color('#1d4d24')],
  bush: [new THREE.Color('#a7a55a'), new THREE.Color('#556f2c')],
};

/** lon/lat (degrees) of local metres (east, north): the inverse of the world's projection
 * (Lambert azimuthal equal-area on the sphere, centred on world.center). */
export function lonLatOf(e, n, [lon0, lat0]) {
  const rho = Math.hypot(e, n);
  if (rho === 0) return [lon0, lat0];
  const deg = Math.PI / 180;
  const c = 2 * Math.asin(Math.min(1, rho / (2 * EARTH_RADIUS)));
  const sinLat0 = Math.sin(lat0 * deg), cosLat0 = Math.cos(lat0 * deg);
  const phi = Math.asin(Math.max(-1, Math.min(1, Math.cos(c) * sinLat0 + (n * Math.sin(c) * cosLat0) / rho)));
  const lambda = Math.atan2(e * Math.sin(c), rho * cosLat0 * Math.cos(c) - n * sinLat0 * Math.sin(c));
  return [lon0 + lambda / deg, phi / deg];
}

/** Fractional Web Mercator tile coordinates of lon/lat at zoom z (x east, y south). */
export function tileCoordinates(lon, lat, z) {
  const s = Math.sin((lat * Math.PI) / 180);
  return [((lon + 180) / 360) * 2 ** z, (0.5 - Math.log((1 + s) / (1 - s)) / (4 * Math.PI)) * 2 ** z];
}

// Unit shapes (1 m canopy radius, 1 m tall), scaled per instance: a trunk and a cone crown, and a
// squashed icosahedron for a bush.
function treeParts() {
  const trunk = new THREE.CylinderGeometry(0.1, 0.14, 0.35, 5).translate(0, 0.175, 0);
  const crown = new THREE.ConeGeometry(1, 0.8, 7).translate(0, 0.6, 0);
  return [
    { geometry: trunk, material: new THREE.MeshLambertMaterial({ color: '#5a4030' }), tinted: false },
    { geometry: crown, material: new THREE.MeshLambertMaterial({ color: '#ffffff' }), tinted: true },
  ];
}

function bushParts() {
  const body = new THREE.IcosahedronGeometry(1, 0).scale(1, 0.6, 1).translate(0, 0.45, 0);
  return [{ geometry: body, material: new THREE.MeshLambertMaterial({ color: '#ffffff' }), tinted: true }];
}

// The density layer tile as a sampler of 0..1 at tile coordinates (x, y in [0, 1)), or null.
async function loadDensity(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`GET ${url}: HTTP ${response.status}`);
  const bitmap = await createImageBitmap(await response.blob());
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d', { willReadFrequently: true });
  context.drawImage(bitmap, 0, 0);
  const { data, width, height } = context.getImageData(0, 0, bitmap.width, bitmap.height);
  return (x, y) => {
    const px = Math.min(width - 1, Math.max(0, Math.floor(x * width)));
    const py = Math.min(height - 1, Math.max(0, Math.floor(y * height)));
    return data[4 * (py * width + px)] / 255;
  };
}

export class VegetationLayer {
  /**
   * @param world   the world's metadata from GET /worlds (id, center)
   * @param url     (path) => absolute URL of a resource of the world
   * @param options maxInFlight: concurrent tile requests
   */
  constructor(world, url, { maxInFlight = 4 } = {}) {
    Object.assign(this, { world, url, maxInFlight });
    this.group = new THREE.Group(); // add this to the scene
    this.tiles = new Map(); // "species/z/x/y" -> { state, instances, lastNeeded }
    this.inFlight = 0;
    this.dirty = false;
    this.settled = false; // every tile the last update() wanted has loaded (or failed)
    this.stats = { requested: 0, loaded: 0, failed: 0, dropped: 0, tree: 0, bush: 0, instances: 0 };
    this.kinds = [TREES, BUSHES].map((kind) => ({ ...kind, parts: kind === TREES ? treeParts() : bushParts(), meshes: [] }));
  }

  /** Call every frame with the camera and the ground height under it (m). */
  update(camera, groundHeight) {
    const e = camera.position.x, n = -camera.position.z;
    const [lon, lat] = lonLatOf(e, n, this.world.center);
    const altitude = camera.position.y - groundHeight;
    const needed = new Set();
    const wanted = [];
    for (const kind of this.kinds) {
      if (altitude > kind.maxAltitude) continue;
      const side = (EQUATOR * Math.cos((lat * Math.PI) / 180)) / 2 ** kind.zoom;
      const [tx, ty] = tileCoordinates(lon, lat, kind.zoom);
      const reach = Math.ceil(kind.radius / side);
      for (let y = Math.floor(ty) - reach; y <= Math.floor(ty) + reach; y += 1) {
        for (let x = Math.floor(tx) - reach; x <= Math.floor(tx) + reach; x += 1) {
          const distance = Math.hypot(x + 0.5 - tx, y + 0.5 - ty) * side;
          if (distance > kind.radius + side * 0.71) continue;
          const key = `${kind.name}/${kind.zoom}/${x}/${y}`;
          needed.add(key);
          wanted.push({ key, kind, x, y, distance });
        }
      }
    }
    wanted.sort((a, b) => a.distance - b.distance);
    for (const w of wanted) {
      if (this.inFlight >= this.maxInFlight) break;
      if (!this.tiles.has(w.key)) this.request(w);
    }
    this.settled = wanted.every((w) => this.tiles.has(w.key) && this.tiles.get(w.key).state !== 'loading');
    // Drop what is far behind (hysteresis: the tiles still wanted stay).
    for (const [key, tile] of this.tiles) {
      if (needed.has(key)) tile.lastNeeded = performance.now();
      else if (tile.state !== 'loading' && performance.now() - tile.lastNeeded > 3000) {
        this.tiles.delete(key);
        this.stats.dropped += 1;
        this.dirty = true;
      }
    }
    if (this.dirty) this.rebuild();
  }

  async request({ key, kind, x, y }) {
    const tile = { state: 'loading', instances: [], lastNeeded: performance.now() };
    this.tiles.set(key, tile);
    this.inFlight += 1;
    this.stats.requested += 1;
    try {
      const path = `${kind.zoom}/${x}/${y}`;
      const [json, density] = await Promise.all([
        fetch(this.url(`vegetation/${path}.json`)).then((r) => {
          if (!r.ok) throw new Error(`vegetation ${path}: HTTP ${r.status}`);
          return r.json();
        }),
        loadDensity(this.url(`layers/vegetation/${path}.png?species=${kind.name}`)),
      ]);
      tile.instances = json.instances
        .filter((i) => i.species === kind.species)
        .map((i) => ({ ...i, density: density(i.x, i.y) }));
      tile.state = 'loaded';
      this.stats.loaded += 1;
    } catch (error) {
      tile.state = 'failed';
      this.stats.failed += 1;
      console.warn(error.message);
    } finally {
      this.inFlight -= 1;
      this.dirty = true;
    }
  }

  // Refills the instanced meshes from the loaded tiles.
  rebuild() {
    this.dirty = false;
    const matrix = new THREE.Matrix4();
    const rotation = new THREE.Quaternion();
    const up = new THREE.Vector3(0, 1, 0);
    const colour = new THREE.Color();
    let total = 0;
    for (const kind of this.kinds) {
      const instances = [];
      for (const [key, tile] of this.tiles) if (key.startsWith(`${kind.name}/`)) instances.push(...tile.instances);
      const count = Math.min(instances.length, kind.capacity);
      if (kind.meshes.length === 0) {
        kind.meshes = kind.parts.map((part) => {
          const mesh = new THREE.InstancedMesh(part.geometry, part.material, kind.capacity);
          mesh.frustumCulled = false; // the instances span many tiles; the bounds would be stale
          mesh.name = `${kind.name}s`;
          this.group.add(mesh);
          return mesh;
        });
      }
      for (let k = 0; k < count; k += 1) {
        const i = instances[k];
        // Trees: crown radius = canopy radius, height 3 m + 2.2 × radius; bushes 1.2 × radius.
        const height = (kind === TREES ? 3 + 2.2 * i.radius : 1.2 * i.radius) * i.scale;
        matrix.compose(new THREE.Vector3(i.e, i.h, -i.n), rotation.setFromAxisAngle(up, i.rotation),
          new THREE.Vector3(i.radius, height, i.radius));
        const [sparse, dense] = COLOURS[kind.name];
        colour.copy(sparse).lerp(dense, Math.min(1, i.density * 1.5));
        kind.parts.forEach((part, p) => {
          kind.meshes[p].setMatrixAt(k, matrix);
          if (part.tinted) kind.meshes[p].setColorAt(k, colour);
        });
      }
      for (const mesh of kind.meshes) {
        mesh.count = count;
        mesh.instanceMatrix.needsUpdate = true;
        if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
      }
      this.stats[kind.name] = count;
      total += count;
    }
    this.stats.instances = total;
  }
}
