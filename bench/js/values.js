// Values and interpolation: 1M linear (and natural neighbour) queries on a 1M-vertex
// triangulation against delaunator's time to triangulate 1M points, and a 4096 x 4096 raster
// of a 1M-triangle surface. Alternating rounds in one process, medians.
//   node --expose-gc bench/js/values.js [--rounds N] [--quick]
import { init, Triangulation } from '../../web/index.node.js';
import { alternate } from './timing.js';
import { uniformLehmer } from './datasets.js';
import * as peers from './peers.js';

const option = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? Number(process.argv[i + 1]) : fallback;
};
const quick = process.argv.includes('--quick');
const rounds = option('--rounds', quick ? 3 : 5);
const size = quick ? 100_000 : 1_000_000;
const n = (x) => x.toLocaleString('en-US');
const ms = (x) => (x < 10 ? x.toFixed(2) : x.toFixed(0));

await init();

function surface(points) {
  const xy = uniformLehmer(points);
  const values = new Float64Array(points);
  for (let i = 0; i < points; i++) values[i] = Math.sin(xy[2 * i] / 50) * xy[2 * i + 1];
  const t = new Triangulation();
  t.insertPoints(xy, values);
  return { t, xy };
}

function table(results, reference) {
  const base = results[reference].ms;
  console.log('| call | ms (median) | vs ' + reference + ' |');
  console.log('| --- | --- | --- |');
  for (const [name, r] of Object.entries(results)) {
    const cell = r.error ? `FAILED: ${r.error}` : ms(r.ms);
    console.log(`| ${name} | ${cell} | ${r.error ? '' : `${(r.ms / base).toFixed(2)}×`} |`);
  }
  console.log();
}

// Queries: 1M uniform points over the same square (in random order: every query walks from
// the grid cell's last triangle), and the same sorted into rows (a scan: walks of a step).
{
  const { t, xy } = surface(size);
  const random = uniformLehmer(size, 777);
  const rows = new Float64Array(2 * size);
  const side = Math.round(Math.sqrt(size));
  for (let i = 0; i < size; i++) {
    rows[2 * i] = ((i % side) + 0.5) * (1000 / side);
    rows[2 * i + 1] = (Math.floor(i / side) + 0.5) * (1000 / side);
  }
  console.log(`## ${n(size)} queries on ${n(t.vertexCount)} vertices (${rounds} rounds)\n`);
  const contenders = [
    { name: `delaunator, ${n(size)} points`, run: () => peers.delaunator(xy), describe: () => '' },
    {
      name: 'interpolate linear, random order',
      run: () => t.interpolate(random),
      describe: () => '',
    },
    { name: 'interpolate linear, rows', run: () => t.interpolate(rows), describe: () => '' },
    {
      name: 'interpolate natural, random order',
      run: () => t.interpolate(random, { method: 'natural' }),
      describe: () => '',
    },
  ];
  table(await alternate(contenders, rounds), `delaunator, ${n(size)} points`);
  const { walkSteps, locates } = t.stats;
  console.log(`${(walkSteps / locates).toFixed(2)} walk steps per location overall\n`);
  t.dispose();
}

// A raster of a surface of about 1M triangles (500k points); delaunator on 1M points runs in
// alternation as the yardstick of how loaded the machine is.
{
  const { t } = surface(size / 2);
  const side = quick ? 1024 : 4096;
  console.log(`## ${side} x ${side} raster of ${n(t.triangleCount)} triangles\n`);
  const spec = { bbox: [0, 0, 1000, 1000], width: side, height: side };
  const xy = uniformLehmer(size);
  const reference = `delaunator, ${n(size)} points`;
  const contenders = [
    { name: reference, run: () => peers.delaunator(xy), describe: () => '' },
    { name: 'rasterize linear', run: () => t.rasterize(spec), describe: () => '' },
  ];
  table(await alternate(contenders, rounds), reference);
  t.dispose();
}
