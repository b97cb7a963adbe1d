// Frames a box of the ground in the map's pitched view. MapLibre's fitBounds fits the box as
// seen from straight above and keeps the pitch: under 50° the near edge then spreads past the
// padding (off the canvas, under the panel). Here the camera is corrected on the projected box.

const STEPS = 10;        // the corrections converge in 3 to 5 steps
const CLOSE_PX = 0.5;    // done when the box's size and centre are this near their targets

/**
 * Moves `map` (no animation, its pitch and bearing kept) so that the box `bounds` =
 * [west, south, east, north] (degrees, at sea level) fills the canvas less `padding` (px, per
 * side) in one direction and is centred in it in both.
 */
export function frameBounds(map, bounds, padding) {
  const [west, south, east, north] = bounds;
  const corners = [[west, south], [east, south], [east, north], [west, north]];
  const { clientWidth: width, clientHeight: height } = map.getContainer();
  const target = { left: padding.left, right: width - padding.right, top: padding.top, bottom: height - padding.bottom };
  const flat = map.cameraForBounds(bounds, { padding });
  if (!flat) return; // the padding leaves no room (a very small window): MapLibre has warned
  map.jumpTo(flat);
  for (let step = 0; step < STEPS; step += 1) {
    // The box's edges are straight lines on the ground, hence on screen: its corners bound it.
    const points = corners.map((c) => map.project(c));
    const xs = points.map((p) => p.x), ys = points.map((p) => p.y);
    const box = { left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) };
    const scale = Math.min((target.right - target.left) / (box.right - box.left),
      (target.bottom - target.top) / (box.bottom - box.top));
    const middle = (b) => [(b.left + b.right) / 2, (b.top + b.bottom) / 2];
    const [[bx, by], [tx, ty]] = [middle(box), middle(target)];
    if (Math.abs(scale - 1) * Math.max(width, height) < CLOSE_PX && Math.hypot(bx - tx, by - ty) < CLOSE_PX) return;
    // Move the ground under the box's screen centre to the target's centre, then zoom by the
    // misfit; the perspective makes both approximate, hence the steps.
    const [from, to] = [map.unproject([bx, by]), map.unproject([tx, ty])];
    const centre = map.getCenter();
    map.jumpTo({ center: [centre.lng + from.lng - to.lng, centre.lat + from.lat - to.lat], zoom: map.getZoom() + Math.log2(scale) });
  }
}
