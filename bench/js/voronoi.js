// Voronoi cells against d3-delaunay, in one process, alternating, medians: 1M uniform sites
// clipped to a box (d3: new Delaunay(points), .voronoi(box) and every cellPolygon(i); geocdt:
// voronoi() with every cell in GeoArrow arrays), then geocdt alone on the Natural Earth rings:
// 20,000 sites against the 50m countries (the cells' areas summed against the land's, from the
// rings' own triangulation), and 1M sites against the 10m countries next to the same sites in
// their box. Then the box as users meet it first: the first call in a fresh process, and in
// headless Chromium, warm (alternating in one page) and cold (the first call in a fresh page).
// Prints each target as met or missed.
//   node --expose-gc bench/js/voronoi.js [--quick] [--rounds N] [--threads N] [--cold-runs N]
//     [--skip cold,chromium]
//   node bench/js/voronoi.js --first geocdt|d3 [--quick]   (one cold call; prints JSON)
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { Delaunay } from 'd3-delaunay';
import { init, triangulate, voronoi } from 'geocdt';
import { median, threadCpuClock } from './timing.js';
import { countryRings, uniformLehmer as uniform } from './datasets.js';
import { chromiumPath, inChromium } from './chromium-page.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const quick = process.argv.includes('--quick');
const rounds = Number(option('--rounds', quick ? 3 : 7));
const threads = Number(option('--threads', 1));
const coldRuns = Number(option('--cold-runs', 3));
const skip = new Set(option('--skip', '').split(',').filter(Boolean));
const n = (x) => x.toLocaleString('en-US');
const cpuClock = threadCpuClock();

// Runs the contenders in alternation: { name: { wall, cpu } } medians in ms.
function alternate(contenders) {
  const times = Object.fromEntries(contenders.map(([name]) => [name, { wall: [], cpu: [] }]));
  for (let round = 0; round < rounds; round++) {
    for (let k = 0; k < contenders.length; k++) {
      const [name, run] = contenders[(k + round) % contenders.length];
      globalThis.gc?.();
      const started = performance.now();
      const cpuStarted = cpuClock?.();
      run();
      if (cpuClock) times[name].cpu.push(cpuClock() - cpuStarted);
      times[name].wall.push(performance.now() - started);
    }
  }
  return Object.fromEntries(Object.entries(times).map(([name, t]) => [name,
    { wall: median(t.wall), cpu: cpuClock ? median(t.cpu) : undefined }]));
}

// Every cell of d3's diagram, as d3 users get them: one array of [x, y] pairs a cell.
function d3Cells(points, box) {
  const voronoiDiagram = new Delaunay(points).voronoi(box);
  let vertices = 0;
  for (let i = 0; i < points.length / 2; i++) {
    vertices += voronoiDiagram.cellPolygon(i)?.length ?? 0;
  }
  return vertices;
}

function meshArea({ points: p, triangles: t }) {
  let area = 0;
  for (let k = 0; k < t.length; k += 3) {
    const [a, b, c] = [2 * t[k], 2 * t[k + 1], 2 * t[k + 2]];
    area += ((p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[b + 1] - p[a + 1]) * (p[c] - p[a])) / 2;
  }
  return area;
}

function cellsArea(c) {
  let area = 0;
  const p = c.coords;
  for (let r = 0; r + 1 < c.ringOffsets.length; r++) {
    const b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
    for (let k = b + 1; k + 1 < e; k++) {
      area += ((p[2 * k] - p[2 * b]) * (p[2 * k + 3] - p[2 * b + 1])
        - (p[2 * k + 1] - p[2 * b + 1]) * (p[2 * k + 2] - p[2 * b])) / 2;
    }
  }
  return area;
}

// Sites uniform over [x0, x1] x [y0, y1].
function sitesIn(count, [x0, y0, x1, y1], seed) {
  const u = uniform(count, seed);
  for (let i = 0; i < u.length; i += 2) {
    u[i] = x0 + (u[i] / 1000) * (x1 - x0);
    u[i + 1] = y0 + (u[i + 1] / 1000) * (y1 - y0);
  }
  return u;
}

const verdict = (met) => (met ? 'met' : '**missed**');
const ratio = (a, b) => (a / b).toFixed(2);

const count = quick ? 200_000 : 1_000_000;
const box = [0, 0, 1000, 1000];

// One contender's first call in this (fresh) process, geocdt's after init(); prints JSON.
async function first(contender) {
  const points = uniform(count);
  if (contender === 'geocdt') await init({ warmUp: false });
  const started = performance.now();
  if (contender === 'geocdt') voronoi({ points }, { clip: box });
  else d3Cells(points, box);
  console.log(JSON.stringify({ ms: performance.now() - started }));
}

function fresh(contender) {
  const out = execFileSync(process.execPath, [new URL(import.meta.url).pathname, '--first',
    contender, ...(quick ? ['--quick'] : [])], { encoding: 'utf8' });
  return JSON.parse(out.trim().split('\n').pop()).ms;
}

// Runs in the page: the box, geocdt and d3-delaunay alternating (warm: medians of `rounds`), or
// one contender's first call (cold). Wall time.
async function inPage(mode, sites, clip, rounds) {
  const { init: start, voronoi: cells } = await import('geocdt');
  const { Delaunay: D3 } = await import('d3-delaunay');
  await start({ warmUp: false });
  let s = 12345;
  const points = new Float64Array(2 * sites);
  for (let i = 0; i < 2 * sites; i++) {
    s = (s * 16807) % 2147483647;
    points[i] = (s / 2147483647) * 1000;
  }
  const runs = {
    geocdt: () => cells({ points }, { clip }),
    d3: () => {
      const diagram = new D3(points).voronoi(clip);
      let vertices = 0;
      for (let i = 0; i < sites; i++) vertices += diagram.cellPolygon(i)?.length ?? 0;
      return vertices;
    },
  };
  const timed = (name) => {
    const started = performance.now();
    runs[name]();
    return performance.now() - started;
  };
  if (mode !== 'warm') return timed(mode);
  const times = { geocdt: [], d3: [] };
  const names = Object.keys(times);
  for (let r = 0; r < rounds; r++) {
    for (let k = 0; k < names.length; k++) {
      const name = names[(k + r) % names.length];
      times[name].push(timed(name));
    }
  }
  const middle = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
  return { geocdt: middle(times.geocdt), d3: middle(times.d3) };
}

const d3Module = { 'd3-delaunay': '/node_modules/d3-delaunay/dist/d3-delaunay.mjs' };
const pageRun = (mode) => inChromium(inPage, [mode, count, box, rounds], { imports: d3Module });

// The box as users meet it first, and in Chromium: rows for the targets table.
async function firstAndBrowser() {
  const rows = [];
  const row = (what, g, d) => rows.push([`${n(count)} uniform sites clipped to a box, ${what}`,
    `${g.toFixed(0)} ms against d3-delaunay's ${d.toFixed(0)} ms: ${ratio(g, d)}×`, '≤ 0.3×',
    verdict(g / d <= 0.3)]);
  const coldMedians = async (once) => {
    const times = { geocdt: [], d3: [] };
    for (let r = 0; r < coldRuns; r++) {
      for (const name of Object.keys(times)) times[name].push(await once(name));
    }
    return [median(times.geocdt), median(times.d3)];
  };
  if (!skip.has('cold')) {
    row(`cold (the first call in a fresh Node process, median of ${coldRuns})`,
      ...await coldMedians(fresh));
  }
  if (!skip.has('chromium') && existsSync(chromiumPath())) {
    const warm = await pageRun('warm');
    row(`Chromium, warm (medians of ${rounds} alternating rounds)`, warm.geocdt, warm.d3);
    row(`Chromium, cold (the first call in a fresh page, median of ${coldRuns})`,
      ...await coldMedians(pageRun));
  }
  return rows;
}

async function main() {
  await init({ threads, warmUp: false });
  const results = [];

  // 1. A box: geocdt against d3-delaunay.
  const points = uniform(count);
  const boxTimes = alternate([
    ['geocdt', () => voronoi({ points }, { clip: box })],
    ['d3', () => d3Cells(points, box)],
  ]);
  const boxRatio = boxTimes.geocdt.wall / boxTimes.d3.wall;
  const cpu = cpuClock ? ` (main-thread CPU ${ratio(boxTimes.geocdt.cpu, boxTimes.d3.cpu)}×)` : '';
  results.push([`${n(count)} uniform sites clipped to a box`,
    `${boxTimes.geocdt.wall.toFixed(0)} ms against d3-delaunay's `
    + `${boxTimes.d3.wall.toFixed(0)} ms: ${ratio(boxTimes.geocdt.wall, boxTimes.d3.wall)}×${cpu}`,
    '≤ 0.3×', verdict(boxRatio <= 0.3)]);

  // 2. 20,000 sites and the 50m countries: the cells' area against the land's.
  const rings50 = countryRings('50m').polylines;
  const land = meshArea(triangulate({ polylines: rings50 }, { keep: 'inside' }));
  const sites50 = sitesIn(20_000, [-180, -90, 180, 84], 7);
  const cells50 = voronoi({ points: sites50, polylines: rings50 });
  const error = Math.abs(cellsArea(cells50) - land) / land;
  results.push(['20,000 sites clipped to the Natural Earth 50m country rings',
    `cells' area off the land's by ${error.toExponential(2)} (relative); `
    + `${n(cells50.stats.crossings)} crossings, ${cells50.stats.milliseconds.toFixed(0)} ms`,
    '≤ 1e-9', verdict(error <= 1e-9)]);

  // 3. 1M sites and the 10m countries, against the same sites in their box.
  const rings10 = countryRings(quick ? '50m' : '10m').polylines;
  const world = [-180, -90, 180, 84];
  const sites = sitesIn(count, world, 9);
  const ringTimes = alternate([
    ['rings', () => voronoi({ points: sites, polylines: rings10 })],
    ['box', () => voronoi({ points: sites }, { clip: world })],
  ]);
  const ringRatio = ringTimes.rings.wall / ringTimes.box.wall;
  const ringCpu = cpuClock ? ` (CPU ${ratio(ringTimes.rings.cpu, ringTimes.box.cpu)}×)` : '';
  results.push([`${n(count)} sites clipped to the Natural Earth ${quick ? '50m' : '10m'} rings`,
    `${ringTimes.rings.wall.toFixed(0)} ms against ${ringTimes.box.wall.toFixed(0)} ms `
    + 'in their box: '
    + `${ratio(ringTimes.rings.wall, ringTimes.box.wall)}×${ringCpu}`, '≤ 2×',
    verdict(ringRatio <= 2)]);

  results.push(...await firstAndBrowser());

  console.log(`Voronoi cells, ${rounds} rounds, medians${threads > 1 ? `, ${threads} threads` : ''}`
    + `${quick ? ' (--quick: 200,000 sites, the 50m rings for the third row)' : ''}\n`);
  console.log('| target | measured | goal | |');
  console.log('| --- | --- | --: | --- |');
  for (const row of results) console.log(`| ${row.join(' | ')} |`);
}

if (process.argv.includes('--first')) await first(option('--first'));
else await main();
