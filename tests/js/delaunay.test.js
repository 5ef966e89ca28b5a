// Delaunay invariants on the JS output, through the package's own name (the exports map).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { circle, gaussianClusters, lattice, scaled, uniform } from './support/inputs.js';

before(() => init());

function check(points) {
  const input = { points };
  const r = triangulate(input);
  return { r, ...checkMesh(r, input) };
}

test('init() after the first load resolves without loading again', async () => {
  await init();
  // Options of a second call are not used: the module is loaded once.
  assert.equal(await init({ wasmUrl: 'file:///nonexistent/geocdt.wasm' }), undefined);
  assert.equal(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length, 3);
});

test('uniform points', () => {
  const { r, V, T } = check(uniform(20_000));
  assert.equal(V, 20_000);
  assert.ok(T > 39_000);
  assert.equal(r.stats.inserted, 20_000);
});

test('gaussian clusters', () => { check(gaussianClusters(10_000)); });

test('lattice (massively cocircular)', () => {
  const { V, T, hullEdges } = check(lattice(60));
  assert.equal(V, 3600);
  assert.equal(hullEdges, 4 * 59, 'every boundary lattice point is a hull vertex');
  assert.equal(T, 2 * 59 * 59);
});

test('points on a circle', () => { check(circle(500)); });

test('copies scaled from 1e-9 to 1e9', () => {
  const base = uniform(2_000, 7);
  for (const f of [1e-9, 1e-3, 1, 1e3, 1e9]) check(scaled(base, f));
});

test('tiny bounding box at a huge offset', () => {
  check(scaled(uniform(2_000, 9), 1e-6, 1.6e7));  // Web Mercator metres, sub-metre spacing
});

test('lon/lat coordinates', () => {
  const xy = uniform(5_000, 3).map((v, i) => (i % 2 === 0 ? v * 0.36 - 180 : v * 0.18 - 90));
  check(xy);
});

test('duplicates map to one vertex each', () => {
  const points = [0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 1, 1, 1];
  const { r, V } = check(points);
  assert.equal(V, 4);
  assert.deepEqual(Array.from(r.inputToVertex),
    [r.inputToVertex[0], r.inputToVertex[1], r.inputToVertex[2], r.inputToVertex[1],
      r.inputToVertex[0], r.inputToVertex[5], r.inputToVertex[5]]);
  assert.equal(r.stats.duplicates, 3);
});

test('all points duplicates', () => {
  const { r, V, T } = check(new Float64Array(200).fill(5));
  assert.equal(V, 1);
  assert.equal(T, 0);
  assert.ok(r.inputToVertex.every((v) => v === 0));
});

test('0, 1 and 2 points, and no input at all', () => {
  for (const points of [[], [1, 2], [1, 2, 3, 4]]) {
    const { V, T } = check(points);
    assert.equal(V, points.length / 2);
    assert.equal(T, 0);
  }
  const r = triangulate({});
  assert.equal(r.points.length, 0);
  assert.equal(r.triangles.length, 0);
});

test('collinear points give no triangle', () => {
  const xy = [];
  for (let i = 0; i < 100; i++) xy.push(i, 2 * i);
  const { T } = check(xy);
  assert.equal(T, 0);
});

test('collinear hull points are all hull vertices', () => {
  const xy = [];
  for (let i = 0; i <= 50; i++) xy.push(i, 0, i, 50, 0, i, 50, i);
  xy.push(25, 25, 10, 30);
  const { hullEdges } = check(xy);
  assert.equal(hullEdges, 200);
});

test('number[] and Float64Array give the same result', () => {
  const xy = uniform(3_000, 11);
  const a = triangulate({ points: xy });
  const b = triangulate({ points: Array.from(xy) });
  assert.deepEqual(a.triangles, b.triangles);
  assert.deepEqual(a.halfedges, b.halfedges);
  assert.deepEqual(a.points, b.points);
});

test('the result is plain typed arrays the caller owns', () => {
  const a = triangulate({ points: uniform(1_000, 5) });
  const b = triangulate({ points: uniform(100_000, 6) });  // grows the heap
  assert.ok(a.points instanceof Float64Array);
  assert.ok(a.triangles instanceof Uint32Array);
  assert.ok(a.halfedges instanceof Int32Array);
  assert.ok(a.constrained instanceof Uint8Array);
  assert.ok(a.inputToVertex instanceof Uint32Array);
  for (const array of [a.points, a.triangles, a.halfedges, b.triangles]) {
    assert.equal(array.byteOffset, 0);
    assert.equal(array.buffer.byteLength, array.byteLength, 'not a view into the wasm heap');
  }
  checkMesh(a, { points: uniform(1_000, 5) });
});
