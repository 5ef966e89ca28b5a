// triangle-wasm runs in a worker thread: on bad input Triangle calls exit(), which would end
// the whole benchmark process; in a worker it ends only the worker.
import { parentPort, workerData } from 'node:worker_threads';
import * as peers from './peers.js';

await peers.initTriangle();
parentPort.on('message', (graph) => {
  const started = performance.now();
  const mesh = peers.triangle(graph);
  const ms = performance.now() - started;
  parentPort.postMessage({ output: peers.summary(mesh), ms });
});
void workerData;
