// geocdt/worker for Node: the calls run in a worker_threads Worker. The worker does not keep
// the process alive while no request is pending.
import { Worker } from 'node:worker_threads';
import { checkOptionNames } from './call-options.js';
import { GeocdtWorker } from './worker-client.js';
import { GeocdtError } from './errors.js';
import { threadsError } from './input.js';

export { GeocdtWorker, RemoteTriangulation } from './worker-client.js';
export { GeocdtError } from './errors.js';

// The worker inherits node's flags, except those that only make sense for an inline script.
function workerFlags() {
  const flags = [];
  for (let i = 0; i < process.execArgv.length; i++) {
    const flag = process.execArgv[i];
    if (/^(-e|--eval|-p|--print)$/.test(flag)) i++;
    else if (!/^(--input-type|--eval|--print)(=|$)/.test(flag)) flags.push(flag);
  }
  return flags;
}

// options.threads: as init()'s (the worker loads the threaded build).
export function createWorker(options) {
  checkOptionNames(options, 'createWorker()');
  const wrongThreads = threadsError(options?.threads);
  if (wrongThreads) throw wrongThreads;
  const url = new URL('./worker-thread.node.js', import.meta.url);
  const worker = new Worker(url, { execArgv: workerFlags() });
  const client = new GeocdtWorker({
    post: (message, transfer) => worker.postMessage(message, transfer),
    busy: (isBusy) => (isBusy ? worker.ref() : worker.unref()),
    terminate: () => worker.terminate(),
  });
  if (options?.threads !== undefined) {
    worker.postMessage({ op: 'configure', args: [{ threads: options.threads }] });
  }
  worker.unref();
  worker.on('message', (message) => client.receive(message));
  worker.on('error', (error) => client.fail(new GeocdtError('WorkerFailed',
    `geocdt: the worker failed: ${error?.message ?? error}`, { cause: error })));
  worker.on('exit', (code) => client.fail(
    new GeocdtError('WorkerFailed', `geocdt: the worker exited (code ${code})`)));
  return client;
}
