// Every failure reaches the caller as a TypeError, a RangeError or a GeocdtError with a code:
// never a plain Error. Out of memory is tested in memory.test.js, Busy in progress.test.js.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { init, triangulate, Triangulation, GeocdtError } from 'geocdt';
import { createWorker, GeocdtError as WorkerGeocdtError } from 'geocdt/worker';
import { reviveError, serializeError, statusError } from '../../web/errors.js';

before(() => init());

function caught(f) {
  try {
    f();
  } catch (error) {
    return error;
  }
  assert.fail('expected an exception');
}

const NAMED = [TypeError, RangeError, GeocdtError];
const named = (error) => NAMED.includes(error.constructor);

test('GeocdtError is one class, exported by both entries', () => {
  assert.equal(WorkerGeocdtError, GeocdtError);
  const e = new GeocdtError('InternalError', 'geocdt: broken', { index: 3, segment: -1 });
  assert.ok(e instanceof Error);
  assert.equal(e.name, 'GeocdtError');
  assert.equal(e.code, 'InternalError');
  assert.equal(e.index, 3);
  assert.equal('segment' in e, false, '-1 means none');
  assert.match(String(e), /^GeocdtError: geocdt: broken$/);
});

test('core statuses become named errors with their code, index and segment', () => {
  const located = statusError('InternalError', 'polyline 4 segment 7: stuck', 4, 7);
  assert.ok(located instanceof GeocdtError);
  assert.deepEqual([located.code, located.index, located.segment], ['InternalError', 4, 7]);
  assert.equal(located.message, 'geocdt: polyline 4 segment 7: stuck');
  const internal = statusError('InternalError', 'walk found no way on', -1, -1);
  assert.ok(internal instanceof GeocdtError);
  assert.equal(internal.index, undefined);
  const memory = statusError('OutOfMemory', 'out of memory: too large', -1, -1);
  assert.equal(memory.code, 'OutOfMemory');
  assert.match(memory.message, /a WebAssembly module can address at most 4 GB$/);
  const argument = statusError('InvalidArgument', 'too many points', -1, -1);
  assert.ok(argument instanceof TypeError);
  assert.equal(argument.code, 'InvalidArgument');
  const coordinate = statusError('InvalidCoordinate', 'point 2 has x = nan', 2, -1);
  assert.ok(coordinate instanceof RangeError);
  assert.equal(coordinate.index, 2);
  assert.ok(statusError(undefined, 'unknown status', -1, -1) instanceof GeocdtError);
});

test('errors keep their class, code, index and segment through postMessage', () => {
  const errors = [
    statusError('InternalError', 'stuck', 4, 7),
    caught(() => triangulate({ points: [0, 0, NaN, 1] })),
    caught(() => triangulate({ points: 'x' })),
  ];
  for (const error of errors) {
    const back = reviveError(structuredClone(serializeError(error)));
    assert.equal(back.constructor, error.constructor);
    for (const key of ['name', 'message', 'code', 'index', 'segment']) {
      assert.equal(back[key], error[key], key);
    }
  }
  const odd = reviveError(serializeError(new SyntaxError('odd')));
  assert.ok(odd instanceof GeocdtError, 'anything else is a GeocdtError');
});

test('the JS layer\'s own failures are GeocdtErrors', () => {
  const t = new Triangulation();
  t.dispose();
  for (const f of [() => t.insertPoints([0, 0]), () => t.locate(0, 0), () => t.results(),
    () => t.vertexCount]) {
    const e = caught(f);
    assert.ok(e instanceof GeocdtError, String(e));
    assert.equal(e.code, 'Disposed');
  }
  const script = "import { triangulate } from 'geocdt'; "
    + 'try { triangulate({}); } catch (e) { console.log(e.name, e.code); }';
  const out = execFileSync(process.execPath, ['--input-type=module', '-e', script],
    { encoding: 'utf8' });
  assert.equal(out.trim(), 'GeocdtError NotLoaded');
});

test('locate() with a NaN or infinite coordinate is a RangeError', () => {
  const t = new Triangulation();
  t.insertPoints([0, 0, 10, 0, 0, 10]);
  for (const [x, y] of [[NaN, 1], [1, NaN], [Infinity, 0], [0, -Infinity]]) {
    const e = caught(() => t.locate(x, y));
    assert.ok(e instanceof RangeError, String(e));
    assert.match(e.message, /x and y must be finite numbers/);
  }
  assert.equal(t.locate(1, 1).kind, 'face');
  t.dispose();
});

test('bad input of every kind is a TypeError or a RangeError, never a plain Error', () => {
  const t = new Triangulation();
  const failures = [
    () => triangulate(null),
    () => triangulate({ points: [0, 0, 1] }),
    () => triangulate({ points: [0, 0, 1e300, 0] }),
    () => triangulate({ polylines: { coords: [0, 0], offsets: [1, 0] } }),
    () => triangulate({ polylines: [[0, 0, 1, NaN]] }),
    () => triangulate({}, { keep: 'some' }),
    () => t.insertPolyline([0, 0, NaN, 0]),
    () => t.locate('a', 0),
  ];
  for (const f of failures) {
    const e = caught(f);
    assert.ok(named(e) && !(e instanceof GeocdtError), `${e.constructor.name}: ${e.message}`);
  }
  t.dispose();
});

test('a terminated worker rejects its calls with WorkerTerminated', async () => {
  const worker = createWorker();
  const pending = worker.triangulate({ points: new Float64Array(2_000_000) });
  worker.terminate();
  for (const call of [pending, worker.triangulate({ points: [0, 0] }), worker.memoryUsage()]) {
    await assert.rejects(call, (e) => {
      assert.ok(e instanceof GeocdtError, String(e));
      assert.equal(e.code, 'WorkerTerminated');
      return true;
    });
  }
});

test('errors from the worker keep their class and code', async () => {
  const worker = createWorker();
  try {
    await assert.rejects(worker.triangulate({ points: [0, 0, Infinity, 0] }), (e) => {
      assert.ok(e instanceof RangeError);
      assert.equal(e.code, 'InvalidCoordinate');
      assert.match(e.message, /points\[2\] \(x of point 1\) is Infinity/);
      return true;
    });
    const t = worker.createTriangulation();
    await t.dispose();
    await assert.rejects(t.locate(0, 0), { name: 'GeocdtError', code: 'Disposed' });
    const remote = worker.createTriangulation();
    await assert.rejects(remote.locate(NaN, 0), { name: 'RangeError' });
    await remote.dispose();
  } finally {
    worker.terminate();
  }
});
