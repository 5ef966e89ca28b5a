// The wasm targets of the speed work, warm, in one process: geocdt against delaunator on the
// same points (geocdt with the constraints, delaunator without), alternating, medians; and the
// share of each geocdt call spent outside the core (stats.milliseconds vs coreMilliseconds).
//   node --expose-gc bench/js/targets.js [--data DIR] [--quick]
// DIR holds gshhg_region.gpl (scripts/datasets/gshhg_region.sh makes it); --quick runs 1M
// uniform points only.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import Delaunator from 'delaunator';
import { init, triangulate } from 'geocdt';
import { median, threadCpuClock } from './timing.js';
import { countryRings, flatPolylines, readGpl, uniform } from './datasets.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const quick = process.argv.includes('--quick');
const data = option('--data', null);
const n = (x) => x.toLocaleString('en-US');

// Runs geocdt and delaunator in alternation on a row; medians of wall and main-thread CPU ms.
function alternateRow(row, cpuClock) {
  const runs = { geocdt: { wall: [], cpu: [] }, delaunator: { wall: [], cpu: [] } };
  const outside = [];
  const contenders = [
    ['geocdt', () => {
      const { stats } = triangulate(row.input);
      outside.push(1 - stats.coreMilliseconds / stats.milliseconds);
    }],
    ['delaunator', () => new Delaunator(row.points)],
  ];
  for (let round = 0; round < row.rounds; round++) {
    for (let k = 0; k < 2; k++) {
      const [name, run] = contenders[(k + round) % 2];
      globalThis.gc?.();
      const started = performance.now();
      const cpuStarted = cpuClock?.();
      run();
      if (cpuClock) runs[name].cpu.push(cpuClock() - cpuStarted);
      runs[name].wall.push(performance.now() - started);
    }
  }
  return { runs, outside: median(outside) };
}

// rows: [{ name, input, points (the coordinates delaunator gets), target, rounds }]
function measure(rows) {
  const cpuClock = threadCpuClock();
  const cpu = cpuClock !== undefined;
  console.log('| input | points | geocdt ms | delaunator ms | geocdt / delaunator | '
    + `${cpu ? 'main-thread CPU ratio | ' : ''}target | outside the core |`);
  console.log(`| --- | --: | --: | --: | --: | ${cpu ? '--: | ' : ''}--: | --: |`);
  for (const row of rows) {
    const { runs, outside } = alternateRow(row, cpuClock);
    const g = median(runs.geocdt.wall), d = median(runs.delaunator.wall);
    const cpuRatio = cpu ? `${(median(runs.geocdt.cpu) / median(runs.delaunator.cpu))
      .toFixed(2)}× | ` : '';
    console.log(`| ${row.name} | ${n(row.points.length / 2)} | ${g.toFixed(0)} | `
      + `${d.toFixed(0)} | ${(g / d).toFixed(2)}× | ${cpuRatio}${row.target} | `
      + `${(100 * outside).toFixed(1)}% |`);
  }
  console.log();
}

await init();
const rows = [];
const points1m = uniform(1_000_000);
rows.push({ name: 'uniform', input: { points: points1m }, points: points1m, target: '≤ 0.35×',
  rounds: 7 });
if (!quick) {
  const points4m = uniform(4_000_000);
  rows.push({ name: 'uniform', input: { points: points4m }, points: points4m, target: '',
    rounds: 3 });
  const rings = flatPolylines(countryRings('10m').polylines);
  rows.push({ name: 'Natural Earth 10m country rings', input: { polylines: rings },
    points: rings.coords, target: '≤ 0.7×', rounds: 5 });
  const gpl = data && join(data, 'gshhg_region.gpl');
  if (gpl && existsSync(gpl)) {
    const region = readGpl(gpl);
    rows.push({ name: 'GSHHG region', input: { polylines: region }, points: region.coords,
      target: '≤ 0.7×', rounds: 3 });
  }
}
console.log('## geocdt (constrained where there are polylines) vs delaunator (the same points, '
  + `unconstrained), warm, alternating, medians; ${new Date().toISOString().slice(0, 10)}\n`);
measure(rows);
if (!quick && !(data && existsSync(join(data, 'gshhg_region.gpl')))) {
  console.log('(GSHHG region skipped: pass --data DIR with gshhg_region.gpl in it.)');
}
