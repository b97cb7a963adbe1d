// Quadtree level of detail for strahler's LocalQuad mesh tiles: the reference for game clients.
//
// Tile (z, x, y) of a world covers a square of side rootSide / 2^z metres; x counts eastwards,
// y counts southwards from the north edge of the root square. Each .glb holds one mesh whose
// glTF node is already translated to the tile's south-west corner, in a frame where x is east,
// y is up and z is south: adding the glTF scene as it is puts every tile in place.
//
// Each frame, update(camera):
//  1. walks the quadtree from the roots (every tile of level local.minzoom, usually just 0/0/0),
//     skipping tiles outside the view frustum;
//  2. refines a tile into its four children while its screen-space error is too large, but only
//     once all four children are loaded, so there is never a hole (the parent is drawn meanwhile);
//  3. queues the missing tiles, coarsest and nearest first, a few requests at a time;
//  4. evicts the least recently used tiles that this frame did not need, above a budget.
// Neighbouring tiles of different levels leave T-junction cracks; the meshes' skirts hide them.
import * as THREE from 'three';

export class TileStreamer {
  /**
   * @param world   the world's metadata from GET /worlds (local.{minzoom, maxzoom, rootSouthWest, rootSide})
   * @param load    async (z, x, y) => THREE.Object3D, the tile's glTF scene
   * @param options gridSize: quads per tile side (the ?size= of the requests);
   *                maxPixelError: refine while a tile's error exceeds this many pixels;
   *                maxInFlight: concurrent requests; maxCached: tiles kept in memory
   */
  constructor(world, load, { gridSize = 64, maxPixelError = 6, maxInFlight = 6, maxCached = 256 } = {}) {
    Object.assign(this, { load, gridSize, maxPixelError, maxInFlight, maxCached });
    this.minZoom = world.local.minzoom ?? 0;
    this.maxZoom = world.local.maxzoom;
    this.rootSide = world.local.rootSide;
    [this.rootWest, this.rootSouth] = world.local.rootSouthWest;
    this.group = new THREE.Group(); // add this to the scene
    this.nodes = new Map(); // "z/x/y" -> node; a node exists once needed, its object once loaded
    this.frame = 0;
    this.stats = { loaded: 0, cached: 0, visible: 0, inFlight: 0, evicted: 0, failed: 0, maxVisibleZoom: -1 };
    this.frustum = new THREE.Frustum();
    this.matrix = new THREE.Matrix4();
  }

  node(z, x, y, parent) {
    const key = `${z}/${x}/${y}`;
    let node = this.nodes.get(key);
    if (!node) {
      const side = this.rootSide / 2 ** z;
      const west = this.rootWest + x * side;
      const south = this.rootSouth + this.rootSide - (y + 1) * side; // y counts from the north edge
      // Heights are unknown until the tile loads: borrow the parent's range (roots guess).
      const [low, high] = parent ? [parent.box.min.y, parent.box.max.y] : [-500, 3000];
      node = {
        key, z, x, y, side, state: 'empty', object: null, lastUsed: 0, retryAt: 0,
        box: new THREE.Box3(new THREE.Vector3(west, low, -(south + side)), new THREE.Vector3(west + side, high, -south)),
      };
      this.nodes.set(key, node);
    }
    return node;
  }

  children(node) {
    const { z, x, y } = node;
    return [0, 1, 2, 3].map((i) => this.node(z + 1, 2 * x + (i & 1), 2 * y + (i >> 1), node));
  }

  // Screen-space error: the tile's geometric error (its sample spacing, the smallest detail it
  // can show) projected to pixels at the tile's distance from the camera.
  screenSpaceError(node, camera, pixelsPerRadian) {
    const distance = Math.max(1, node.box.distanceToPoint(camera.position));
    return (node.side / this.gridSize) * pixelsPerRadian / distance;
  }

  update(camera, viewportHeight) {
    this.frame += 1;
    camera.updateMatrixWorld();
    this.frustum.setFromProjectionMatrix(this.matrix.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse));
    const pixelsPerRadian = viewportHeight / (2 * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2));
    const visible = new Set();
    const wanted = [];

    const visit = (node) => {
      if (!this.frustum.intersectsBox(node.box)) return;
      node.lastUsed = this.frame;
      if (node.state !== 'ready') {
        wanted.push(node);
        return;
      }
      if (node.z < this.maxZoom && this.screenSpaceError(node, camera, pixelsPerRadian) > this.maxPixelError) {
        const kids = this.children(node);
        for (const kid of kids) kid.lastUsed = this.frame;
        if (kids.every((k) => k.state === 'ready')) return kids.forEach(visit);
        // All four children are loaded, even those off screen: simpler than partial refinement.
        wanted.push(...kids.filter((k) => k.state !== 'ready'));
      }
      visible.add(node);
    };
    const rootsPerSide = 2 ** this.minZoom;
    for (let y = 0; y < rootsPerSide; y++) for (let x = 0; x < rootsPerSide; x++) visit(this.node(this.minZoom, x, y));

    for (const node of this.nodes.values()) if (node.object) node.object.visible = visible.has(node);
    this.requestTiles(wanted, camera);
    this.evict();
    this.stats.visible = visible.size;
    this.stats.maxVisibleZoom = Math.max(-1, ...[...visible].map((n) => n.z));
  }

  /** The highest point of the loaded roots, in metres (-Infinity before any loads). */
  rootMaxHeight() {
    const roots = [...this.nodes.values()].filter((n) => n.z === this.minZoom && n.object);
    return Math.max(...roots.map((n) => n.box.max.y));
  }

  requestTiles(wanted, camera) {
    const now = performance.now();
    const queue = wanted.filter((n) => n.state === 'empty' && n.retryAt <= now);
    queue.sort((a, b) => a.z - b.z || a.box.distanceToPoint(camera.position) - b.box.distanceToPoint(camera.position));
    for (const node of queue.slice(0, this.maxInFlight - this.stats.inFlight)) this.fetch(node);
  }

  async fetch(node) {
    node.state = 'loading';
    this.stats.inFlight += 1;
    try {
      const object = await this.load(node.z, node.x, node.y);
      const bounds = new THREE.Box3().setFromObject(object);
      node.box.min.y = bounds.min.y; // the real height range: tighter culling and distances
      node.box.max.y = bounds.max.y;
      object.visible = false; // shown by the next update() if selected
      this.group.add(object);
      Object.assign(node, { object, state: 'ready' });
      this.stats.loaded += 1;
      this.stats.cached += 1;
    } catch (error) {
      // A failed tile is retried later; meanwhile its parent stays on screen.
      console.warn(`tile ${node.key}: ${error.message}`);
      Object.assign(node, { state: 'empty', retryAt: performance.now() + 2000 });
      this.stats.failed += 1;
    } finally {
      this.stats.inFlight -= 1;
    }
  }

  // Least recently used first; never a root, nor a tile used this frame (drawn, or an ancestor of one).
  // Unused placeholders of tiles never loaded are dropped too, so a long flight does not
  // accumulate nodes; they are recreated when needed again.
  evict() {
    const unused = [...this.nodes.values()].filter((n) => n.lastUsed < this.frame && n.z > this.minZoom);
    for (const node of unused) if (node.state === 'empty') this.nodes.delete(node.key);
    if (this.stats.cached <= this.maxCached) return;
    const stale = unused.filter((n) => n.state === 'ready').sort((a, b) => a.lastUsed - b.lastUsed);
    for (const node of stale.slice(0, this.stats.cached - this.maxCached)) {
      this.group.remove(node.object);
      node.object.traverse((o) => o.geometry?.dispose());
      this.nodes.delete(node.key);
      this.stats.cached -= 1;
      this.stats.evicted += 1;
    }
  }
}
