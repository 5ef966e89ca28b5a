// The wasm targets of the speed work, warm, in one process: geocdt against delaunator on the
// same points (geocdt with the constraints, delaunator without), alternating, medians; and the
// share of each geocdt call spent outside the core (stats.milliseconds vs coreMilliseconds).
//   node --expose-gc bench/js/targets.js [--data DIR] [--quick]
// DIR holds gshhg_region.gpl, gshhg_asia.gpl and gshhg_east.gpl (scripts/datasets/all.sh makes
// them); --quick runs 1M uniform points only. With gshhg_east.gpl, it also compares the time
// per point of the eastern hemisphere's GSHHG (7.3M points) with the 2M-point region's.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import Delaunator from 'delaunator';
import { init, triangulate } from 'geocdt';
import { median, threadCpuClock } from './timing.js';
import { countryRings, flatPolylines, readGpl, uniformLehmer } from './datasets.js';

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
const points1m = uniformLehmer(1_000_000);
rows.push({ name: 'uniform', input: { points: points1m }, points: points1m, target: '≤ 0.35×',
  rounds: 7 });
if (!quick) {
  const points4m = uniformLehmer(4_000_000);
  rows.push({ name: 'uniform', input: { points: points4m }, points: points4m, target: '',
    rounds: 3 });
  const rings = flatPolylines(countryRings('10m').polylines);
  rows.push({ name: 'Natural Earth 10m country rings', input: { polylines: rings },
    points: rings.coords, target: '≤ 0.7×', rounds: 5 });
  // Europe (4,268 crossings) and South and East Asia (14,896: the target's 10,000 or more).
  const regions = [['gshhg_region.gpl', 'GSHHG Europe'], ['gshhg_asia.gpl', 'GSHHG Asia']];
  for (const [file, name] of regions) {
    const gpl = data && join(data, file);
    if (!gpl || !existsSync(gpl)) continue;
    const region = readGpl(gpl);
    rows.push({ name, input: { polylines: region }, points: region.coords, target: '≤ 0.7×',
      rounds: 3 });
  }
}
console.log('## geocdt (constrained where there are polylines) vs delaunator (the same points, '
  + `unconstrained), warm, alternating, medians; ${new Date().toISOString().slice(0, 10)}\n`);
measure(rows);
if (!quick && !(data && existsSync(join(data, 'gshhg_region.gpl')))) {
  console.log('(GSHHG regions skipped: pass --data DIR with the .gpl files in it.)');
}

// Time per point as the constrained input grows: one call on the eastern hemisphere's
// GSHHG against one on the 2M-point region, alternating (target: within 1.2×).
const large = data && join(data, 'gshhg_east.gpl');
const europe = rows.find((row) => row.name === 'GSHHG Europe');
if (europe && existsSync(large)) {
  const sets = [['GSHHG region', europe.input.polylines],
    ['GSHHG eastern hemisphere', readGpl(large)]];
  const perPoint = sets.map(() => []);
  const crossings = [];
  for (let round = 0; round < 3; round++) {
    sets.forEach(([, polylines], k) => {
      globalThis.gc?.();
      const started = performance.now();
      const { stats } = triangulate({ polylines });
      perPoint[k].push((performance.now() - started) * 1e6 / (polylines.coords.length / 2));
      crossings[k] = stats.crossings;
    });
  }
  console.log('| input | points | polylines | crossings | ns per point | per point vs the region '
    + '| target |');
  console.log('| --- | --: | --: | --: | --: | --: | --: |');
  sets.forEach(([name, polylines], k) => {
    const ratio = median(perPoint[k]) / median(perPoint[0]);
    console.log(`| ${name} | ${n(polylines.coords.length / 2)} | `
      + `${n(polylines.offsets.length - 1)} | ${n(crossings[k])} | `
      + `${median(perPoint[k]).toFixed(0)} | ${ratio.toFixed(2)}× | ${k ? '≤ 1.2×' : ''} |`);
  });
  console.log('\nIn one process the region\'s output arrays, most under 32 MB, may reuse memory an '
    + 'earlier call freed; bench/js/one-call.js times one call per fresh process.');
  console.log();
}
