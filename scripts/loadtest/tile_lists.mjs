// Writes <dir>/sweep.txt (the Web Mercator tiles of a viewport sweep over the default island
// at zoom 12 and 13, as a map viewer would request them) and <dir>/hot.txt (one of them).
import fs from "node:fs";

const [dir] = process.argv.slice(2);
const lon = -27.35, lat = 43.72; // the default island's centre
const paths = [];
for (const [z, radius] of [[12, 6], [13, 10]]) {
  const n = 2 ** z;
  const cx = Math.floor(((lon + 180) / 360) * n);
  const cy = Math.floor(((1 - Math.asinh(Math.tan((lat * Math.PI) / 180)) / Math.PI) / 2) * n);
  for (let dy = -radius; dy <= radius; dy++)
    for (let dx = -radius; dx <= radius; dx++) paths.push(`/worlds/default/tiles/${z}/${cx + dx}/${cy + dy}.png`);
}
fs.writeFileSync(`${dir}/sweep.txt`, paths.join("\n") + "\n");
fs.writeFileSync(`${dir}/hot.txt`, paths[Math.floor(paths.length / 2)] + "\n");
