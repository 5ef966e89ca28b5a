// Terrain meshes from the USGS Jacksboro fault DEM (403 x 344 int16 metres, Debian's
// python-matplotlib-data): geocdt's triangulateRaster (wasm; plain, and with decimate)
// against delatin (greedy Delaunay insertion) and @mapbox/martini (RTIN, on the top-left
// 257 x 257 crop, the size it needs), alternating in one process, medians of wall and
// main-thread CPU time; against delatin on the DEM upsampled 4 times too (no target). Each
// mesh's largest error is measured over every pixel, the same way for all (pixel-error.js).
// Then breaklines and minAngle 20 against geocdt's plain mesh.
// Then each one's first call in a fresh process (cold: wall time, medians of --cold-runs
// processes). Prints the targets, met or missed. With --chromium, the comparisons also run in
// a headless Chromium page (wall time there), warm and cold (the first call in a fresh page).
//   node --expose-gc bench/js/terrain.js [--rounds N] [--cold-runs N] [--quick] [--chromium]
//   node bench/js/terrain.js --first geocdt|geocdt-later|delatin --error E   (one cold call,
//     printed as JSON)
import { execFileSync } from 'node:child_process';
import Delatin from 'delatin';
import Martini from '@mapbox/martini';
import { init, triangulateRaster } from 'geocdt';
import { crop, jacksboro, upsampled } from '../../scripts/usgs-dems.mjs';
import { maxPixelError } from './pixel-error.js';
import { median, threadCpuClock } from './timing.js';
import { inChromium } from './chromium-page.js';

const option = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? Number(process.argv[i + 1]) : fallback;
};
const quick = process.argv.includes('--quick');
const rounds = option('--rounds', quick ? 3 : 7);
const coldRuns = option('--cold-runs', 3);
const errors = quick ? [5, 20] : [1, 5, 10, 20];
const n = (x) => x.toLocaleString('en-US');
const ms = (x) => (x < 10 ? x.toFixed(2) : x.toFixed(1));
const ratio = (x) => `${x.toFixed(2)}×`;

// One contender's first call in this fresh process, the DEM loaded before it: what a tile's
// first mesh in a new worker costs. geocdt made at once after init() (its warm-up thread
// left out), or 1 s after it (the warm-up's head start while a caller fetches its tile).
if (process.argv.includes('--first')) {
  const firstOf = process.argv[process.argv.indexOf('--first') + 1];
  const raster = jacksboro(), maxError = option('--error', 5);
  if (firstOf === 'geocdt') await init({ warmUp: false });
  if (firstOf === 'geocdt-later') {
    await init();
    await new Promise((resolve) => { setTimeout(resolve, 1000); });
  }
  const started = performance.now();
  const triangles = firstOf.startsWith('geocdt')
    ? triangulateRaster(raster, { maxError }).triangles.length / 3
    : (() => {
      const d = new Delatin(raster.heights, raster.width, raster.height);
      d.run(maxError);
      return d.triangles.length / 3;
    })();
  console.log(JSON.stringify({ ms: performance.now() - started, triangles }));
  process.exit(0);
}

await init();
const cpuClock = threadCpuClock();

// Runs the contenders in alternation, `times` rounds; each returns a mesh summary
// { triangles, maxError }, measured after the timing from the last run's output.
function alternate(contenders, times = rounds) {
  const results = contenders.map(() => ({ wall: [], cpu: [], output: null }));
  for (let round = 0; round < times; round++) {
    for (let k = 0; k < contenders.length; k++) {
      const i = (k + round) % contenders.length;
      globalThis.gc?.();
      const started = performance.now();
      const cpuStarted = cpuClock?.();
      const output = contenders[i].run();
      results[i].wall.push(performance.now() - started);
      if (cpuClock) results[i].cpu.push(cpuClock() - cpuStarted);
      results[i].output = output;
    }
  }
  return results.map((r, i) => ({
    name: contenders[i].name,
    wall: median(r.wall),
    cpu: cpuClock ? median(r.cpu) : NaN,
    runs: cpuClock ? r.cpu : r.wall,  // each round's time, for paired ratios
    ...contenders[i].measure(r.output),
  }));
}

const dem = jacksboro();
const small = crop(dem, 257);
const martini = new Martini(257);
const smallFloat = Float32Array.from(small.heights);

const geocdt = (raster, maxError, extra = {}, name = 'geocdt') => ({
  name,
  run: () => triangulateRaster(raster, { maxError, ...extra }),
  measure: (r) => ({
    triangles: r.triangles.length / 3,
    ...maxPixelError({ xy: r.points, triangles: r.triangles, z: r.values }, raster),
  }),
});
const delatin = (raster, maxError) => ({
  name: 'delatin',
  run: () => {
    const d = new Delatin(raster.heights, raster.width, raster.height);
    d.run(maxError);
    return d;
  },
  measure: (d) => ({
    triangles: d.triangles.length / 3,
    ...maxPixelError({ xy: d.coords, triangles: d.triangles }, raster),
  }),
});

const targets = [];
function target(text, met, detail) {
  targets.push(`- ${met ? 'met' : 'MISSED'}: ${text} (${detail})`);
}

function table(rows) {
  console.log('| max error | library | triangles | wall ms | CPU ms | largest error '
    + 'over every pixel | pixels in no triangle |');
  console.log('|--:|---|--:|--:|--:|--:|--:|');
  for (const { e, r } of rows) {
    console.log(`| ${e} m | ${r.name} | ${n(r.triangles)} | ${ms(r.wall)} | ${ms(r.cpu)} | `
      + `${r.maxError.toFixed(3)} | ${r.uncovered} |`);
  }
  console.log();
}

// The main targets: against delatin on the whole DEM.
console.log(`## Jacksboro DEM, ${dem.width} x ${dem.height}, ${rounds} rounds\n`);
{
  const rows = [];
  for (const e of errors) {
    const [g, gd, d] = alternate([geocdt(dem, e),
      geocdt(dem, e, { decimate: true }, 'geocdt, decimate'), delatin(dem, e)]);
    rows.push({ e, r: g }, { e, r: gd }, { e, r: d });
    for (const [r, how] of [[g, ''], [gd, ', decimate']]) {
      const time = (cpuClock ? r.cpu / d.cpu : r.wall / d.wall);
      target(`${e} m${how}: at most 1.0× delatin's triangles`, r.triangles <= d.triangles,
        `${n(r.triangles)} against ${n(d.triangles)}, ${ratio(r.triangles / d.triangles)}`);
      target(`${e} m${how}: at most 0.25× delatin's time`, time <= 0.25,
        `${ratio(time)} (${cpuClock ? 'CPU' : 'wall'}: ${ms(cpuClock ? r.cpu : r.wall)} against `
        + `${ms(cpuClock ? d.cpu : d.wall)} ms)`);
      target(`${e} m${how}: every pixel within the bound`,
        r.maxError <= e * (1 + 1e-9) && !r.uncovered,
        `largest ${r.maxError.toFixed(3)}, ${r.uncovered} uncovered`);
    }
  }
  table(rows);
}

// A high-resolution model's size: the DEM 4 times finer (bilinear), against delatin; no
// target. Large triangles are scanned by blocks (bench/EXPERIMENTS.md, TN43).
{
  const fine = upsampled(dem, 4);
  const fineRounds = Math.min(rounds, 3);
  console.log(`## The DEM upsampled 4 times, ${fine.width} x ${fine.height}, ${fineRounds} `
    + 'rounds\n');
  const rows = [];
  for (const e of quick ? [20] : [5, 20]) {
    const [g, d] = alternate([geocdt(fine, e), delatin(fine, e)], fineRounds);
    rows.push({ e, r: g }, { e, r: d });
  }
  table(rows);
  const time = (r) => (cpuClock ? r.cpu : r.wall);
  for (let k = 0; k < rows.length; k += 2) {
    console.log(`- ${rows[k].e} m: geocdt ${ratio(time(rows[k].r) / time(rows[k + 1].r))} `
      + `delatin's time, ${ratio(rows[k].r.triangles / rows[k + 1].r.triangles)} its triangles`);
  }
  console.log();
}

// Against martini on the 257 x 257 crop it can take.
console.log(`## The top-left 257 x 257 crop, ${rounds} rounds\n`);
{
  const rows = [];
  const equal = [];
  for (const e of errors) {
    const m = {
      name: 'martini',
      run: () => martini.createTile(smallFloat).getMesh(e),
      measure: ({ vertices, triangles }) => ({
        triangles: triangles.length / 3,
        ...maxPixelError({ xy: vertices, triangles }, small),
      }),
    };
    const [g, gd, mm, d] = alternate([geocdt(small, e),
      geocdt(small, e, { decimate: true }, 'geocdt, decimate'), m, delatin(small, e)]);
    rows.push({ e, r: g }, { e, r: gd }, { e, r: mm }, { e, r: d });
    // martini's maxError does not bound the error at every pixel: geocdt at the error
    // martini's mesh reached, once, for the comparison at equal measured error.
    const atMartinis = triangulateRaster(small, { maxError: mm.maxError });
    equal.push(`| ${e} m | ${mm.maxError.toFixed(3)} m | ${n(mm.triangles)} | `
      + `${n(atMartinis.triangles.length / 3)} | `
      + `${ratio(atMartinis.triangles.length / 3 / mm.triangles)} |`);
    const time = cpuClock ? g.cpu / mm.cpu : g.wall / mm.wall;
    for (const [r, how] of [[g, ''], [gd, ', decimate']]) {
      target(`crop, ${e} m${how}: at most 0.6× martini's triangles`,
        r.triangles <= 0.6 * mm.triangles,
        `${n(r.triangles)} against ${n(mm.triangles)}, ${ratio(r.triangles / mm.triangles)}`);
    }
    target(`crop, ${e} m (aim): martini's time`, time <= 1, `${ratio(time)}`);
  }
  table(rows);
  console.log('At the error martini\'s mesh reached (measured over every pixel):\n');
  console.log('| martini\'s maxError | its largest error | martini | geocdt at that error | '
    + 'geocdt / martini |');
  console.log('|--:|--:|--:|--:|--:|');
  console.log(`${equal.join('\n')}\n`);
}

// Breaklines (three lines across the DEM, crossing each other and its edges, and a closed
// one) and minAngle 20, against the plain mesh.
const breaklines = [
  [-10, 330, 120, 230, 260, 150, 415, 20],
  [30, -5, 160, 120, 250, 200, 330, 350],
  [0, 100, 402, 180],
  [200, 60, 260, 60, 260, 110, 200, 110, 200, 60],
];
console.log(`## Breaklines and minAngle 20 at 5 m and 20 m, ${rounds} rounds\n`);
{
  console.log('| max error | mesh | triangles | Steiner points | wall ms | CPU ms | vs plain '
    + '| vs plain, paired | largest error over every pixel |');
  console.log('|--:|---|--:|--:|--:|--:|--:|--:|--:|');
  for (const e of quick ? [5] : [5, 20]) {
    const variant = (name, extra) => ({
      ...geocdt(dem, e, extra),
      name,
      measure: (r) => ({
        triangles: r.triangles.length / 3,
        steiner: r.stats.steinerPoints,
        ...maxPixelError({ xy: r.points, triangles: r.triangles, z: r.values }, dem),
      }),
    });
    const results = alternate([
      variant('plain', {}),
      variant('breaklines', { breaklines }),
      variant('minAngle 20', { minAngle: 20 }),
      variant('breaklines, minAngle 20', { breaklines, minAngle: 20 }),
    ]);
    const plain = results[0];
    const time = (r) => (cpuClock ? r.cpu : r.wall);
    // The median of each round's ratio: the two ran side by side in that round, so a drift in
    // the host's speed over the rounds cancels out of it; it stays in the ratio of the medians.
    const paired = (r) => median(r.runs.map((t, round) => t / plain.runs[round]));
    for (const r of results) {
      console.log(`| ${e} m | ${r.name} | ${n(r.triangles)} | ${n(r.steiner)} | ${ms(r.wall)} | `
        + `${ms(r.cpu)} | ${ratio(time(r) / time(plain))} | ${ratio(paired(r))} | `
        + `${r.maxError.toFixed(3)} |`);
    }
    const both = results[3];
    target(`${e} m: breaklines and minAngle 20 at most 1.5× the plain mesh's time`,
      paired(both) <= 1.5, `${ratio(paired(both))}, the median of the rounds' ratios; `
        + `${ratio(time(both) / time(plain))} between the medians of the times`);
  }
  console.log();
}

// Cold: each contender's first call, firstCall(who, maxError) resolving to { ms, triangles }
// in a fresh process or page, the three alternating; a table and the targets, as `where`.
const coldErrors = quick ? [5] : [5, 20];
async function coldTable(where, firstCall) {
  console.log(`## ${where}: the first call (cold; wall time, medians of ${coldRuns})\n`);
  console.log('| max error | geocdt ms, at once after init() | 1 s after init() | delatin ms '
    + '| geocdt / delatin | triangles, geocdt / delatin |');
  console.log('|--:|--:|--:|--:|--:|--:|');
  for (const e of coldErrors) {
    const runs = { geocdt: [], 'geocdt-later': [], delatin: [] };
    const triangles = {};
    for (let r = 0; r < coldRuns; r++) {
      for (const who of Object.keys(runs)) {
        const first = await firstCall(who, e);
        runs[who].push(first.ms);
        triangles[who] = first.triangles;
      }
    }
    const [g, later, d] = Object.values(runs).map(median);
    console.log(`| ${e} m | ${ms(g)} | ${ms(later)} | ${ms(d)} | ${ratio(g / d)}, `
      + `${ratio(later / d)} | ${n(triangles.geocdt)} / ${n(triangles.delatin)} |`);
    target(`${where}, cold, ${e} m: at most 0.25× delatin's time`, g <= 0.25 * d,
      `${ratio(g / d)} at once after init(), ${ratio(later / d)} 1 s after it (wall: ${ms(g)}`
      + ` and ${ms(later)} against ${ms(d)} ms)`);
  }
  console.log();
}

await coldTable('Node, a fresh process', (who, e) => JSON.parse(execFileSync(process.execPath, [
  new URL(import.meta.url).pathname, '--first', who, '--error', String(e)],
{ encoding: 'utf8' }).trim().split('\n').pop()));

// --- Chromium: the same alternations in a page, wall time. ---

// Runs in the page: geocdt (the browser build), delatin and martini on the DEM's bytes.
async function measureInPage(rounds, errors) {
  const api = await import('/web/index.browser.js');
  const { default: Delatin } = await import('/node_modules/delatin/index.js');
  const { default: Martini } = await import('/node_modules/@mapbox/martini/index.js');
  await api.init({ warmUp: false });
  const bytes = await (await fetch('/data/dem')).arrayBuffer();
  const [width, height] = new Uint32Array(bytes, 0, 2);
  const heights = new Int16Array(bytes, 8, width * height);
  const dem = { heights, width, height };
  const small = new Int16Array(257 * 257);
  for (let j = 0; j < 257; j++) small.set(heights.subarray(j * width, j * width + 257), j * 257);
  const smallFloat = Float32Array.from(small);
  const martini = new Martini(257);
  const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
  const time = (runs) => {
    const t = runs.map(() => []);
    const counts = [];
    for (let round = 0; round < rounds; round++) {
      for (let k = 0; k < runs.length; k++) {
        const i = (k + round) % runs.length;
        const started = performance.now();
        counts[i] = runs[i]();
        t[i].push(performance.now() - started);
      }
    }
    return t.map((v, i) => ({ ms: median(v), triangles: counts[i] }));
  };
  const rows = [];
  for (const e of errors) {
    const [g, d] = time([
      () => api.triangulateRaster(dem, { maxError: e }).triangles.length / 3,
      () => {
        const x = new Delatin(heights, width, height);
        x.run(e);
        return x.triangles.length / 3;
      },
    ]);
    const [gc, m] = time([
      () => api.triangulateRaster({ heights: small, width: 257, height: 257 },
        { maxError: e }).triangles.length / 3,
      () => martini.createTile(smallFloat).getMesh(e).triangles.length / 3,
    ]);
    rows.push({ e, g, d, gc, m });
  }
  return rows;
}

// Runs in a fresh page: one contender's first call, as --first does in Node.
async function firstInPage(who, maxError) {
  const bytes = await (await fetch('/data/dem')).arrayBuffer();
  const [width, height] = new Uint32Array(bytes, 0, 2);
  const heights = new Int16Array(bytes, 8, width * height);
  let run;
  if (who === 'delatin') {
    const { default: Delatin } = await import('/node_modules/delatin/index.js');
    run = () => {
      const d = new Delatin(heights, width, height);
      d.run(maxError);
      return d.triangles.length / 3;
    };
  } else {
    const api = await import('/web/index.browser.js');
    await api.init(who === 'geocdt' ? { warmUp: false } : {});
    if (who === 'geocdt-later') await new Promise((resolve) => { setTimeout(resolve, 1000); });
    run = () => api.triangulateRaster({ heights, width, height }, { maxError }).triangles.length
      / 3;
  }
  const started = performance.now();
  const triangles = run();
  return { ms: performance.now() - started, triangles };
}

async function chromiumRun() {
  const bytes = new Uint8Array(8 + 2 * dem.width * dem.height);
  new Uint32Array(bytes.buffer, 0, 2).set([dem.width, dem.height]);
  new Int16Array(bytes.buffer, 8).set(dem.heights);
  const data = { data: new Map([['dem', bytes]]) };
  const rows = await inChromium(measureInPage, [rounds, errors], data);
  console.log(`## Chromium (${rounds} rounds, wall time medians)\n`);
  console.log('| max error | geocdt | delatin | geocdt / delatin | geocdt, crop | martini, crop '
    + '| crop triangles, geocdt / martini |');
  console.log('|--:|--:|--:|--:|--:|--:|--:|');
  for (const { e, g, d, gc, m } of rows) {
    console.log(`| ${e} m | ${ms(g.ms)} ms | ${ms(d.ms)} ms | ${ratio(g.ms / d.ms)} | `
      + `${ms(gc.ms)} ms | ${ms(m.ms)} ms | ${ratio(gc.triangles / m.triangles)} |`);
    target(`Chromium, ${e} m: at most 0.25× delatin's time`, g.ms <= 0.25 * d.ms,
      ratio(g.ms / d.ms));
  }
  console.log();
  await coldTable('Chromium, a fresh page', (who, e) => inChromium(firstInPage, [who, e], data));
}

if (process.argv.includes('--chromium')) await chromiumRun();

console.log('## Targets\n');
console.log(targets.join('\n'));
