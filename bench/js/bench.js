// npm run bench: geocdt against its JS/wasm peers, same process, alternating runs, medians.
//   node --expose-gc bench/js/bench.js [--quick]
//   node --expose-gc bench/js/bench.js --targets [--data DIR]
// --targets prints every wasm target of the speed work instead, each benchmark in its own
// processes: targets.js (warm, against delaunator), the heap peaks, one-call.js and
// first-call.js (at once and 1 s after init(); Chromium rows where Chromium is installed).
// DIR holds the GSHHG regions (default build/data, as scripts/datasets/all.sh writes them).
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { init, triangulate } from 'geocdt';
import { alternate, median } from './timing.js';
import { countryArcs, countryRings, indexedGraph, pointCount, uniformLehmer } from './datasets.js';
import * as peers from './peers.js';
import { constraintCost, constraintDatasets } from './constraint-cost.js';

const quick = process.argv.includes('--quick');
const here = (file) => fileURLToPath(new URL(file, import.meta.url));
const n = (x) => x.toLocaleString('en-US');
const ms = (x) => (x === undefined ? '' : x < 10 ? x.toFixed(2) : x.toFixed(0));

function table(header, rows) {
  const line = (cells) => `| ${cells.join(' | ')} |`;
  console.log([line(header), line(header.map(() => '---')), ...rows.map(line)].join('\n'));
  console.log();
}

function resultRows(results, reference) {
  const base = results[reference]?.ms;
  return Object.entries(results).map(([name, r]) => r.error
    ? [name, 'FAILED', '', r.error]
    : [name, ms(r.ms), base ? `${(r.ms / base).toFixed(2)}×` : '', r.summary]);
}

// Reports the median of the wasm core's share of the time (the rest: checks and copies).
function geocdt(name, input, options) {
  const core = [];
  return {
    name,
    run: () => triangulate(input, options),
    describe: (r) => {
      core.push(r.stats.coreMilliseconds);
      const bad = peers.badTriangles(r.points, r.triangles);
      return `${n(r.triangles.length / 3)} triangles, ${n(r.stats.crossings)} crossings, ` +
        `core ${ms(median(core))} ms${bad ? `, ${bad} INVALID` : ''}`;
    },
  };
}

// Runs a script in a fresh Node process and parses the JSON it prints.
function runJson(script, ...args) {
  return JSON.parse(execFileSync(process.execPath, [script, ...args], { encoding: 'utf8' }));
}

async function startup() {
  const wasm = readFileSync(here('../../web/dist/geocdt.wasm'));
  const runs = [];
  for (let i = 0; i < 7; i++) runs.push(runJson(here('startup.js')));
  const gzipped = gzipSync(wasm, { level: 9 }).length;
  const initMs = median(runs.map((r) => r.initMs));
  console.log('## Package\n');
  table(['measure', 'value', 'target'], [
    ['geocdt.wasm', `${n(wasm.length)} B, ${n(gzipped)} B gzipped`, '≤ 100 KB gzipped'],
    ['cold `await init()` (median of 7 processes)', `${ms(initMs)} ms`, '≤ 50 ms'],
    ['import + init', `${ms(median(runs.map((r) => r.importAndInitMs)))} ms`, ''],
  ]);
}

function heapPeak(sizes) {
  console.log('## wasm heap per point (fresh process, uniform points)\n');
  const header = ['points', 'allocator peak / point', 'memory growth / point', 'target'];
  table(header, sizes.map((size) => {
    const r = runJson(here('heap-peak.js'), String(size));
    const perPoint = (bytes) => `${bytes.toFixed(1)} B`;
    return [n(size), perPoint(r.peakBytesPerPoint), perPoint(r.heapGrowthPerPoint), '≤ 80 B'];
  }));
}

async function uniformPoints(sizes) {
  console.log('## Uniform points: geocdt vs delaunator\n');
  console.log('geocdt times include the input checks and the copies in and out of the wasm ' +
    'heap.\n');
  for (const size of sizes) {
    const xy = uniformLehmer(size);
    const rounds = size <= 100_000 ? 9 : size <= 1_000_000 ? 5 : 3;
    const results = await alternate([
      geocdt('geocdt', { points: xy }),
      { name: 'delaunator', run: () => peers.delaunator(xy), describe: peers.summary },
    ], rounds);
    console.log(`### ${n(size)} points (${rounds} alternating rounds, medians)\n`);
    table(['library', 'ms', 'vs delaunator', 'result'], resultRows(results, 'delaunator'));
  }
}

// cdt2d takes minutes from the 50m scale on; Triangle (wasm32, fixed 16 MB heap) runs out of
// memory on the 10m one: they run where they can finish.
async function constrained(dataset, { cdt2d, triangleWasm }) {
  const { name, polylines, polygons } = dataset;
  const graph = indexedGraph(polylines);
  const contenders = [
    geocdt('geocdt (keep all)', { polylines }),
    geocdt('geocdt (keep inside)', { polylines }, { keep: 'inside' }),
    { name: 'constrainautor', run: () => peers.constrainautor(graph), describe: peers.summary },
  ];
  if (cdt2d) {
    contenders.push({ name: 'cdt2d', run: () => peers.cdt(graph), describe: peers.cdtSummary });
  }
  if (triangleWasm) {
    contenders.push({ name: 'triangle-wasm', run: () => triangle.run(graph), describe: (s) => s });
  }
  if (polygons) {
    contenders.push({
      name: 'earcut (each polygon alone)',
      run: () => peers.earcutPolygons(polygons),
      describe: (r) => peers.earcutSummary(polygons, r),
    });
  }
  const rounds = pointCount(polylines) > 200_000 ? 3 : 5;
  const results = await alternate(contenders, rounds);
  console.log(`### ${name}: ${n(pointCount(polylines))} points, ${n(polylines.length)} ` +
    `polylines, ${n(graph.edges.length)} distinct-point segments (${rounds} rounds)\n`);
  table(['library', 'ms', 'vs geocdt', 'result'], resultRows(results, 'geocdt (keep all)'));
  const skipped = [!cdt2d && 'cdt2d', !triangleWasm && 'triangle-wasm'].filter(Boolean);
  if (skipped.length) console.log(`(${skipped.join(' and ')}: not run at this scale.)\n`);
}

// Runs a benchmark script in a fresh Node process, its output going straight to ours.
function runScript(args) {
  execFileSync(process.execPath, args, { stdio: 'inherit' });
}

function targets() {
  const i = process.argv.indexOf('--data');
  const data = i >= 0 ? process.argv[i + 1] : here('../../build/data');
  console.log('## Warm, in one process (bench/js/targets.js)\n');
  runScript(['--expose-gc', here('targets.js'), '--data', data]);
  console.log('## wasm heap peak per input point (fresh process each)\n');
  table(['input', 'allocator peak / point', 'target'], [
    ['1M uniform points', '1000000', '≤ 80 B'],
    ['Natural Earth 10m rings', 'rings', '≤ 140 B'],
  ].map(([name, what, target]) => [name,
    `${runJson(here('heap-peak.js'), what).peakBytesPerPoint.toFixed(1)} B`, target]));
  runScript([here('one-call.js'), '--data', data, '--runs', '5']);
  console.log();
  const engines = existsSync(process.env.CHROMIUM_PATH ?? '/usr/bin/chromium') ? []
    : ['--node'];
  if (engines.length) console.log('(No Chromium found: the first call in Node only.)\n');
  for (const delay of ['0', '1000']) {
    console.log(`## The first call, ${delay === '0' ? 'at once after' : '1 s after'} init() `
      + '(bench/js/first-call.js; target ≤ 1.3× a warm call, init() ≤ 50 ms in Chromium)\n');
    runScript([here('first-call.js'), '--runs', '5', '--delay', delay, ...engines]);
  }
}

if (process.argv.includes('--targets')) {
  targets();
  process.exit(0);
}

const triangle = peers.triangleInWorker();
await init();
await startup();
heapPeak(quick ? [100_000] : [100_000, 1_000_000]);
await uniformPoints(quick ? [100_000] : [100_000, 1_000_000, 2_000_000]);
console.log('## Constraints: Natural Earth (world-atlas), triangulated in lon/lat\n');
console.log('Peers get deduplicated points and index edges prepared outside the timing; ' +
  'geocdt gets the raw rings.\n');
for (const scale of quick ? ['110m'] : ['110m', '50m', '10m']) {
  const peersHere = { cdt2d: scale === '110m', triangleWasm: scale !== '10m' };
  await constrained(countryRings(scale), peersHere);
  await constrained(countryArcs(scale), peersHere);
}
if (!quick) {
  console.log('## What constraints cost: constrained vs the same points alone\n');
  const dataDir = fileURLToPath(new URL('../../build/data', import.meta.url));
  for (const { name, polylines } of constraintDatasets(dataDir))
    await constraintCost({ triangulate }, name, polylines, 5);
}
triangle.close();
