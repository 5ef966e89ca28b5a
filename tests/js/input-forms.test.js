// Every input form gives the same triangulation: coordinates in any numeric array, polylines
// as an array of arrays or as one flat buffer with offsets (GeoArrow's layout), mixed.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, triangulateGeoJSON, geoJSONToInput, Triangulation } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { checkConstraints } from './support/constraints.js';
import { flatPolylines, polylineArrays, random } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

// Every numeric typed array but the BigInt ones.
const TYPES = [Float64Array, Float32Array, Int32Array, Uint32Array, Int16Array, Uint16Array,
  Int8Array, Uint8Array, Uint8ClampedArray];

// Integer coordinates from 0 to 100, which every type holds exactly.
function integers(n, seed) {
  const rnd = random(seed);
  return Array.from({ length: 2 * n }, () => Math.floor(rnd() * 101));
}

const square = (x0, y0, x1, y1) => [x0, y0, x1, y0, x1, y1, x0, y1, x0, y0];
const polylines = [square(10, 10, 90, 90), [0, 50, 100, 55, 50, 100], square(30, 30, 60, 60),
  [], [5, 5], [20, 80, 80, 20]];

function same(a, b) {
  for (const key of ['points', 'triangles', 'halfedges', 'constrained', 'inputToVertex',
    'constraintEdges', 'sourceOffsets', 'sources']) {
    assert.deepEqual(a[key], b[key], key);
  }
}

test('points in every numeric array type give the same triangulation', () => {
  const xy = integers(500, 3);
  const reference = triangulate({ points: Float64Array.from(xy) });
  checkMesh(reference, { points: xy });
  same(triangulate({ points: xy }), reference);
  for (const Type of TYPES) same(triangulate({ points: Type.from(xy) }), reference);
});

test('polylines in every numeric array type, as arrays and flat', () => {
  const points = integers(300, 4);
  const reference = triangulate({ points, polylines }, { insideFlags: true });
  checkMesh(reference, { points, polylines });
  checkConstraints(reference, { points, polylines });
  const flat = flatPolylines(polylines);
  for (const Type of TYPES) {
    same(triangulate({ points, polylines: polylines.map((l) => Type.from(l)) }), reference);
    const coords = Type.from(flat.coords);
    same(triangulate({ points, polylines: { coords, offsets: flat.offsets } }), reference);
  }
});

test('mixed forms: typed points, plain and typed polylines, Int32Array and number[] offsets',
  () => {
    const points = integers(200, 5);
    const reference = triangulate({ points, polylines });
    const flat = flatPolylines(polylines);
    same(triangulate({
      points: Uint16Array.from(points),
      polylines: polylines.map((l, i) => (i % 2 ? Int32Array.from(l) : l)),
    }), reference);
    same(triangulate({
      points: Float32Array.from(points),
      polylines: { coords: Array.from(flat.coords), offsets: Int32Array.from(flat.offsets) },
    }), reference);
    same(triangulate({
      points: Int8Array.from(points),
      polylines: { coords: Int16Array.from(flat.coords), offsets: Array.from(flat.offsets) },
    }), reference);
  });

test('flat polylines: views into a larger buffer, no polylines, empty polylines', () => {
  const flat = flatPolylines(polylines);
  const big = new Float64Array(flat.coords.length + 10);
  big.set(flat.coords, 6);
  const coords = big.subarray(6, 6 + flat.coords.length);
  same(triangulate({ polylines: { coords, offsets: flat.offsets } }), triangulate({ polylines }));

  const none = triangulate({ points: [0, 0, 1, 0, 0, 1], polylines: {
    coords: new Float64Array(0), offsets: new Uint32Array([0]) } });
  assert.equal(none.triangles.length, 3);
  const empty = triangulate({ points: [0, 0, 1, 0, 0, 1], polylines: {
    coords: new Float64Array(0), offsets: new Uint32Array([0, 0, 0]) } });
  assert.equal(empty.stats.polylines, 2);
  assert.equal(empty.constraintEdges.length, 0);
});

test('the flat form at scale: 2,000 rings, crossings and provenance as with arrays', () => {
  const rnd = random(17);
  const rings = [];
  for (let i = 0; i < 2_000; i++) {
    const x = rnd() * 1000, y = rnd() * 1000, s = 1 + rnd() * 20;
    rings.push(Float64Array.from(square(x, y, x + s, y + s)));
  }
  const flat = flatPolylines(rings);
  const r = triangulate({ polylines: flat }, { insideFlags: true });
  const input = { polylines: polylineArrays(flat) };
  checkMesh(r, input);
  checkConstraints(r, input);
  assert.ok(r.stats.crossings > 100, `crossings: ${r.stats.crossings}`);
  same(r, triangulate({ polylines: rings }, { insideFlags: true }));
});

test('the incremental class takes every numeric array type', () => {
  const xy = integers(300, 6);
  const line = [0, 0, 100, 100, 0, 100];
  const results = [];
  for (const Type of [Float64Array, ...TYPES, Array]) {
    const t = new Triangulation();
    const ids = t.insertPoints(Type.from(xy));
    assert.equal(ids.length, 300);
    assert.equal(t.insertPolyline(Type.from(line)).length, 3);
    results.push(t.results());
    t.dispose();
  }
  for (const r of results) {
    assert.deepEqual(r.triangles, results[0].triangles);
    assert.deepEqual(r.constrained, results[0].constrained);
  }
});

test('GeoJSON goes in flat: no array per ring', () => {
  const fc = {
    type: 'FeatureCollection',
    features: [
      { type: 'Feature', geometry: { type: 'Polygon', coordinates: [[[0, 0], [4, 0], [4, 4]]] } },
      { type: 'Feature', geometry: { type: 'LineString', coordinates: [[-1, 2], [5, 2]] } },
      { type: 'Feature', geometry: { type: 'MultiPoint', coordinates: [[1, 3], [2, 1]] } },
    ],
  };
  const flat = geoJSONToInput(fc, { flat: true });
  assert.ok(flat.polylines.coords instanceof Float64Array);
  assert.deepEqual(Array.from(flat.polylines.offsets), [0, 4, 6]);
  assert.deepEqual(Array.from(flat.polylines.coords), [0, 0, 4, 0, 4, 4, 0, 0, -1, 2, 5, 2]);
  assert.deepEqual(Array.from(flat.points), [1, 3, 2, 1]);
  const arrays = geoJSONToInput(fc);
  assert.deepEqual(arrays.polylines.map((l) => Array.from(l)), polylineArrays(flat.polylines)
    .map((l) => Array.from(l)));
  same(triangulateGeoJSON(fc, { output: 'arrays' }), triangulate(arrays));
});

test('bad coordinates are named in every form, after being found by the core', () => {
  const flat = flatPolylines([[0, 0, 1, 1], [2, 2, 3, 3, 4, 4]]);
  flat.coords[9] = NaN;  // y of point 2 of polyline 1
  throwsWith(() => triangulate({ polylines: flat }), RangeError,
    /^geocdt: polylines\.coords\[9\] \(y of point 2 of polyline 1\) is NaN$/);
  const f32 = Float32Array.from([0, 0, 1, 1, Infinity, 5]);
  throwsWith(() => triangulate({ points: f32 }), RangeError,
    /^geocdt: points\[4\] \(x of point 2\) is Infinity$/);
  const lines = [[0, 0], new Float32Array([1, -Infinity])];
  throwsWith(() => triangulate({ points: [0, 0], polylines: lines }), RangeError,
    /^geocdt: polylines\[1\]\[1\] \(y of point 0 of polyline 1\) is -Infinity$/);
  let error;
  try {
    triangulate({ points: [0, 0, 3e150, 1] });
  } catch (e) {
    error = e;
  }
  assert.equal(error.code, 'InvalidCoordinate');
  assert.equal(error.index, 1);
  assert.match(error.message, /points\[2\] \(x of point 1\) is 3e\+150, beyond the supported/);
  const t = new Triangulation();
  throwsWith(() => t.insertPolyline(new Float64Array([0, 0, 1, NaN])), RangeError,
    /^geocdt: polyline\[3\] \(y of point 1\) is NaN$/);
  throwsWith(() => t.insertPoints(Float32Array.from([1, 2, NaN, 0])), RangeError,
    /^geocdt: points\[2\] \(x of point 1\) is NaN$/);
  assert.equal(t.vertexCount, 0, 'nothing was inserted');
  t.dispose();
});

test('bad flat layouts are named', () => {
  const coords = new Float64Array([0, 0, 1, 1, 2, 0, 3, 1]);  // 4 points
  const bad = (offsets) => () => triangulate({ polylines: { coords, offsets } });
  throwsWith(bad(new Uint32Array([1, 4])), RangeError,
    /polylines\.offsets\[0\] is 1: the first offset must be 0/);
  throwsWith(bad(new Uint32Array([0, 3, 2, 4])), RangeError,
    /polylines\.offsets\[2\] is 2: below offsets\[1\] = 3/);
  throwsWith(bad(new Uint32Array([0, 9, 9])), RangeError,
    /polylines\.offsets\[1\] is 9: past the 4 points of polylines.coords/);
  throwsWith(bad(new Uint32Array([0, 2, 3])), RangeError,
    /polylines\.offsets\[2\] is 3: the last offset must be the number of points.*\(4\)/);
  throwsWith(bad(new Int32Array([0, -1, 4])), RangeError,
    /polylines\.offsets\[1\] is -1: below offsets\[0\] = 0/);
  throwsWith(bad([0, 1.5, 4]), RangeError, /polylines\.offsets\[1\] must be an integer/);
  throwsWith(bad(new Float64Array([0, 4])), TypeError,
    /polylines\.offsets must be a Uint32Array/);
  throwsWith(bad(new Uint32Array(0)), RangeError, /polylines\.offsets is empty/);
  throwsWith(() => triangulate({ polylines: { coords: [0, 0, 1], offsets: [0, 1] } }),
    RangeError, /polylines\.coords has an odd length \(3\)/);
  throwsWith(() => triangulate({ polylines: { coords: 'x', offsets: [0] } }), TypeError,
    /polylines\.coords must be a Float64Array/);
  throwsWith(() => triangulate({ polylines: { coords: [0, 0, 'a', 1], offsets: [0, 2] } }),
    TypeError, /polylines\.coords\[2\] must be a number, got string/);
  assert.equal(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length, 3, 'still works');
});
