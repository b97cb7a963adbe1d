// Game-client demo: streams a world's LocalQuad Draco mesh tiles around a free-flying camera,
// with instanced trees and bushes near it (vegetation.js).
// Tests read window.strahlerGame (tile counters, frames drawn, the camera, vegetation.stats,
// groundAt(x, z)).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import { loadWorlds, tileUrl } from './api.js';
import { FlyControls } from './fly-controls.js';
import { createTerrainMaterial } from './terrain-material.js';
import { TileStreamer } from './tile-streamer.js';
import { VegetationLayer } from './vegetation.js';

const GRID_SIZE = 64; // quads per tile side, the server's default ?size=
const SKY = new THREE.Color('#a9c8e6');

function createLoader(world, terrain) {
  const draco = new DRACOLoader().setDecoderPath(new URL('../vendor/three/draco/', import.meta.url).href);
  const gltf = new GLTFLoader().setDRACOLoader(draco);
  return async (z, x, y) => {
    const { scene } = await gltf.loadAsync(tileUrl(world, `local/${z}/${x}/${y}.glb?size=${GRID_SIZE}`));
    scene.traverse((object) => {
      if (!object.isMesh) return;
      object.material.dispose(); // the tile's own default material; all tiles share ours
      object.material = terrain.material;
      if (!object.geometry.attributes.normal) object.geometry.computeVertexNormals();
    });
    return scene;
  };
}

function createScene(world) {
  const { rootSide } = world.local;
  const [west, south] = world.local.rootSouthWest;
  const centre = new THREE.Vector3(west + rootSide / 2, 0, -(south + rootSide / 2));

  const scene = new THREE.Scene();
  scene.background = SKY;
  scene.fog = new THREE.Fog(SKY, rootSide * 0.6, rootSide * 2.5); // hides the far LOD edge
  scene.add(new THREE.HemisphereLight('#dfefff', '#5b4a36', 1.2));
  const sun = new THREE.DirectionalLight('#fff4e0', 2.5);
  sun.position.set(-0.6, 0.7, -0.4); // from the north-west, as cartographers light relief
  scene.add(sun);

  // Sea level: a plane over the offshore shelf, wide enough for its edge to be in the fog.
  const sea = new THREE.Mesh(new THREE.PlaneGeometry(rootSide * 8, rootSide * 8),
    new THREE.MeshStandardMaterial({ color: '#2f6f9f', roughness: 0.6 }));
  sea.rotation.x = -Math.PI / 2;
  sea.position.copy(centre);
  scene.add(sea);

  // Start south of the centre, a few kilometres up, looking north across the island.
  const camera = new THREE.PerspectiveCamera(60, 1, 2, rootSide * 4);
  camera.position.set(centre.x, rootSide * 0.07, centre.z + rootSide * 0.3);
  camera.lookAt(centre.x, 0, centre.z - rootSide * 0.05);
  return { scene, camera };
}

async function main() {
  const { selected: world } = await loadWorlds();
  const canvas = document.getElementById('scene');
  // preserveDrawingBuffer keeps the last frame readable for screenshots; the logarithmic depth
  // buffer resolves near mountains and the far coast alike with one near/far range.
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, logarithmicDepthBuffer: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(devicePixelRatio, 2));
  const { scene, camera } = createScene(world);
  const terrain = createTerrainMaterial();
  const streamer = new TileStreamer(world, createLoader(world, terrain), { gridSize: GRID_SIZE });
  scene.add(streamer.group);
  const controls = new FlyControls(camera, canvas);
  const vegetation = new VegetationLayer(world, (path) => tileUrl(world, path));
  scene.add(vegetation.group);

  // The height of the loaded terrain under (x, z), or null where no tile is loaded yet.
  const raycaster = new THREE.Raycaster();
  const down = new THREE.Vector3(0, -1, 0);
  const groundAt = (x, z) => {
    raycaster.set(new THREE.Vector3(x, 1e5, z), down);
    const hit = raycaster.intersectObject(streamer.group, true)[0];
    return hit ? hit.point.y : null;
  };

  const game = { world, camera, streamer, stats: streamer.stats, vegetation, groundAt, frames: 0 };
  window.strahlerGame = game;

  const resize = () => {
    renderer.setSize(innerWidth, innerHeight, false);
    camera.aspect = innerWidth / innerHeight;
    camera.updateProjectionMatrix();
  };
  addEventListener('resize', resize);
  resize();

  const statsText = document.getElementById('stats');
  let last = performance.now();
  let heightRampSet = false;
  let ground = 0; // the terrain under the camera, sampled every few frames
  renderer.setAnimationLoop((now) => {
    const seconds = Math.min(0.1, (now - last) / 1000);
    last = now;
    controls.update(seconds);
    streamer.update(camera, renderer.domElement.height);
    if (game.frames % 10 === 0) ground = groundAt(camera.position.x, camera.position.z) ?? ground;
    vegetation.update(camera, ground);
    // The roots' height range sets the colour ramp, so snow sits on this world's summits.
    if (!heightRampSet && streamer.stats.inFlight === 0 && streamer.stats.loaded > 0) {
      terrain.setMaxHeight(streamer.rootMaxHeight());
      heightRampSet = true;
    }
    renderer.render(scene, camera);
    game.frames += 1;
    if (game.frames % 15 === 0) {
      const s = streamer.stats;
      statsText.textContent = `${world.name ?? world.id}\n` +
        `tiles visible ${s.visible} (deepest z${s.maxVisibleZoom}) · cached ${s.cached}\n` +
        `loaded ${s.loaded} · in flight ${s.inFlight} · evicted ${s.evicted} · failed ${s.failed}\n` +
        `trees ${vegetation.stats.tree} · bushes ${vegetation.stats.bush}\n` +
        `altitude ${camera.position.y.toFixed(0)} m · ${(1 / Math.max(seconds, 1e-3)).toFixed(0)} fps`;
    }
  });
}

main().catch((error) => {
  document.getElementById('stats').textContent = `Cannot start: ${error.message}`;
  console.error(error);
});
