// Editing in place through the wasm build: 100,000 removals and 100,000 moves of free points
// from a 1M-point Triangulation, one call each, against the time to insert the 1M points
// (then 100,000 more removals in one removePoints call, no target);
// and removing polylines from meshes of 100k and 1M points of the same density (the larger
// spreads wider), whose cost must not grow with the mesh. Also 100,000 small moves (up to a
// quarter of the spacing, as a drag or an animation frame makes them; no target). Alternating
// rounds in one process, medians; each target printed as met or missed. The first round, in a
// fresh process, is also shown alone (cold). With --chromium the point rounds also run in a
// headless Chromium page.
//   node --expose-gc bench/js/editing.js [--rounds N] [--quick] [--chromium]
import { existsSync } from 'node:fs';
import { init, Triangulation } from '../../web/index.node.js';
import { chromiumPath, inChromium } from './chromium-page.js';

// Uniform points in [0, 1000)^2 (datasets.js's generator, without loading its GeoJSON).
function uniform(count, seed = 12345) {
  let s = seed;
  const xy = new Float64Array(2 * count);
  for (let i = 0; i < 2 * count; i++) {
    s = (s * 16807) % 2147483647;
    xy[i] = (s / 2147483647) * 1000;
  }
  return xy;
}

const option = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? Number(process.argv[i + 1]) : fallback;
};
const quick = process.argv.includes('--quick');
const rounds = option('--rounds', quick ? 2 : 3);
const size = quick ? 100_000 : 1_000_000;
const edits = size / 10;
const now = () => performance.now();
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
const verdict = (met) => (met ? 'met' : 'MISSED');
const n = (x) => x.toLocaleString('en-US');

await init();

// A deterministic shuffle.
function shuffled(ids, seed) {
  let s = seed;
  const out = Uint32Array.from(ids);
  for (let i = out.length - 1; i > 0; i--) {
    s = (s * 1103515245 + 12345) % 2147483648;
    const j = Math.floor((s / 2147483648) * (i + 1));
    [out[i], out[j]] = [out[j], out[i]];
  }
  return out;
}

// One round on `size` uniform points: inserting them into a new Triangulation, then removals,
// moves to random places and small moves, a tenth of the points each, one call each in a
// shuffled order. It names no outer binding but uniform() and shuffled(), which the Chromium
// page makes from their sources too.
function pointRound(Mesh, size, round) {
  const edits = size / 10;
  const xy = uniform(size, 1);
  globalThis.gc?.();
  const t = new Mesh();
  const a = performance.now();
  const ids = t.insertPoints(xy);
  const b = performance.now();
  const order = shuffled(ids, 7 + round);
  const places = uniform(edits, 99 + round);
  const reach = 250 / Math.sqrt(size);
  const offsets = uniform(edits, 199 + round).map((v) => ((v - 500) / 500) * reach);
  const c = performance.now();
  for (let k = 0; k < edits; k++) t.removePoint(order[k]);
  const d = performance.now();
  for (let k = 0; k < edits; k++) t.movePoint(order[edits + k], places[2 * k], places[2 * k + 1]);
  const e = performance.now();
  for (let k = 0; k < edits; k++) {
    const id = order[2 * edits + k];
    t.movePoint(id, xy[2 * id] + offsets[2 * k], xy[2 * id + 1] + offsets[2 * k + 1]);
  }
  const f = performance.now();
  t.removePoints(order.subarray(3 * edits, 4 * edits));
  const g = performance.now();
  t.dispose();
  return { insert: b - a, removals: d - c, moves: e - d, smallMoves: f - e, batch: g - f };
}

// Runs in the page: `rounds` point rounds with the browser build; sources: pointRound's,
// uniform's and shuffled's.
async function inPage([roundSource, uniformSource, shuffledSource], size, rounds) {
  const { init: start, Triangulation: Mesh } = await import('geocdt');
  await start({ warmUp: false });
  const make = (source, ...names) => new Function(...names, `return (${source})`);
  const round = make(roundSource, 'uniform', 'shuffled')(make(uniformSource)(),
    make(shuffledSource)());
  const rows = [];
  for (let r = 0; r < rounds; r++) rows.push(round(Mesh, size, r));
  return rows;
}

// 200 polylines of 20 points, alternately near-horizontal and near-vertical across
// [100, 900]^2, in a mesh of `points` at 0.1 points a square unit: the time to remove them
// all, one call each, per crossing they had made.
function lineRound(points, round) {
  globalThis.gc?.();
  const t = new Triangulation();
  const side = Math.sqrt(points * 10);
  const xy = uniform(points, 31 + round).map((v) => (v * side) / 1000);
  t.insertPoints(xy);
  const jitter = uniform(4000, 41 + round);
  for (let k = 0; k < 200; k++) {
    const base = 100 + 0.8 * jitter[k];
    const line = [];
    for (let i = 0; i < 20; i++) {
      const along = 100 + (800 * i) / 19, across = base + (jitter[200 + 20 * k + i] - 500) * 0.01;
      line.push(k % 2 ? across : along, k % 2 ? along : across);
    }
    t.insertPolyline(line);
  }
  const crossings = t.stats.crossings;
  const a = now();
  for (let k = 0; k < 200; k++) t.removePolyline(k);
  const ms = now() - a;
  t.dispose();
  return { perCrossing: ms / crossings, crossings };
}

const rows = [];
const small = [], large = [];
for (let round = 0; round < rounds; round++) {
  rows.push(pointRound(Triangulation, size, round));
  small.push(lineRound(size / 10, round));
  large.push(lineRound(size, round));
}
const smallCost = median(small.map((r) => r.perCrossing));
const largeCost = median(large.map((r) => r.perCrossing));

// The point rounds' lines: times, and the ratios to inserting the points against the targets.
function pointLines(list) {
  const insert = median(list.map((r) => r.insert));
  const removalRatio = median(list.map((r) => r.removals / r.insert));
  const moveRatio = median(list.map((r) => r.moves / r.insert));
  console.log(`- inserting the points: ${insert.toFixed(0)} ms`);
  console.log(`- ${n(edits)} removals, one call each: `
    + `${median(list.map((r) => r.removals)).toFixed(0)} ms = ${removalRatio.toFixed(3)}× `
    + `(target ≤ 0.5×, aim 0.25×): ${verdict(removalRatio <= 0.5)}`);
  console.log(`- ${n(edits)} moves of free points: `
    + `${median(list.map((r) => r.moves)).toFixed(0)} ms = ${moveRatio.toFixed(3)}× `
    + `(target ≤ 1.0×): ${verdict(moveRatio <= 1.0)}`);
  console.log(`- ${n(edits)} small moves (up to a quarter of the spacing): `
    + `${median(list.map((r) => r.smallMoves)).toFixed(0)} ms = `
    + `${median(list.map((r) => r.smallMoves / r.insert)).toFixed(3)}× (no target)`);
  console.log(`- ${n(edits)} more removals in one removePoints call (from the points left): `
    + `${median(list.map((r) => r.batch)).toFixed(0)} ms = `
    + `${median(list.map((r) => r.batch / r.insert)).toFixed(3)}× (no target)`);
}

console.log(`## Editing, ${n(size)} points (${rounds} rounds, medians)\n`);
pointLines(rows);
console.log(`- removing 200 polylines: ${(1000 * smallCost).toFixed(2)} µs a crossing at `
  + `${n(size / 10)} points (${n(small[0].crossings)} crossings), `
  + `${(1000 * largeCost).toFixed(2)} µs at ${n(size)}: ${(largeCost / smallCost).toFixed(2)}× `
  + `(target: within 1.5×): ${verdict(largeCost / smallCost <= 1.5)}`);
console.log('\n## The first round alone, in this fresh process (cold)\n');
pointLines(rows.slice(0, 1));
if (process.argv.includes('--chromium') && existsSync(chromiumPath())) {
  const pageRows = await inChromium(inPage,
    [[pointRound, uniform, shuffled].map(String), size, rounds]);
  console.log(`\n## Chromium (headless, ${rounds} rounds, medians)\n`);
  pointLines(pageRows);
  console.log('\n## Chromium, the first round in a fresh page (cold)\n');
  pointLines(pageRows.slice(0, 1));
}
