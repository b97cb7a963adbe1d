// Free-flight camera: drag to look, WASD or arrows to move, R/F up and down, Shift faster.
// No pointer lock, so it also works in an iframe or under test automation.
const KEYS = {
  forward: ['KeyW', 'ArrowUp'], back: ['KeyS', 'ArrowDown'], left: ['KeyA', 'ArrowLeft'],
  right: ['KeyD', 'ArrowRight'], up: ['KeyR', 'PageUp'], down: ['KeyF', 'PageDown'],
};
const LOOK_SPEED = 0.004; // radians per pixel dragged

export class FlyControls {
  constructor(camera, element) {
    this.camera = camera;
    camera.rotation.order = 'YXZ'; // yaw, then pitch: no roll creeps in
    this.pressed = new Set();
    addEventListener('keydown', (e) => this.pressed.add(e.code));
    addEventListener('keyup', (e) => this.pressed.delete(e.code));
    addEventListener('blur', () => this.pressed.clear());
    element.addEventListener('pointerdown', (e) => element.setPointerCapture(e.pointerId));
    element.addEventListener('pointermove', (e) => {
      if (!element.hasPointerCapture(e.pointerId)) return;
      camera.rotation.y -= e.movementX * LOOK_SPEED;
      camera.rotation.x = Math.max(-1.5, Math.min(1.5, camera.rotation.x - e.movementY * LOOK_SPEED));
    });
  }

  held(action) { return KEYS[action].some((code) => this.pressed.has(code)); }

  update(seconds) {
    const axis = (plus, minus) => (this.held(plus) ? 1 : 0) - (this.held(minus) ? 1 : 0);
    const forward = axis('forward', 'back'), right = axis('right', 'left'), up = axis('up', 'down');
    if (!forward && !right && !up) return;
    const camera = this.camera;
    // Speed grows with altitude: crossing the island from high up, creeping along valleys below.
    const speed = Math.max(40, Math.abs(camera.position.y) * 0.8) * (this.pressed.has('ShiftLeft') || this.pressed.has('ShiftRight') ? 4 : 1);
    camera.translateZ(-forward * speed * seconds);
    camera.translateX(right * speed * seconds);
    camera.position.y = Math.max(5, camera.position.y + up * speed * seconds);
  }
}
