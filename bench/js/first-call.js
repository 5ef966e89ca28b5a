// The first call in a fresh process against a warm one, as a user who calls once sees it: each
// run starts a new Node process (and a new Chromium browser), times `await init()`, the first
// triangulate() and then warm calls, and reports medians over the runs. delaunator runs the
// same way, on the same points, for context.
//   node bench/js/first-call.js [--runs N] [--node] [--chromium] [--quick] [--baseline DIR]
//     [--delay MS] [--threads N] [--running-browser]
// --node or --chromium runs only that engine; --quick runs only the Natural Earth 50m rings;
// --baseline DIR also runs another build of the package (a folder holding its web/) in the
// same rounds, for a before/after; --delay MS waits that long between init() and the first
// call, as a page or script that loads its data after init() does (default 0); --threads N
// passes init({ threads: N }) (the threaded build; in Chromium the page is then served
// cross-origin isolated); --running-browser starts Chromium once and opens each run's page in
// a fresh context of that browser (a new renderer process), as a user's visit to a page
// does, instead of starting a browser per run, whose own start-up competes with the page.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { median, threadCpuClock } from './timing.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const root = resolve(new URL('../..', import.meta.url).pathname);
const packageDir = resolve(option('--package', root));
const baselineDir = option('--baseline', null) && resolve(option('--baseline', null));
const runs = Number(option('--runs', 5));
const warmCalls = 6;
const delayMs = Number(option('--delay', 0));
const threads = Number(option('--threads', 1));
const runningBrowser = process.argv.includes('--running-browser');

// Each dataset is { points } or { polylines: { coords, offsets } } (the flat form), made in
// Node and handed to the browser as bytes; delaunator gets the same points, unconstrained.
const DATASETS = {
  'ne50m-rings': { title: 'Natural Earth 50m country rings', scale: '50m' },
  'ne10m-rings': { title: 'Natural Earth 10m country rings', scale: '10m' },
  'uniform-1m': { title: '1,000,000 uniform points', uniform: 1_000_000 },
};

async function makeDataset(name) {
  const d = DATASETS[name];
  const { countryRings, flatPolylines, uniformLehmer } = await import('./datasets.js');
  if (d.uniform) return { points: uniformLehmer(d.uniform) };
  return { polylines: flatPolylines(countryRings(d.scale).polylines) };
}

// The dataset as bytes: [kind (0 points, 1 polylines), count] as two uint32, then the
// coordinates, then (polylines) the offsets.
function encode(input) {
  const coords = input.points ?? input.polylines.coords;
  const offsets = input.polylines?.offsets ?? new Uint32Array(0);
  const head = new Uint32Array([input.points ? 0 : 1, offsets.length]);
  return Buffer.concat([head, coords, offsets].map((a) => Buffer.from(a.buffer, a.byteOffset,
    a.byteLength)));
}

// --- What runs in the fresh process or page (no imports: it is also sent to the browser). ---

// load(): imports a library and returns { initMs, run(input) }. Times init, the first call,
// then warmCalls more; warm is the median of the last warmCalls - 1 (the second call can still
// run code that is being optimised). cpuClock, when given, reads the main thread's CPU time
// in ms: steadier than the wall clock on a loaded machine, but blind to the compiler's threads.
// delayMs: the wait between init and the first call.
async function measureOnce(bytes, load, warmCalls, delayMs, cpuClock) {
  const head = new Uint32Array(bytes, 0, 2);
  const offsetCount = head[1];
  const coordBytes = bytes.byteLength - 8 - 4 * offsetCount;
  const coords = new Float64Array(bytes, 8, coordBytes / 8);
  const input = head[0] === 0 ? { points: coords }
    : { polylines: { coords, offsets: new Uint32Array(bytes, 8 + coordBytes, offsetCount) } };
  const gc = () => globalThis.gc?.();
  const { initMs, run } = await load();
  if (delayMs > 0) await new Promise((done) => setTimeout(done, delayMs));
  const times = [];
  const cpu = [];
  for (let i = 0; i <= warmCalls; i++) {
    gc();
    const started = performance.now();
    const cpuStarted = cpuClock?.();
    run(input);
    if (cpuClock) cpu.push(cpuClock() - cpuStarted);
    times.push(performance.now() - started);
  }
  const warm = (values) => {
    const w = values.slice(2).sort((a, b) => a - b);
    const m = w.length >> 1;
    return w.length % 2 ? w[m] : (w[m - 1] + w[m]) / 2;
  };
  const result = { initMs, firstMs: times[0], secondMs: times[1], warmMs: warm(times) };
  if (cpuClock) Object.assign(result, { firstCpuMs: cpu[0], warmCpuMs: warm(cpu) });
  return result;
}

function loader(library, geocdtUrl, delaunatorUrl, threads) {
  return async () => {
    if (library === 'geocdt') {
      const api = await import(geocdtUrl);
      const started = performance.now();
      await api.init(threads > 1 ? { threads } : undefined);
      const initMs = performance.now() - started;
      return { initMs, run: (input) => api.triangulate(input) };
    }
    const { default: Delaunator } = await import(delaunatorUrl);
    return { initMs: 0, run: (input) => new Delaunator(input.points ?? input.polylines.coords) };
  };
}

// --- Node: one fresh process per run. ---

async function child(library, dataset) {
  const bytes = encode(await makeDataset(dataset));
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const geocdtUrl = pathToFileURL(join(packageDir, 'web/index.node.js')).href;
  const load = loader(library, geocdtUrl, 'delaunator', threads);
  const result = await measureOnce(buffer, load, warmCalls, delayMs, threadCpuClock());
  console.log(JSON.stringify(result));
}

function inNode(library, dataset) {
  const args = ['--expose-gc', new URL(import.meta.url).pathname, '--child',
    library === 'baseline' ? 'geocdt' : library, dataset,
    '--package', library === 'baseline' ? baselineDir : packageDir, '--delay', String(delayMs),
    '--threads', String(threads)];
  return JSON.parse(execFileSync(process.execPath, args, { encoding: 'utf8' }));
}

// --- Chromium: one fresh browser per run, serving the package and the dataset's bytes. ---

const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm' };
const PAGE = `<!doctype html><script type="importmap">{"imports": {
  "robust-predicates": "/node_modules/robust-predicates/index.js"}}</script><p>first call</p>`;

function serve(data) {
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url, 'http://x').pathname);
    let body = null;
    let type = 'application/octet-stream';
    try {
      if (path === '/') [body, type] = [PAGE, MIME['.html']];
      else if (path.startsWith('/data/')) body = data.get(path.slice(6));
      else if (path.startsWith('/package/') || path.startsWith('/baseline/')) {
        const [folder, rest] = path.startsWith('/package/') ? [packageDir, path.slice(9)]
          : [baselineDir, path.slice(10)];
        body = readFileSync(join(folder, rest));
        type = MIME[extname(path)] ?? type;
      } else if (path.startsWith('/node_modules/')) {
        body = readFileSync(join(root, path));
        type = MIME[extname(path)] ?? type;
      }
    } catch {
      body = null;
    }
    if (body == null) return response.writeHead(404).end();
    const isolation = threads > 1 ? {
      'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp',
    } : {};
    response.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-store', ...isolation });
    response.end(body);
  });
  return new Promise((done) => server.listen(0, '127.0.0.1', () => done(server)));
}

async function launchChromium() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--js-flags=--expose-gc'],
  });
}

// running: a browser started before, or null to start one for this run alone. In a running
// browser each run gets a context of its own: a new renderer process, with empty caches.
async function inChromium(server, library, dataset, running) {
  const browser = running ?? await launchChromium();
  const context = running ? await running.newContext() : null;
  try {
    const page = await (context ?? browser).newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    return await page.evaluate(async ([measureSource, loaderSource, lib, name, calls, delay,
      threadCount]) => {
      const make = (source) => new Function(`return (${source})`)();
      const bytes = await (await fetch(`/data/${name}`)).arrayBuffer();
      const load = make(loaderSource)(lib === 'baseline' ? 'geocdt' : lib,
        `/${lib === 'baseline' ? 'baseline' : 'package'}/web/index.browser.js`,
        '/node_modules/delaunator/index.js', threadCount);
      return make(measureSource)(bytes, load, calls, delay);
    }, [measureOnce.toString(), loader.toString(), library, dataset, warmCalls, delayMs,
      threads]);
  } finally {
    await (context ?? browser).close();
  }
}

// --- The report. ---

const fmt = (x) => (x < 10 ? x.toFixed(1) : x.toFixed(0));

function report(engine, title, results) {
  const fresh = engine === 'Node' ? 'processes'
    : runningBrowser ? 'pages, each in a context of its own in one running browser' : 'browsers';
  const delay = delayMs > 0 ? `, first call ${delayMs} ms after init` : '';
  console.log(`### ${engine}: ${title} (${runs} fresh ${fresh}, medians${delay})\n`);
  const cpu = Object.values(results)[0][0].firstCpuMs !== undefined;
  console.log(`| library | init ms | first call ms | second ms | warm ms | first / warm |${
    cpu ? ' first / warm, main thread CPU |' : ''}`);
  console.log(`| --- | --: | --: | --: | --: | --: |${cpu ? ' --: |' : ''}`);
  for (const [library, rs] of Object.entries(results)) {
    const m = (key) => median(rs.map((r) => r[key]));
    const ratio = (a, b) => {
      const q = rs.map((r) => r[a] / r[b]);
      return `${median(q).toFixed(2)}× (${Math.min(...q).toFixed(2)}–${Math.max(...q).toFixed(2)})`;
    };
    console.log(`| ${library} | ${library !== 'delaunator' ? fmt(m('initMs')) : ''} | `
      + `${fmt(m('firstMs'))} | ${fmt(m('secondMs'))} | ${fmt(m('warmMs'))} | `
      + `${ratio('firstMs', 'warmMs')} |${cpu ? ` ${ratio('firstCpuMs', 'warmCpuMs')} |` : ''}`);
  }
  console.log();
}

async function main() {
  const datasets = process.argv.includes('--quick') ? ['ne50m-rings'] : Object.keys(DATASETS);
  const only = ['--node', '--chromium'].filter((f) => process.argv.includes(f));
  const engines = only.length ? only.map((f) => f.slice(2)) : ['node', 'chromium'];
  const libraries = ['geocdt', ...(baselineDir ? ['baseline'] : []), 'delaunator'];
  const data = new Map();
  const server = engines.includes('chromium') ? await serve(data) : null;
  let running = null;
  if (engines.includes('chromium') && runningBrowser) {
    running = await launchChromium();
    // Its start-up work done before the first run, as in a browser the user has open.
    await new Promise((done) => setTimeout(done, 3000));
  }
  try {
    for (const engine of engines) {
      for (const dataset of datasets) {
        if (engine === 'chromium' && !data.has(dataset)) {
          data.set(dataset, encode(await makeDataset(dataset)));
        }
        const results = Object.fromEntries(libraries.map((l) => [l, []]));
        for (let r = 0; r < runs; r++) {
          for (const library of libraries) {
            results[library].push(engine === 'node' ? inNode(library, dataset)
              : await inChromium(server, library, dataset, running));
          }
        }
        report(engine === 'node' ? 'Node' : 'Chromium', DATASETS[dataset].title, results);
      }
    }
  } finally {
    await running?.close();
    server?.close();
  }
}

const at = process.argv.indexOf('--child');
if (at >= 0) await child(process.argv[at + 1], process.argv[at + 2]);
else await main();
