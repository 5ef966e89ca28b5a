// triangle-wasm runs in a worker thread: on bad input Triangle calls exit(), which would end
// the whole benchmark process; in a worker it ends only the worker.
import { parentPort, workerData } from 'node:worker_threads';
import * as peers from './peers.js';

await peers.initTriangle();
parentPort.on('message', (graph) => {
  const started = performance.now();
  const mesh = peers.triangle(graph);
  const ms = performance.now() - started;
  const output = graph.switches?.quality
    ? peers.refinedSummary(graph.xy.length / 2, mesh) : peers.summary(mesh);
  parentPort.postMessage({ output, ms });
});
void workerData;
