// One call in a fresh process, as a script or the CLI makes it: each run starts a new Node
// process, which calls init(), waits (a script reads its data meanwhile; the warm-up worker
// compiles the code), then makes a single triangulate() call. Reports, over the runs, the
// median time per input point and the share of the call spent outside the core
// (stats.milliseconds vs stats.coreMilliseconds), and the time per point of the eastern
// hemisphere's GSHHG against the 2M-point region's, run by run.
//   node bench/js/one-call.js [--data DIR] [--runs N] [--delay MS]
// DIR holds gshhg_region.gpl and gshhg_east.gpl (scripts/datasets/all.sh makes them); without
// them only 1M uniform points run. Unlike targets.js, no call here finds memory that an
// earlier call freed: every output array and the wasm heap are fresh pages.
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { median } from './timing.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const runs = Number(option('--runs', 5));
const delayMs = Number(option('--delay', 1000));
const data = option('--data', null);

async function child(dataset, path) {
  const { readGpl, uniformLehmer } = await import('./datasets.js');
  const { init, triangulate } = await import('geocdt');
  const input = dataset === 'uniform' ? { points: uniformLehmer(1_000_000) }
    : { polylines: readGpl(path) };
  const points = (input.points ?? input.polylines.coords).length / 2;
  await init();
  await new Promise((done) => setTimeout(done, delayMs));
  const { stats } = triangulate(input);
  console.log(JSON.stringify({
    nsPerPoint: (stats.milliseconds * 1e6) / points,
    outside: 1 - stats.coreMilliseconds / stats.milliseconds,
    points, crossings: stats.crossings,
  }));
}

function inFreshProcess(dataset, path) {
  const args = [new URL(import.meta.url).pathname, '--child', dataset, path ?? '-',
    '--delay', String(delayMs)];
  return JSON.parse(execFileSync(process.execPath, args, { encoding: 'utf8' }));
}

function main() {
  const rows = [['1M uniform points', 'uniform', null]];
  const region = data && join(data, 'gshhg_region.gpl');
  const east = data && join(data, 'gshhg_east.gpl');
  const scale = region && existsSync(region) && existsSync(east);
  if (scale) {
    rows.push(['GSHHG region (Europe)', 'gpl', region],
      ['GSHHG eastern hemisphere', 'gpl', east]);
  }
  const results = rows.map(() => []);
  for (let run = 0; run < runs; run++) {
    // Each run in another order, so that a slow phase of the machine falls on every row.
    rows.forEach((_, k) => {
      const i = (k + run) % rows.length;
      results[i].push(inFreshProcess(rows[i][1], rows[i][2]));
    });
  }
  console.log(`### One call in a fresh process, ${delayMs} ms after init() (${runs} runs, `
    + 'medians)\n');
  console.log('| input | points | crossings | ns per point | outside the core |');
  console.log('| --- | --: | --: | --: | --: |');
  rows.forEach(([name], k) => {
    const rs = results[k];
    const pct = (x) => `${(100 * x).toFixed(1)}%`;
    const outside = rs.map((r) => r.outside);
    console.log(`| ${name} | ${rs[0].points.toLocaleString('en-US')} | `
      + `${rs[0].crossings.toLocaleString('en-US')} | ${median(rs.map((r) => r.nsPerPoint))
        .toFixed(0)} | ${pct(median(outside))} (${pct(Math.min(...outside))}–`
      + `${pct(Math.max(...outside))}) |`);
  });
  if (scale) {
    const ratios = results[2].map((r, i) => r.nsPerPoint / results[1][i].nsPerPoint);
    const m = median(results[2].map((r) => r.nsPerPoint))
      / median(results[1].map((r) => r.nsPerPoint));
    console.log(`\nTime per point, eastern hemisphere / region: ${m.toFixed(2)}× (medians; run `
      + `by run ${ratios.map((r) => r.toFixed(2)).join(', ')}; target ≤ 1.2×)`);
  }
}

if (process.argv[2] === '--child') await child(process.argv[3], process.argv[4]);
else main();
