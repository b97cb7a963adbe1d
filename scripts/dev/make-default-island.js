// One-off generator of core/input/data/default_island.geojson (node scripts/dev/make-default-island.js).
let seed = 12345;
const rnd = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
const harm = [];
for (let k = 2; k <= 40; k++) harm.push({k, a: (rnd() * 2 - 1) * 0.30 / Math.pow(k, 0.95), ph: rnd() * 2 * Math.PI});
const lon0 = -27.35, lat0 = 43.72, m = 111195;
function ring(n, r0, sx, sy, cx, cy, h, ccw) {
  const pts = [];
  for (let i = 0; i < n; i++) {
    const t = 2 * Math.PI * i / n;
    let r = 1;
    for (const {k, a, ph} of h) r += a * Math.cos(k * t + ph);
    // a deep bay on the south-east and a peninsula to the west
    r -= 0.45 * Math.exp(-Math.pow((t - 5.2) / 0.12, 2));
    r += 0.35 * Math.exp(-Math.pow((t - 3.0) / 0.22, 2));
    const x = cx + sx * r0 * r * Math.cos(t), y = cy + sy * r0 * r * Math.sin(t);
    pts.push([x, y]);
  }
  if (!ccw) pts.reverse();
  return pts;
}
function area(r) { let a = 0; for (let i = 0; i < r.length; i++) { const [x1, y1] = r[i], [x2, y2] = r[(i + 1) % r.length]; a += x1 * y2 - x2 * y1; } return a / 2; }
const outer = ring(720, 17400, 1.45, 0.72, 0, 0, harm, true);
const lakeH = [{k: 3, a: 0.12, ph: 1}, {k: 5, a: 0.06, ph: 2}];
const lake = ring(48, 1100, 1.3, 0.8, 6500, 3500, [], false).map(([x, y], i) => [x, y]);
console.log('area km2', area(outer) / 1e6, 'lake', area(lake) / 1e6);
const toLL = ([x, y]) => [+(lon0 + x / (m * Math.cos(lat0 * Math.PI / 180))).toFixed(6), +(lat0 + y / m).toFixed(6)];
const close = r => { const c = r.map(toLL); c.push(c[0]); return c; };
const gj = {type: 'FeatureCollection', features: [{type: 'Feature', properties: {name: 'Strahler Island', note: 'fictitious default island of strahler'}, geometry: {type: 'Polygon', coordinates: [close(outer), close(lake)]}}]};
require('fs').writeFileSync('core/input/data/default_island.geojson', JSON.stringify(gj));
