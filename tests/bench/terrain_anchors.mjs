// Anchors of terrainlod's simplify (docs/terrainlod.md §6): Martini (RTIN) and Delatin
// (greedy Delaunay insertion) on the same height grid, one JSON line per case.
//
//   node terrain_anchors.mjs GRID.asc ERROR...      (needs `npm install @mapbox/martini delatin`
//                                                    in NODE_PATH or a parent node_modules)
// GRID.asc is an ESRI ASCII grid of (2^k+1)^2 samples (Martini's tile shape).
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(process.env.ANCHOR_MODULES ? process.env.ANCHOR_MODULES + '/' : import.meta.url);
const Martini = require('@mapbox/martini').default ?? require('@mapbox/martini');
const Delatin = require('delatin').default ?? require('delatin');

const [file, ...errors] = process.argv.slice(2);
const lines = readFileSync(file, 'utf8').trim().split('\n');
const header = {};
let row = 0;
while (/^[a-zA-Z]/.test(lines[row])) {
  const [k, v] = lines[row].trim().split(/\s+/);
  header[k.toLowerCase()] = Number(v);
  row++;
}
const w = header.ncols, h = header.nrows;
const data = new Float32Array(w * h);
for (let r = 0; r < h; r++) {
  const vals = lines[row + r].trim().split(/\s+/).map(Number);
  for (let c = 0; c < w; c++) data[r * w + c] = vals[c];
}
const now = () => Number(process.hrtime.bigint()) / 1e6;

let t = now();
const martini = new Martini(w);
const tile = martini.createTile(data);
const createMs = now() - t;
for (const e of errors.map(Number)) {
  t = now();
  const mesh = tile.getMesh(e);
  const ms = now() - t;
  console.log(JSON.stringify({ bench: 'terrainlod_simplify', system: 'martini', max_error: e,
    vertices: mesh.vertices.length / 2, triangles: mesh.triangles.length / 3, ms, create_tile_ms: createMs }));
}
for (const e of errors.map(Number)) {
  t = now();
  const tin = new Delatin(data, w, h);
  tin.run(e);
  const ms = now() - t;
  console.log(JSON.stringify({ bench: 'terrainlod_simplify', system: 'delatin', max_error: e,
    vertices: tin.coords.length / 2, triangles: tin.triangles.length / 3, ms }));
}
