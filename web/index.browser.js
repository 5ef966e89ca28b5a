// The browser and web-worker entry. The wasm is fetched from beside this file; bundlers see
// the `new URL(..., import.meta.url)` and ship it (and the warm-up's worker) as assets.
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi, kAutoThreads } from './api.js';
import { instantiateCompiled, instantiateWithWarmUp, threadedSettings } from './warm-up.js';

export { geoJSONToInput, meshToGeoJSON } from './geojson.js';
export { cellsToGeoJSON } from './voronoi-geojson.js';
export { GeocdtError } from './errors.js';

// Starts the warm-up (web/warm-up.js) on the compiled module; the worker closes itself when
// done. Nothing waits for it: where workers are missing or refused (one core, a nested worker
// in an older browser, a content security policy), there is no warm-up and nothing else
// changes.
function startWarmUp(module) {
  if (typeof Worker !== 'function' || !(globalThis.navigator?.hardwareConcurrency > 1)) return;
  try {
    // Written in the one form bundlers recognise: the URL inline in the Worker call.
    const worker = new Worker(new URL('./warm-up-thread.browser.js', import.meta.url), {
      type: 'module',
    });
    worker.addEventListener('error', (event) => event.preventDefault?.());
    worker.postMessage({ module });
  } catch {
    // No warm-up.
  }
}

// Compiles while the bytes arrive where the server sends application/wasm; otherwise (or
// when the bytes are given) from the whole buffer. threaded: the threaded build's bytes.
async function compile(options, threaded) {
  if (options.wasmBinary && !threaded) return WebAssembly.compile(options.wasmBinary);
  const { wasmUrl } = options;
  const url = threaded ? new URL('./dist/geocdt-threads.wasm', import.meta.url).href
    : wasmUrl === undefined ? new URL('./dist/geocdt.wasm', import.meta.url).href
      : typeof wasmUrl === 'string' ? wasmUrl : wasmUrl.href;
  const response = await fetch(url, { credentials: 'same-origin' });
  if (!response.ok) throw new Error(`geocdt: could not fetch ${url}: HTTP ${response.status}`);
  const wasm = response.headers.get('Content-Type')?.startsWith('application/wasm');
  if (wasm && typeof WebAssembly.compileStreaming === 'function') {
    return WebAssembly.compileStreaming(response);
  }
  return WebAssembly.compile(await response.arrayBuffer());
}

// Shared memory needs a cross-origin isolated page (served with COOP: same-origin and COEP:
// require-corp); a worker of such a page is one too.
const canShareMemory = () => globalThis.crossOriginIsolated === true
  && typeof SharedArrayBuffer === 'function';

// The threaded build, with a pool of threads - 1 workers started now (the calling thread is
// the first). In a page's main thread a call then blocks it while the pool works, as any call
// does: a worker (geocdt/worker) keeps the page responsive.
// The glue, its worker script and the wasm are referenced by URL only, so that bundlers copy
// them as they are (assets) rather than bundle them: a dynamic import() of the glue would make
// every bundle of this entry a code-splitting one, which a worker bundle in Vite's default
// format cannot be. The pool's workers get their script from locateFile(), as a blob: URL of
// this page's origin: a bundler may inline the small script as a data: URL, whose worker has
// no origin and may not import the glue.
async function poolScript() {
  const script = new URL('./dist/geocdt-threads.worker.js', import.meta.url).href;
  const response = await fetch(script, { credentials: 'same-origin' });
  if (!response.ok) throw new Error(`geocdt: could not fetch ${script}: HTTP ${response.status}`);
  return URL.createObjectURL(new Blob([await response.text()], { type: 'text/javascript' }));
}

async function instantiateThreaded(options, threads) {
  const glue = new URL('./dist/geocdt-threads.mjs', import.meta.url).href;
  const [{ default: createThreadedModule }, module, script] = await Promise.all([
    import(/* @vite-ignore */ /* webpackIgnore: true */ glue), compile(options, true),
    poolScript()]);
  return instantiateCompiled(createThreadedModule, module, {
    ...threadedSettings(threads, glue),
    locateFile: (path) => (path.endsWith('.worker.js') ? script : new URL(path, glue).href),
  });
}

async function instantiate(options) {
  const threads = options.threads === 'auto'
    ? Math.min(globalThis.navigator?.hardwareConcurrency ?? 1, kAutoThreads)
    : options.threads ?? 1;
  if (threads > 1 && canShareMemory()) {
    return { wasm: await instantiateThreaded(options, threads), threads };
  }
  const module = await compile(options, false);
  return instantiateWithWarmUp(createGeocdtModule, module, options, startWarmUp);
}

export const {
  init, triangulate, triangulatePolygons, earcut, triangulateRaster, triangulateGeoJSON, voronoi,
  voronoiGeoJSON, memoryUsage, Triangulation,
} = createApi(instantiate);
