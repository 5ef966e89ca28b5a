// onProgress: phases in order, each named, fractions growing, one report per 100 ms, nothing
// when absent; in the main API, the incremental class and the worker (worker_threads).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation, GeocdtError } from 'geocdt';
import { createWorker } from 'geocdt/worker';
import { checkProgressEvents, PHASES } from './support/progress.js';
import { random, uniform } from './support/inputs.js';

before(() => init());

const worker = createWorker();
after(() => worker.terminate());

// Short segments in a 1000-wide square: a few crossings, a constraints phase of its own.
function segments(n, seed) {
  const rnd = random(seed);
  return Array.from({ length: n }, () => {
    const x = rnd() * 980, y = rnd() * 980;
    return [x, y, x + rnd() * 20, y + rnd() * 20];
  });
}

// Records each report with the time it arrived.
function recorder() {
  const events = [];
  const times = [];
  return {
    events,
    times,
    onProgress: (e) => {
      times.push(performance.now());
      events.push(e);
    },
  };
}

test('triangulate names every phase in order, fractions growing, one per 100 ms within one', () => {
  // Enough points that inserting them takes well over 100 ms on a fast machine too, so that
  // a report inside the phase is due.
  const input = { points: uniform(1_500_000, 41), polylines: segments(3_000, 42) };
  const r = recorder();
  const started = performance.now();
  const mesh = triangulate(input, { onProgress: r.onProgress });
  const elapsed = performance.now() - started;
  checkProgressEvents(r.events);
  assert.equal(r.events[0].phase, 'sort');
  assert.deepEqual(r.events.at(-1), { phase: 'export', fraction: 1 });
  assert.ok(r.events.some((e) => e.phase === 'points' && e.fraction > 0 && e.fraction < 1),
    JSON.stringify(r.events));
  // Every phase that ran is named, however short it was.
  assert.deepEqual([...new Set(r.events.map((e) => e.phase))], PHASES, JSON.stringify(r.events));
  // Each phase's first report, then one per 100 ms at most within it, then the last.
  assert.ok(r.events.length <= 1 + PHASES.length + elapsed / 100,
    `${r.events.length} in ${elapsed} ms`);
  for (let i = 1; i + 1 < r.times.length; i++) {
    if (r.events[i].phase !== r.events[i - 1].phase) continue;
    assert.ok(r.times[i] - r.times[i - 1] >= 99, `reports ${i - 1} and ${i} too close`);
  }
  const quiet = triangulate(input);
  assert.deepEqual(quiet.triangles, mesh.triangles, 'the same result without onProgress');
});

test('a small call reports each phase as it begins, then its last state', () => {
  const r = recorder();
  triangulate({ points: [0, 0, 1, 0, 0, 1], polylines: [[0, 0, 1, 1]] },
    { onProgress: r.onProgress });
  checkProgressEvents(r.events);
  const begun = r.events.filter((e, i) => i === 0 || e.phase !== r.events[i - 1].phase);
  assert.deepEqual(begun.map((e) => e.phase), PHASES, JSON.stringify(r.events));
  assert.ok(r.events.length <= PHASES.length + 1, JSON.stringify(r.events));
  assert.deepEqual(r.events.at(-1), { phase: 'export', fraction: 1 });
});

test('the incremental calls report their phases', () => {
  const t = new Triangulation();
  let r = recorder();
  t.insertPoints(uniform(200_000, 43), { onProgress: r.onProgress });
  checkProgressEvents(r.events);
  assert.deepEqual(r.events.at(-1), { phase: 'points', fraction: 1 });
  r = recorder();
  t.insertPolyline([1, 1, 999, 999, 1, 999, 1, 1], { onProgress: r.onProgress });
  checkProgressEvents(r.events);
  assert.deepEqual(r.events.at(-1), { phase: 'constraints', fraction: 1 });
  r = recorder();
  t.results({ keep: 'inside', onProgress: r.onProgress });
  checkProgressEvents(r.events);
  assert.ok(r.events.every((e) => e.phase === 'export'));
  assert.deepEqual(r.events.at(-1), { phase: 'export', fraction: 1 });
  t.dispose();
});

test('an exception from onProgress stops the reports and is thrown when the call returns', () => {
  const problem = new Error('stop');
  let calls = 0;
  const onProgress = () => {
    calls++;
    throw problem;
  };
  assert.throws(() => triangulate({ points: uniform(1_000, 44) }, { onProgress }), problem);
  assert.equal(calls, 1);
  const t = new Triangulation();
  assert.throws(() => t.insertPoints(uniform(1_000, 45), { onProgress }), problem);
  assert.equal(t.vertexCount, 1_000, 'the insertion itself was done');
  assert.equal(t.results().triangles.length / 3, t.triangleCount);
  t.dispose();
});

test('calling geocdt from inside onProgress throws a Busy GeocdtError', () => {
  const t = new Triangulation();
  t.insertPoints([0, 0, 10, 0, 0, 10]);
  const errors = [];
  const attempt = (f) => {
    try {
      f();
    } catch (e) {
      errors.push(e);
    }
  };
  triangulate({ points: uniform(1_000, 46) }, {
    onProgress: () => {
      attempt(() => triangulate({ points: [0, 0, 1, 0, 0, 1] }));
      attempt(() => t.locate(1, 1));
    },
  });
  assert.ok(errors.length >= 2);
  for (const e of errors) {
    assert.ok(e instanceof GeocdtError, String(e));
    assert.equal(e.code, 'Busy');
  }
  assert.equal(t.locate(1, 1).kind, 'face', 'usable again once the call returned');
  t.dispose();
});

test('onProgress must be a function', () => {
  assert.throws(() => triangulate({ points: [0, 0] }, { onProgress: 'yes' }),
    { name: 'TypeError', message: /options.onProgress must be a function/ });
  const t = new Triangulation();
  assert.throws(() => t.insertPoints([0, 0], { onProgress: 1 }), TypeError);
  t.dispose();
});

test('the worker passes progress on (worker_threads)', async () => {
  const r = recorder();
  const input = { points: uniform(300_000, 47), polylines: segments(1_000, 48) };
  const mesh = await worker.triangulate(input, { onProgress: r.onProgress });
  assert.ok(mesh.triangles.length > 0);
  checkProgressEvents(r.events);
  assert.deepEqual(r.events.at(-1), { phase: 'export', fraction: 1 });
  assert.ok(new Set(r.events.map((e) => e.phase)).size >= 2, JSON.stringify(r.events));

  const t = worker.createTriangulation();
  const inserted = recorder();
  await t.insertPoints(uniform(100_000, 49), { onProgress: inserted.onProgress });
  checkProgressEvents(inserted.events);
  const exported = recorder();
  await t.results({ onProgress: exported.onProgress });
  assert.deepEqual(exported.events.at(-1), { phase: 'export', fraction: 1 });
  await t.dispose();
});

test('in the worker, an exception from onProgress rejects the call', async () => {
  const problem = new Error('no more');
  await assert.rejects(worker.triangulate({ points: uniform(1_000, 50) },
    { onProgress: () => { throw problem; } }), problem);
  const r = await worker.triangulate({ points: [0, 0, 1, 0, 0, 1] });
  assert.equal(r.triangles.length, 3, 'the worker still works');
});
