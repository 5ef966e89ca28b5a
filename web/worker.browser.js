// geocdt/worker for browsers: the calls run in a module Web Worker. Bundlers (Vite, webpack,
// Rollup plugins) recognise the `new Worker(new URL(...), { type: 'module' })` form and bundle
// the worker with the wasm it loads.
import { checkOptionNames } from './call-options.js';
import { GeocdtWorker } from './worker-client.js';
import { GeocdtError } from './errors.js';
import { threadsError } from './input.js';

export { GeocdtWorker, RemoteTriangulation } from './worker-client.js';
export { GeocdtError } from './errors.js';

// options.threads: as init()'s (the worker loads the threaded build where it can).
export function createWorker(options) {
  checkOptionNames(options, 'createWorker()');
  const wrongThreads = threadsError(options?.threads);
  if (wrongThreads) throw wrongThreads;
  // Written in the one form bundlers recognise: the URL inline in the Worker call.
  const worker = new Worker(new URL('./worker-thread.browser.js', import.meta.url), {
    type: 'module',
  });
  const client = new GeocdtWorker({
    post: (message, transfer) => worker.postMessage(message, transfer),
    busy: () => {},
    terminate: () => worker.terminate(),
  });
  if (options?.threads !== undefined) {
    worker.postMessage({ op: 'configure', args: [{ threads: options.threads }] });
  }
  worker.addEventListener('message', (event) => client.receive(event.data));
  worker.addEventListener('error', (event) => {
    event.preventDefault?.();
    client.fail(new GeocdtError('WorkerFailed',
      `geocdt: the worker failed: ${event.message ?? 'could not load'}`));
  });
  return client;
}
