// The browser and web-worker entry. The wasm is fetched from beside this file; bundlers see
// the `new URL(..., import.meta.url)` and ship it (and the warm-up's worker) as assets.
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi } from './api.js';
import { instantiateCompiled } from './warm-up.js';

export { geoJSONToInput, meshToGeoJSON } from './geojson.js';
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
// when the bytes are given) from the whole buffer.
async function compile(options) {
  if (options.wasmBinary) return WebAssembly.compile(options.wasmBinary);
  const { wasmUrl } = options;
  const url = wasmUrl === undefined ? new URL('./dist/geocdt.wasm', import.meta.url).href
    : typeof wasmUrl === 'string' ? wasmUrl : wasmUrl.href;
  const response = await fetch(url, { credentials: 'same-origin' });
  if (!response.ok) throw new Error(`geocdt: could not fetch ${url}: HTTP ${response.status}`);
  const wasm = response.headers.get('Content-Type')?.startsWith('application/wasm');
  if (wasm && typeof WebAssembly.compileStreaming === 'function') {
    return WebAssembly.compileStreaming(response);
  }
  return WebAssembly.compile(await response.arrayBuffer());
}

async function instantiate(options) {
  const module = await compile(options);
  const wasm = await instantiateCompiled(createGeocdtModule, module);
  // After the code that awaits init() has run to its first wait: a call made at once finds
  // both cores free (the warm-up would only compete with it, bench/EXPERIMENTS.md), and a
  // caller that loads its data first gets the warm-up meanwhile.
  if (options.warmUp !== false) setTimeout(() => startWarmUp(module), 0);
  return { wasm, threads: 1 };
}

export const { init, triangulate, triangulateGeoJSON, memoryUsage, Triangulation } =
  createApi(instantiate);
