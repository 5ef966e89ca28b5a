// Memory exhaustion: wasm32 stops at 4 GB. The call throws a GeocdtError with code
// 'OutOfMemory', frees what it took,
// and the module goes on working. (Its own file: node --test runs it in its own process, so
// the grown heap does not weigh on the other tests.)
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation, memoryUsage, GeocdtError } from 'geocdt';

before(() => init());

// 60 million points: the input copy and the core's arrays need well over 4 GB.
function hugeInput() {
  const xy = new Float64Array(120_000_000);
  for (let i = 0; i < xy.length; i++) xy[i] = (i * 7919) & 1023;
  return xy;
}

test('out of wasm memory: a GeocdtError (OutOfMemory), and the module stays usable', () => {
  triangulate({ points: [0, 0, 1, 0, 0, 1] });
  const baseline = memoryUsage().allocatedBytes;
  const xy = hugeInput();
  assert.throws(() => triangulate({ points: xy }), (error) => {
    assert.ok(error instanceof GeocdtError, `${error.name}: ${error.message}`);
    assert.equal(error.name, 'GeocdtError');
    assert.equal(error.code, 'OutOfMemory');
    assert.match(error.message, /out of memory/);
    return true;
  });
  assert.equal(memoryUsage().allocatedBytes, baseline, 'the failed call freed what it took');

  const t = new Triangulation();
  t.insertPoints([0, 0, 1, 0, 0, 1]);
  assert.throws(() => t.insertPoints(xy), { name: 'GeocdtError', code: 'OutOfMemory' });
  t.insertPoints([0, 0, 4, 0, 0, 4, 1, 1]);
  assert.equal(t.results().triangles.length / 3, 3);
  t.dispose();

  const r = triangulate({ points: [0, 0, 1, 0, 0, 1, 1, 1] });
  assert.equal(r.triangles.length, 6);
  assert.equal(memoryUsage().allocatedBytes, baseline);
});

test('an input larger than the 4 GB address space is refused before any copy', () => {
  const baseline = memoryUsage().allocatedBytes;
  const line = new Float64Array(1_000_000).fill(1);
  const polylines = new Array(600).fill(line);  // 4.8 GB of coordinates
  assert.throws(() => triangulate({ polylines }), (error) => {
    assert.ok(error instanceof GeocdtError, `${error.name}: ${error.message}`);
    assert.equal(error.code, 'OutOfMemory');
    assert.match(error.message, /out of memory: the input alone needs 4800002404 bytes/);
    return true;
  });
  assert.equal(memoryUsage().allocatedBytes, baseline);
  assert.equal(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length, 3);
});
