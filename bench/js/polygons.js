// triangulatePolygons() against earcut and earcut + refine() (earcut 3.2's edge flips to a
// constrained Delaunay triangulation), each polygon alone, on three sets (polygon-sets.js):
// the 211 real-world tiles of @mapbox/mvt-fixtures, the Natural Earth 10m countries (each
// polygon alone) and those countries cut into tiles by geojson-vt (z4-5).
//   warm: the contenders alternate in one process, round after round (medians);
//   cold: the first call of each in a fresh process (medians of --cold-runs processes);
//   threads: the threaded build on 2 threads against one thread, outputs compared;
//   heap: the wasm allocator's peak per input vertex, in a fresh process;
//   chromium (--chromium): the warm alternation in a headless Chromium page.
// earcut gets each polygon as Mapbox GL passes it (a plain array and hole indices), made
// outside the timing; geocdt gets the batch's typed arrays. "earcut wrong" counts polygons
// where the area of earcut's triangles differs from the area inside the rings (even-odd, the
// area of geocdt's triangles, which the tests check against triangulate(..., { keep:
// 'inside' })) by more than 1e-9 of it.
//   node --expose-gc bench/js/polygons.js [--rounds 5] [--cold-runs 3] [--sets tiles,...]
//     [--skip cold,threads,heap,chromium]
import { execFileSync } from 'node:child_process';
import earcut, { refine } from 'earcut';
import { init, triangulatePolygons, memoryUsage } from 'geocdt';
import createGeocdtModule from '../../web/dist/geocdt.mjs';
import { createApi } from '../../web/api.js';
import { instantiateCompiled } from '../../web/warm-up.js';
import { existsSync, readFileSync } from 'node:fs';
import {
  earcutInput, loadSet, polygonCount, vertexCount,
} from '../../scripts/datasets/polygon_sets.mjs';
import { alternate, median } from './timing.js';
import { chromiumPath, inChromium } from './chromium-page.js';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 ? args[i + 1] : fallback;
};
const rounds = Number(option('rounds', '5'));
const coldRuns = Number(option('cold-runs', '3'));
const setNames = option('sets', 'tiles,countries,geojson-vt').split(',');
const skip = new Set(option('skip', '').split(',').filter(Boolean));

function earcutInputs(set) {
  const inputs = [];
  for (let p = 0; p < polygonCount(set); p++) inputs.push(earcutInput(set, p));
  return inputs;
}

function runEarcut(inputs, withRefine) {
  const out = new Array(inputs.length);
  for (let i = 0; i < inputs.length; i++) {
    const { data, holes } = inputs[i];
    const triangles = earcut(data, holes);
    if (withRefine) refine(triangles, data);
    out[i] = triangles;
  }
  return out;
}

// Twice the area of triangles[from .. to) (3 indices each), summing each one's |area|.
function doubledArea(triangles, from, to, x, y) {
  let sum = 0;
  for (let i = from; i < to; i += 3) {
    const a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
    sum += Math.abs((x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a)));
  }
  return sum;
}

// Polygons whose earcut triangles' area is off the area inside by more than 1e-9 of it.
function earcutWrong(set, inputs, earcutOut, geocdtOut) {
  const { coords } = set;
  const n = coords.length / 2;
  const { triangles, extraPoints, triangleOffsets } = geocdtOut;
  const gx = (i) => (i < n ? coords[2 * i] : extraPoints[2 * (i - n)]);
  const gy = (i) => (i < n ? coords[2 * i + 1] : extraPoints[2 * (i - n) + 1]);
  let wrong = 0;
  for (let p = 0; p < inputs.length; p++) {
    const inside = doubledArea(triangles, 3 * triangleOffsets[p], 3 * triangleOffsets[p + 1], gx,
      gy);
    const { data } = inputs[p];
    const e = earcutOut[p];
    const got = doubledArea(e, 0, e.length, (i) => data[2 * i], (i) => data[2 * i + 1]);
    if (Math.abs(got - inside) > 1e-9 * inside) wrong++;
  }
  return wrong;
}

const singleThreaded = () => createApi(async () => {
  const bytes = readFileSync(new URL('../../web/dist/geocdt.wasm', import.meta.url));
  return { wasm: await instantiateCompiled(createGeocdtModule, await WebAssembly.compile(bytes)),
    threads: 1 };
});

const batch = ({ coords, ringOffsets, polygonOffsets }) =>
  ({ coords, ringOffsets, polygonOffsets });

// A fresh process's first call: node polygons.js --cold CONTENDER --set NAME prints its ms.
async function cold(contender, name) {
  const set = loadSet(name);
  let run;
  if (contender === 'geocdt') {
    await init({ warmUp: false });
    run = () => triangulatePolygons(batch(set));
  } else {
    const inputs = earcutInputs(set);
    run = () => runEarcut(inputs, contender === 'earcut + refine');
  }
  const started = performance.now();
  run();
  console.log(JSON.stringify({ ms: performance.now() - started }));
}

// The threaded build on 2 threads against the single-threaded one, in a fresh process.
async function threadsOf(name) {
  const set = loadSet(name);
  const input = batch(set);
  await init({ threads: 2 });
  const one = singleThreaded();
  await one.init({ warmUp: false });
  const results = await alternate([
    { name: '1', run: () => one.triangulatePolygons(input), describe: () => null },
    { name: '2', run: () => triangulatePolygons(input), describe: (r) => r.stats.threads },
  ], rounds);
  const a = one.triangulatePolygons(input), b = triangulatePolygons(input);
  const same = ['triangles', 'extraPoints', 'triangleOffsets'].every((k) =>
    a[k].length === b[k].length && a[k].every((v, i) => v === b[k][i]));
  console.log(JSON.stringify({
    one: results['1'].ms, two: results['2'].ms, threads: results['2'].summary, same,
  }));
}

// A fresh process's allocator peak, per input vertex, for one geocdt call on a set.
async function heap(name) {
  const set = loadSet(name);
  await init({ warmUp: false });
  const before = memoryUsage();
  triangulatePolygons(batch(set));
  const after = memoryUsage();
  console.log(JSON.stringify({
    peakPerVertex: (after.peakBytes - before.allocatedBytes) / vertexCount(set),
    heapPerVertex: after.heapBytes / vertexCount(set),
  }));
}

function fresh(extra) {
  const out = execFileSync(process.execPath,
    ['--expose-gc', new URL(import.meta.url).pathname, ...extra], { encoding: 'utf8' });
  return JSON.parse(out.trim().split('\n').pop());
}

// --- Chromium: the same warm alternation in a page, geocdt's browser entry and earcut as ES
// modules served from the repo, each set's arrays as one binary file. ---

// A set's arrays as [uint32 JSON length, JSON { arrays: [{ key, type, length }] }, padding,
// the arrays], for the page.
function encodeSet(set) {
  const keys = ['coords', 'ringOffsets', 'polygonOffsets'];
  const header = Buffer.from(JSON.stringify({ arrays: keys.map((key) =>
    ({ key, type: set[key].constructor.name, length: set[key].length })) }));
  const padded = Math.ceil((4 + header.length) / 8) * 8;  // 8-aligned arrays (Float64Array)
  const parts = [Buffer.alloc(padded)];
  parts[0].writeUInt32LE(header.length, 0);
  header.copy(parts[0], 4);
  for (const key of keys) {
    const a = set[key];
    const bytes = Buffer.from(a.buffer, a.byteOffset, a.byteLength);
    parts.push(bytes, Buffer.alloc((8 - (bytes.length % 8)) % 8));
  }
  return Buffer.concat(parts);
}

// Runs in the page: for each set, the contenders alternating for `rounds`; medians.
async function inPage(names, rounds) {
  const { default: earcut, refine } = await import('earcut');
  const { init, triangulatePolygons } = await import('geocdt');
  await init({ warmUp: false });
  const types = { Int16Array, Int32Array, Float64Array, Uint32Array };
  const out = {};
  for (const name of names) {
    const buffer = await (await fetch(`/data/${name}`)).arrayBuffer();
    const length = new DataView(buffer).getUint32(0, true);
    const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
    let at = Math.ceil((4 + length) / 8) * 8;
    const set = {};
    for (const { key, type, length: n } of header.arrays) {
      set[key] = new types[type](buffer, at, n);
      at += Math.ceil((n * types[type].BYTES_PER_ELEMENT) / 8) * 8;
    }
    const { coords, ringOffsets, polygonOffsets } = set;
    const inputs = [];
    for (let p = 0; p + 1 < polygonOffsets.length; p++) {
      const first = ringOffsets[polygonOffsets[p]];
      const data = Array.from(coords.subarray(2 * first, 2 * ringOffsets[polygonOffsets[p + 1]]));
      const holes = [];
      for (let r = polygonOffsets[p] + 1; r < polygonOffsets[p + 1]; r++) {
        holes.push(ringOffsets[r] - first);
      }
      inputs.push({ data, holes });
    }
    const runs = {
      earcut: () => { for (const { data, holes } of inputs) earcut(data, holes); },
      'earcut + refine': () => {
        for (const { data, holes } of inputs) refine(earcut(data, holes), data);
      },
      geocdt: () => triangulatePolygons({ coords, ringOffsets, polygonOffsets }),
    };
    const times = { earcut: [], 'earcut + refine': [], geocdt: [] };
    const names3 = Object.keys(runs);
    for (let r = 0; r < rounds; r++) {
      for (let k = 0; k < 3; k++) {
        const c = names3[(k + r) % 3];
        const started = performance.now();
        runs[c]();
        times[c].push(performance.now() - started);
      }
    }
    const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
    out[name] = Object.fromEntries(names3.map((c) => [c, median(times[c])]));
  }
  return out;
}

async function chromium(names) {
  const data = new Map(names.map((name) => [name, encodeSet(loadSet(name))]));
  return inChromium(inPage, [names, rounds],
    { imports: { earcut: '/node_modules/earcut/src/earcut.js' }, data });
}

const fmt = (ms) => ms.toFixed(0);
const ratio = (a, b) => `${(a / b).toFixed(2)}×`;
const verdict = (value, target) => (value <= target ? 'met' : 'missed');

async function main() {
  await init({ warmUp: false });
  const targets = [];
  console.log(`| set | polygons | vertices | earcut ms | earcut + refine ms | geocdt ms | `
    + 'vs earcut | vs earcut + refine | earcut wrong | geocdt general path (crossings) |');
  console.log('|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|');
  const warm = {};
  for (const name of setNames) {
    const set = loadSet(name);
    const inputs = earcutInputs(set);
    const input = batch(set);
    const results = await alternate([
      { name: 'earcut', run: () => runEarcut(inputs, false), describe: () => null },
      { name: 'earcut + refine', run: () => runEarcut(inputs, true), describe: () => null },
      { name: 'geocdt', run: () => triangulatePolygons(input), describe: (r) => r.stats },
    ], rounds);
    const g = triangulatePolygons(input);
    const wrong = earcutWrong(set, inputs, runEarcut(inputs, false), g);
    const e = results.earcut.ms, er = results['earcut + refine'].ms, gm = results.geocdt.ms;
    warm[name] = { e, er, gm };
    console.log(`| ${set.name} | ${polygonCount(set)} | ${vertexCount(set)} | ${fmt(e)} | `
      + `${fmt(er)} | ${fmt(gm)} | ${ratio(gm, e)} | ${ratio(gm, er)} | ${wrong} | `
      + `${g.stats.general} (${g.stats.crossings}) |`);
    if (name === 'tiles') {
      targets.push(['tiles, warm: ≤ 1.0× earcut + refine', gm / er, 1]);
      targets.push(['tiles, warm (aim): ≤ 1.0× earcut', gm / e, 1]);
    }
    if (name === 'countries') targets.push(['countries, warm: ≤ 1.0× earcut + refine', gm / er, 1]);
  }
  if (!skip.has('cold')) {
    console.log(`\nCold: the first call in a fresh process (median of ${coldRuns})\n`);
    console.log('| set | earcut ms | earcut + refine ms | geocdt ms | vs earcut '
      + '| vs earcut + refine |');
    console.log('|---|--:|--:|--:|--:|--:|');
    for (const name of setNames) {
      const ms = {};
      for (const c of ['earcut', 'earcut + refine', 'geocdt']) {
        const runs = [];
        for (let r = 0; r < coldRuns; r++) runs.push(fresh(['--cold', c, '--set', name]).ms);
        ms[c] = median(runs);
      }
      console.log(`| ${name} | ${fmt(ms.earcut)} | ${fmt(ms['earcut + refine'])} | `
        + `${fmt(ms.geocdt)} | ${ratio(ms.geocdt, ms.earcut)} | `
        + `${ratio(ms.geocdt, ms['earcut + refine'])} |`);
    }
  }
  if (!skip.has('threads') && setNames.includes('tiles')) {
    const t = fresh(['--threads-of', 'tiles', '--rounds', String(rounds)]);
    console.log(`\nThreads, tiles: 1 thread ${fmt(t.one)} ms, 2 threads ${fmt(t.two)} ms `
      + `(stats.threads ${t.threads}): ${(t.two / t.one).toFixed(2)}×, output `
      + `${t.same ? 'identical' : 'DIFFERENT'}`);
    targets.push(['tiles, 2 threads: ≤ 0.6× one thread', t.same ? t.two / t.one : Infinity, 0.6]);
  }
  if (!skip.has('heap') && setNames.includes('tiles')) {
    const h = fresh(['--heap', 'tiles']);
    console.log(`\nHeap, tiles: allocator peak ${h.peakPerVertex.toFixed(1)} B a vertex `
      + `(wasm memory ${h.heapPerVertex.toFixed(1)} B a vertex)`);
    targets.push(['tiles, wasm heap peak: ≤ 64 B a vertex', h.peakPerVertex, 64]);
  }
  if (!skip.has('chromium') && existsSync(chromiumPath())) {
    console.log(`\nChromium (headless, warm, medians of ${rounds} alternating rounds)\n`);
    console.log('| set | earcut ms | earcut + refine ms | geocdt ms | vs earcut | '
      + 'vs earcut + refine |');
    console.log('|---|--:|--:|--:|--:|--:|');
    const results = await chromium(setNames);
    for (const name of setNames) {
      const r = results[name];
      console.log(`| ${name} | ${fmt(r.earcut)} | ${fmt(r['earcut + refine'])} | `
        + `${fmt(r.geocdt)} | ${ratio(r.geocdt, r.earcut)} | `
        + `${ratio(r.geocdt, r['earcut + refine'])} |`);
      if (name === 'tiles') {
        targets.push(['tiles, Chromium: ≤ 1.0× earcut + refine', r.geocdt / r['earcut + refine'],
          1]);
      }
    }
  }
  console.log('\n| target | measured | |');
  console.log('|---|--:|---|');
  for (const [what, value, target] of targets) {
    console.log(`| ${what} | ${value.toFixed(2)} | ${verdict(value, target)} |`);
  }
}

if (args.includes('--cold')) await cold(option('cold'), option('set'));
else if (args.includes('--heap')) await heap(option('heap'));
else if (args.includes('--threads-of')) await threadsOf(option('threads-of'));
else await main();
