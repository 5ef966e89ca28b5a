// The Node entry: reads the wasm bytes from the package folder (the generated glue cannot
// load them in Node 20 by itself), compiles them, and instantiates the compiled module, which
// the warm-up's worker shares.
import { readdirSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { availableParallelism, setPriority } from 'node:os';
import { Worker } from 'node:worker_threads';
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi, kAutoThreads } from './api.js';
import { PthreadWorker } from './pthread-worker.node.js';
import { instantiateCompiled, instantiateWithWarmUp, threadedSettings } from './warm-up.js';

export { geoJSONToInput, meshToGeoJSON } from './geojson.js';
export { cellsToGeoJSON } from './voronoi-geojson.js';
export { GeocdtError } from './errors.js';

// The threads of this process (Linux), or null.
function threadIds() {
  try {
    return new Set(readdirSync('/proc/self/task'));
  } catch {
    return null;
  }
}

// Gives the threads started since `before` (the warm-up's) the lowest priority, from their
// start on, so that the warm-up takes no core from the caller's first call when cores are
// short: starting a worker alone takes tens of milliseconds of a core.
function lowestPriority(before) {
  if (before === null) return;
  for (const id of threadIds() ?? []) {
    if (before.has(id)) continue;
    try {
      setPriority(Number(id), 19);
    } catch {
      // The warm-up keeps the priority it has.
    }
  }
}

// Starts the warm-up (web/warm-up.js) on the compiled module. Nothing waits for it: the
// worker never keeps the process alive, and an error in it (no worker_threads, no memory) only
// means no warm-up.
function startWarmUp(module) {
  if (availableParallelism() < 2) return;
  try {
    // No flags of node's own: V8's apply to every thread anyway, and a worker refuses some
    // (--expose-gc), which would leave the warm-up out.
    const before = threadIds();
    const worker = new Worker(new URL('./warm-up-thread.node.js', import.meta.url),
      { execArgv: [] });
    lowestPriority(before);
    worker.unref();
    worker.on('error', () => {});
    worker.postMessage({ module });
  } catch {
    // No warm-up.
  }
}

// The threaded build, with a pool of threads - 1 workers (the calling thread is the first).
// Its glue starts the pool's workers as it is created, with the browser's Worker, which
// stands in only for that moment.
async function instantiateThreaded(threads) {
  const glue = new URL('./dist/geocdt-threads.mjs', import.meta.url);
  const { default: createThreadedModule } = await import(glue.href);
  const module = await WebAssembly.compile(
    await readFile(new URL('./dist/geocdt-threads.wasm', import.meta.url)));
  const pool = [];
  const had = Object.hasOwn(globalThis, 'Worker');
  const before = globalThis.Worker;
  globalThis.Worker = class extends PthreadWorker {
    constructor(url) {
      super(url);
      pool.push(this);
    }
  };
  let ready;
  try {
    ready = instantiateCompiled(createThreadedModule, module,
      threadedSettings(threads, glue.href));
  } finally {
    if (had) globalThis.Worker = before;
    else delete globalThis.Worker;
  }
  const wasm = await ready;
  for (const worker of pool) worker.unref();
  return wasm;
}

async function instantiate(options) {
  const threads = options.threads === 'auto'
    ? Math.min(availableParallelism(), kAutoThreads) : options.threads ?? 1;
  if (threads > 1) return { wasm: await instantiateThreaded(threads), threads };
  const { wasmUrl } = options;
  const where = wasmUrl === undefined ? new URL('./dist/geocdt.wasm', import.meta.url)
    : typeof wasmUrl === 'string' ? wasmUrl : new URL(wasmUrl.href);
  const module = await WebAssembly.compile(options.wasmBinary ?? await readFile(where));
  return instantiateWithWarmUp(createGeocdtModule, module, options, startWarmUp);
}

export const {
  init, triangulate, triangulatePolygons, earcut, triangulateRaster, triangulateGeoJSON, voronoi,
  voronoiGeoJSON, memoryUsage, Triangulation,
} = createApi(instantiate);
