// The warm-up (web/warm-up.js): init() starts a worker on the module it compiled and does not
// wait for it; the worker makes what the same calls make here, never keeps the process
// alive, and init({ warmUp: false }) starts none.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { once } from 'node:events';
import { readFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import * as geocdt from 'geocdt';
import { runWarmUp } from '../../web/warm-up.js';

const runModule = (script) => execFileSync(process.execPath,
  ['--input-type=module', '-e', script], { encoding: 'utf8', timeout: 60_000 });

test('the warm-up worker runs on the module it is sent, makes what runs here, and exits',
  async () => {
    const bytes = readFileSync(new URL('../../web/dist/geocdt.wasm', import.meta.url));
    const worker = new Worker(new URL('../../web/warm-up-thread.node.js', import.meta.url));
    const errors = [];
    worker.on('error', (error) => errors.push(error));
    const report = once(worker, 'message');
    worker.postMessage({ module: await WebAssembly.compile(bytes) });
    const [{ triangles }] = await report;
    const [code] = await once(worker, 'exit');
    assert.deepEqual(errors, []);
    assert.equal(code, 0);
    await geocdt.init({ warmUp: false });
    assert.equal(triangles, runWarmUp(geocdt));
    assert.ok(triangles > 100_000, `${triangles} triangles`);
  });

// In a fresh process: the threads started by init() before the caller's code after it waits
// for anything, those started once it has waited, and what its call returned.
function threadsAfterInit(options) {
  const script = `
    import { readFileSync } from 'node:fs';
    import { init, triangulate } from 'geocdt';
    const threads = () => Number(/Threads:\\s+(\\d+)/.exec(
      readFileSync('/proc/self/status', 'utf8'))[1]);
    const before = threads();
    await init(${JSON.stringify(options)});
    const atOnce = threads();
    await new Promise((done) => setTimeout(done, 0));
    const later = threads();
    const { triangles } = triangulate({ polylines: [[0, 0, 4, 4], [0, 4, 4, 0]] });
    console.log(atOnce - before, later - before, triangles.length / 3);`;
  return runModule(script).trim().split(' ').map(Number);
}

// The worker starts once the caller's code has waited (for its data, say): a call made at
// once has the cores to itself. With one core there is no warm-up.
test('init() starts one worker once the caller has waited, none with warmUp: false',
  () => {
    const [atOnce, later, triangles] = threadsAfterInit({});
    const [atOnceWithout, laterWithout, trianglesWithout] = threadsAfterInit({ warmUp: false });
    assert.equal(atOnce, atOnceWithout);
    assert.equal(later, laterWithout + (availableParallelism() > 1 ? 1 : 0));
    assert.deepEqual([triangles, trianglesWithout], [4, 4]);
  });

test('options.warmUp must be a boolean; a refused init() can be retried', () => {
  const script = `
    import { init, triangulate } from 'geocdt';
    const out = [];
    await init({ warmUp: 'no' }).catch((e) => out.push(e.constructor.name, e.message));
    await init({ warmUp: true });
    out.push(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length);
    console.log(out.join('|'));`;
  assert.equal(runModule(script).trim(),
    'TypeError|geocdt: options.warmUp must be a boolean, got string|3');
});
