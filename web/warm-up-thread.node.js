// The script of the warm-up's worker_threads Worker (started by web/index.node.js):
// it takes the module init() compiled by message, runs the warm-up on it, and exits, saying how
// many triangles it made.
import { parentPort } from 'node:worker_threads';
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi } from './api.js';
import { instantiateCompiled, runWarmUp } from './warm-up.js';

parentPort.once('message', async ({ module }) => {
  const api = createApi(async () => ({
    wasm: await instantiateCompiled(createGeocdtModule, module), threads: 1,
  }));
  await api.init({ warmUp: false });
  parentPort.postMessage({ triangles: runWarmUp(api) });
});
