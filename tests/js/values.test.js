// Values on vertices through the JS API: insertions with values, interpolate() (linear and
// natural neighbour), rasterize(), and the worker.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation } from 'geocdt';
import { createWorker } from 'geocdt/worker';
import { gaussianClusters, lattice, random, uniform } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

const f = (x, y) => 12.5 - 0.75 * x + 2.25 * y;
const valuesAt = (xy) => {
  const out = new Float64Array(xy.length / 2);
  for (let i = 0; i < out.length; i++) out[i] = f(xy[2 * i], xy[2 * i + 1]);
  return out;
};

// Queries over the bounding box of xy: some fall outside the hull.
function queries(xy, n, seed) {
  const next = random(seed);
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < xy.length; i += 2) {
    x0 = Math.min(x0, xy[i]);
    x1 = Math.max(x1, xy[i]);
    y0 = Math.min(y0, xy[i + 1]);
    y1 = Math.max(y1, xy[i + 1]);
  }
  const q = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    q[2 * i] = x0 + next() * (x1 - x0);
    q[2 * i + 1] = y0 + next() * (y1 - y0);
  }
  return q;
}

for (const [name, xy] of [['uniform', uniform(5000, 3)], ['clustered', gaussianClusters(5000, 4)],
  ['lattice', lattice(60)]]) {
  test(`both methods reproduce a linear function inside the hull (${name})`, () => {
    const t = new Triangulation();
    const values = valuesAt(xy);
    t.insertPoints(xy, values);
    let scale = 0;
    for (const v of values) scale = Math.max(scale, Math.abs(v));
    const q = queries(xy, 4000, 5);
    for (const method of ['linear', 'natural']) {
      const out = t.interpolate(q, { method });
      assert.ok(out instanceof Float64Array);
      assert.equal(out.length, q.length / 2);
      let inside = 0;
      for (let i = 0; i < out.length; i++) {
        const outside = t.locate(q[2 * i], q[2 * i + 1]).kind === 'outside';
        if (outside) {
          assert.ok(Number.isNaN(out[i]), `${method}: NaN outside, query ${i}`);
          continue;
        }
        inside++;
        const error = Math.abs(out[i] - f(q[2 * i], q[2 * i + 1]));
        assert.ok(error <= 1e-12 * scale, `${method}: query ${i} off by ${error}`);
      }
      assert.ok(inside > out.length / 10);
      // The vertices' own values, exactly.
      assert.deepEqual(t.interpolate(xy, { method }), values);
    }
    t.dispose();
  });
}

test('natural differs from linear on a curved surface, and is continuous', () => {
  const xy = uniform(400, 6, 1);
  const values = new Float64Array(xy.length / 2);
  for (let i = 0; i < values.length; i++) values[i] = Math.sin(4 * xy[2 * i]) * xy[2 * i + 1];
  const t = new Triangulation();
  t.insertPoints(xy, values);
  const q = [0.4321, 0.5678, 0.4321 + 1e-9, 0.5678];
  const [a] = t.interpolate(q, { method: 'linear' });
  const [b, c] = t.interpolate(q, { method: 'natural' });
  assert.notEqual(a, b);
  assert.ok(Math.abs(b - c) < 1e-6);
  t.dispose();
});

test('continuity across constrained edges, crossings interpolated', () => {
  const t = new Triangulation();
  const xy = uniform(300, 7, 1);
  const next = random(8);
  t.insertPoints(xy, Array.from({ length: xy.length / 2 }, () => next()));
  t.insertPolyline([0.1, 0.2, 0.9, 0.8], [1, 3]);
  t.insertPolyline([0.1, 0.8, 0.9, 0.2], [5, 5]);
  const r = t.results();
  const crossing = r.points.length / 2 - 1;
  assert.ok(Math.abs(r.points[2 * crossing] - 0.5) < 1e-12);
  assert.ok(Math.abs(r.values[crossing] - (2 + 5) / 2) < 1e-12, `${r.values[crossing]}`);
  assert.equal(t.stats.valueDisagreements, 1);
  for (const method of ['linear', 'natural']) {
    for (const u of [0.13, 0.31, 0.77]) {
      const x = 0.1 + 0.8 * u, y = 0.2 + 0.6 * u;
      const e = 1e-12;  // the normal of (0.8, 0.6) is (-0.6, 0.8)
      const [left, right] = t.interpolate([x - 0.6 * e, y + 0.8 * e, x + 0.6 * e, y - 0.8 * e],
        { method });
      assert.ok(Math.abs(left - right) < 1e-6, `${method} at ${u}: ${left} against ${right}`);
    }
  }
  t.dispose();
});

test('duplicates keep the first values; several values per point', () => {
  const r = triangulate({ points: [0, 0, 1, 0, 0, 1, 1, 0], values: [1, 10, 2, 20, 3, 30, 4, 40] },
    { valuesPerPoint: 2 });
  assert.deepEqual(Array.from(r.values), [1, 10, 2, 20, 3, 30]);
  assert.equal(r.stats.valueDuplicates, 1);
  assert.equal(r.stats.duplicates, 1);
  const t = new Triangulation({ valuesPerPoint: 2 });
  assert.equal(t.valuesPerPoint, 2);
  t.insertPoints([0, 0, 4, 0, 0, 4], [0, 1, 4, 1, 0, 5]);
  assert.deepEqual(Array.from(t.interpolate([1, 1, 9, 9])), [1, 2, NaN, NaN]);
  throwsWith(() => t.insertPoints([1, 1], [1]), RangeError, /points values has 1 numbers/);
  throwsWith(() => triangulate({ points: [0, 0] }, { valuesPerPoint: 0 }), RangeError,
    /valuesPerPoint must be a whole number/);
  t.dispose();
});

test('interpolate: NaN without values, bad input refused', () => {
  const t = new Triangulation();
  t.insertPoints([0, 0, 1, 0, 0, 1]);
  assert.ok(Number.isNaN(t.interpolate([0.2, 0.2])[0]));
  assert.equal(t.results().values, undefined);
  t.insertPoints([1, 1], [4]);  // values from now on: the first three have NaN
  assert.equal(t.results().values.length, 4);
  assert.ok(Number.isNaN(t.interpolate([0.2, 0.2])[0]));
  throwsWith(() => t.interpolate([0.2, 0.2], { method: 'cubic' }), TypeError,
    /options.method must be 'linear' or 'natural'/);
  throwsWith(() => t.interpolate([0.2]), RangeError, /odd length/);
  t.dispose();
});

test('rasterize: triangle by triangle, equal to the linear queries at pixel centres', () => {
  const xy = gaussianClusters(3000, 9);
  const values = new Float64Array(xy.length / 2);
  for (let i = 0; i < values.length; i++) values[i] = Math.cos(xy[2 * i] / 5) + xy[2 * i + 1];
  const t = new Triangulation();
  t.insertPoints(xy, values);
  const bbox = [-5, -8, 110, 102];
  const width = 83, height = 57;
  const raster = t.rasterize({ bbox, width, height });
  assert.ok(raster instanceof Float32Array);
  assert.equal(raster.length, width * height);
  const centres = new Float64Array(2 * width * height);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      centres[2 * (j * width + i)] = bbox[0] + (i + 0.5) * (bbox[2] - bbox[0]) / width;
      centres[2 * (j * width + i) + 1] = bbox[3] - (j + 0.5) * (bbox[3] - bbox[1]) / height;
    }
  }
  const expected = t.interpolate(centres);
  let inside = 0;
  for (let k = 0; k < raster.length; k++) {
    if (Number.isNaN(expected[k])) {
      assert.ok(Number.isNaN(raster[k]), `pixel ${k} outside the hull`);
      continue;
    }
    inside++;
    assert.ok(Math.abs(raster[k] - expected[k]) <= 1e-5 * Math.abs(expected[k]) + 1e-5,
      `pixel ${k}: ${raster[k]} against ${expected[k]}`);
  }
  assert.ok(inside > 500);
  const natural = t.rasterize({ bbox, width, height, method: 'natural' });
  assert.deepEqual(natural, Float32Array.from(t.interpolate(centres, { method: 'natural' })));
  throwsWith(() => t.rasterize({ bbox: [0, 0, 0, 1], width: 2, height: 2 }), RangeError,
    /minX < maxX/);
  throwsWith(() => t.rasterize({ bbox, width: 2.5, height: 2 }), RangeError, /width must be/);
  throwsWith(() => t.rasterize({ bbox, width: 65536, height: 65536 }), RangeError, /2 GB/);
  throwsWith(() => t.rasterize({ bbox: 'all', width: 2, height: 2 }), TypeError, /bbox/);
  t.dispose();
});

test('the worker: values in, interpolation and rasters back', async () => {
  const worker = createWorker();
  after(() => worker.terminate());
  const xy = uniform(2000, 10);
  const values = valuesAt(xy);
  const here = new Triangulation();
  here.insertPoints(xy, values);
  here.insertPolyline([100, 100, 900, 900], [f(100, 100), f(900, 900)]);
  const there = worker.createTriangulation();
  await there.insertPoints(xy.slice(), values.slice());
  await there.insertPolyline([100, 100, 900, 900], [f(100, 100), f(900, 900)]);
  const q = queries(xy, 500, 11);
  for (const method of ['linear', 'natural']) {
    assert.deepEqual(await there.interpolate(q.slice(), { method }),
      here.interpolate(q, { method }));
  }
  const spec = { bbox: [0, 0, 1000, 1000], width: 40, height: 30 };
  assert.deepEqual(await there.rasterize(spec), here.rasterize(spec));
  assert.deepEqual((await there.results()).values, here.results().values);
  const r = await worker.triangulate({ points: xy.slice(), values: values.slice() });
  assert.deepEqual(r.values, triangulate({ points: xy, values }).values);
  await there.dispose();
  here.dispose();
});
