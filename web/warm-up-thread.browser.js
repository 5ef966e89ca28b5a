// The script of the warm-up's module Web Worker (started by web/index.browser.js):
// it takes the module init() compiled by message, runs the warm-up on it, and closes, saying how
// many triangles it made.
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi } from './api.js';
import { instantiateCompiled, runWarmUp } from './warm-up.js';

self.addEventListener('message', async ({ data }) => {
  try {
    const api = createApi(async () => ({
      wasm: await instantiateCompiled(createGeocdtModule, data.module), threads: 1,
    }));
    await api.init({ warmUp: false });
    self.postMessage({ triangles: runWarmUp(api) });
  } finally {
    self.close();
  }
}, { once: true });
