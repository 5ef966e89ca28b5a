// The threaded build's glue starts its pool with the browser's `new Worker(url)`, and its
// worker script speaks the browser's worker API (self, postMessage, onmessage). Node has
// neither: this class gives the glue a browser-style worker over worker_threads, only while
// web/index.node.js creates the threaded module.
import { Worker as NodeWorker } from 'node:worker_threads';

// What each pool thread runs first: the browser names the worker script expects, then the
// script itself (read from the package, so that it resolves the glue by absolute URL).
const bootstrap = `
const { parentPort, workerData } = require('node:worker_threads');
const { readFileSync } = require('node:fs');
const { fileURLToPath } = require('node:url');
globalThis.self = globalThis;
globalThis.postMessage = (message, transfer) => parentPort.postMessage(message, transfer);
parentPort.on('message', (data) => {
  if (typeof self.onmessage === 'function') self.onmessage({ data });
});
(0, eval)(readFileSync(fileURLToPath(workerData.script), 'utf8'));
`;

export class PthreadWorker {
  constructor(url) {
    this.onmessage = null;
    this.onerror = null;
    this.thread = new NodeWorker(bootstrap, {
      eval: true, workerData: { script: String(url) }, execArgv: [],
    });
    this.thread.on('message', (data) => this.onmessage?.({ data }));
    this.thread.on('error', (error) => this.onerror?.(error));
  }

  // Once loaded: an idle pool must not keep the process alive when the caller is done.
  // (Not before: a pool that is loading keeps the process alive until init() resolves.)
  unref() {
    this.thread.unref();
  }

  postMessage(message, transfer) {
    this.thread.postMessage(message, transfer);
  }

  terminate() {
    this.thread.terminate();
  }
}
