// 10,000 calls, failed ones included, bring the wasm heap back to its baseline: nothing leaks.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation, memoryUsage } from 'geocdt';
import { uniform } from './support/inputs.js';

before(() => init());

test('10,000 calls leave the heap at its baseline', () => {
  triangulate({ points: uniform(64, 1) });  // let the runtime make its one-time allocations
  const baseline = memoryUsage().allocatedBytes;
  let triangles = 0;
  for (let i = 0; i < 10_000; i++) {
    const points = uniform(16 + (i % 48), i + 1);
    switch (i % 5) {
      case 0:
      case 1:
        triangles += triangulate({ points }, { insideFlags: i % 2 === 0 }).triangles.length;
        break;
      case 2:
        assert.throws(() => triangulate({ points: [...points.subarray(0, 6), NaN, 0] }),
          RangeError);
        break;
      case 3: {
        const t = new Triangulation();
        t.insertPoints(points.subarray(0, 20));
        t.insertPoints(points.subarray(20));
        t.locate(500, 500);
        triangles += t.results().triangles.length;
        t.dispose();
        break;
      }
      default: {
        const t = new Triangulation();
        assert.throws(() => t.insertPoints([0, 0, 1]), RangeError);
        t.insertPoints(points);
        t.dispose();
      }
    }
  }
  assert.ok(triangles > 0);
  assert.equal(memoryUsage().allocatedBytes, baseline, 'allocated bytes back to the baseline');
});

test('a garbage-collected Triangulation is freed by the FinalizationRegistry', async () => {
  const { setFlagsFromString } = await import('node:v8');
  const { runInNewContext } = await import('node:vm');
  setFlagsFromString('--expose-gc');
  const gc = runInNewContext('gc');
  const baseline = memoryUsage().allocatedBytes;
  (() => {
    for (let i = 0; i < 20; i++) new Triangulation().insertPoints(uniform(1_000, i + 1));
  })();
  assert.ok(memoryUsage().allocatedBytes > baseline + 20 * 1_000 * 16,
    'the triangulations hold memory');
  for (let round = 0; round < 50 && memoryUsage().allocatedBytes !== baseline; round++) {
    gc();
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
  assert.equal(memoryUsage().allocatedBytes, baseline);
});
