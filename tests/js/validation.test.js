// Bad input becomes a TypeError or RangeError that names what is wrong, and the module goes on
// working afterwards.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import {
  init, triangulate, triangulateGeoJSON, triangulatePolygons, triangulateRaster, Triangulation,
  memoryUsage, voronoi, voronoiGeoJSON,
} from 'geocdt';
import { throwsWith } from './support/throws.js';

before(() => init());

function stillWorks() {
  const r = triangulate({ points: [0, 0, 1, 0, 0, 1] });
  assert.equal(r.triangles.length, 3);
}

test('wrong types', () => {
  throwsWith(() => triangulate(), TypeError,
    /takes an object \{ points, polylines \}, got undefined/);
  throwsWith(() => triangulate([0, 0, 1, 1]), TypeError, /takes an object/);
  throwsWith(() => triangulate({ points: 'abc' }), TypeError,
    /points must be a Float64Array or an array of numbers.*got string/);
  throwsWith(() => triangulate({ points: new BigInt64Array(4) }), TypeError,
    /got a BigInt64Array/);
  throwsWith(() => triangulate({ points: new DataView(new ArrayBuffer(16)) }), TypeError,
    /got a DataView/);
  throwsWith(() => triangulate({ points: [0, 0, '1', 2] }), TypeError,
    /points\[2\] must be a number, got string/);
  throwsWith(() => triangulate({ points: [0, 0, 1, null] }), TypeError,
    /points\[3\] must be a number, got null/);
  throwsWith(() => triangulate({ polylines: new Float64Array(4) }), TypeError,
    /polylines must be an array of Float64Array/);
  throwsWith(() => triangulate({ polylines: [[0, 0, 1, 1], [0, 0, 1, {}]] }), TypeError,
    /polylines\[1\]\[3\] must be a number, got an Object/);
  stillWorks();
});

test('GeoJSON-style [x, y] positions and a lone polyline are told as such', () => {
  // Odd and even numbers of positions alike: the layout is named, not a length or a value.
  for (const positions of [[[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 0]]]) {
    throwsWith(() => triangulate({ points: positions }), TypeError,
      /points holds an Array at index 0: coordinates are flat .* pass points\.flat\(\)/);
    throwsWith(() => triangulate({ polylines: [[0, 0, 1, 1], positions] }), TypeError,
      /polylines\[1\] holds an Array at index 0: .*not \[x, y\] positions/);
    throwsWith(() => triangulate({ polylines: { coords: positions, offsets: [0, 1] } }),
      TypeError, /polylines\.coords holds an Array/);
  }
  throwsWith(() => triangulate({ points: [new Float64Array(2)] }), TypeError,
    /points holds a Float64Array at index 0/);
  throwsWith(() => triangulate({ polylines: [0, 0, 1, 1] }), TypeError,
    /polylines must be an array of polylines .*got numbers: for one polyline, pass \[line\]/);
  throwsWith(() => triangulate(new Float64Array([0, 0, 1, 0, 0, 1])), TypeError,
    /got a Float64Array \(for points alone: triangulate\(\{ points \}\)\)/);
  throwsWith(() => new Triangulation().insertPoints([[0, 0], [1, 1]]), TypeError,
    /holds an Array at index 0/);
  stillWorks();
});

test('arrays whose buffer was transferred away are told as such, not read as empty', () => {
  const detached = (a) => {
    structuredClone(a.buffer, { transfer: [a.buffer] });
    return a;
  };
  throwsWith(() => triangulate({ points: detached(new Float64Array([0, 0, 1, 0, 0, 1])) }),
    TypeError, /points is a Float64Array whose ArrayBuffer was detached/);
  throwsWith(() => triangulate({ points: [0, 0, 1, 0, 0, 1],
    polylines: [[0, 0, 1, 1], detached(new Float64Array(4))] }),
  TypeError, /polylines\[1\] is a Float64Array whose ArrayBuffer was detached/);
  throwsWith(() => triangulate({ polylines: { coords: new Float64Array([0, 0, 1, 1]),
    offsets: detached(new Uint32Array([0, 2])) } }),
  TypeError, /polylines\.offsets is a Uint32Array whose ArrayBuffer was detached/);
  throwsWith(() => triangulate({ points: [0, 0, 1, 0, 0, 1],
    values: detached(new Float64Array(3)) }), TypeError, /values is a Float64Array whose/);
  const t = new Triangulation();
  throwsWith(() => t.insertPoints(detached(new Float64Array(4))), TypeError, /detached/);
  t.dispose();
  // Empty arrays that own their (empty) buffer are still plain empty input.
  assert.equal(triangulate({ points: new Float64Array(0) }).triangles.length, 0);
  stillWorks();
});

test('odd lengths', () => {
  throwsWith(() => triangulate({ points: [0, 0, 1] }), RangeError,
    /points has an odd length \(3\)/);
  throwsWith(() => triangulate({ polylines: [[0, 0, 1, 1], new Float64Array(5)] }), RangeError,
    /polylines\[1\] has an odd length \(5\)/);
  stillWorks();
});

test('NaN and infinities name the offending index', () => {
  throwsWith(() => triangulate({ points: [0, 0, 1, NaN] }), RangeError,
    /points\[3\] \(y of point 1\) is NaN/);
  throwsWith(() => triangulate({ points: new Float64Array([0, 0, Infinity, 1]) }), RangeError,
    /points\[2\] \(x of point 1\) is Infinity/);
  throwsWith(() => triangulate({ points: [-Infinity, 0] }), RangeError,
    /points\[0\] \(x of point 0\) is -Infinity/);
  throwsWith(() => triangulate({ polylines: [[0, 0, 1, 1, 2, 2], [0, 0, 5, NaN]] }), RangeError,
    /polylines\[1\]\[3\] \(y of point 1 of polyline 1\) is NaN/);
  stillWorks();
});

test('|coordinate| > 1e150', () => {
  triangulate({ points: [1e150, -1e150, 0, 0, 1, 1e150] });  // the limit itself is fine
  throwsWith(() => triangulate({ points: [0, 0, 2e150, 0] }), RangeError,
    /points\[2\] \(x of point 1\) is 2e\+150, beyond the supported \|coordinate\| <= 1e150/);
  throwsWith(
    () => triangulate({ points: new Float32Array([0, 0, 0, 0]), polylines: [[0, -1e300]] }),
    RangeError,
    /polylines\[0\]\[1\]/);
  stillWorks();
});

test('bad options', () => {
  const ok = { points: [0, 0, 1, 0, 0, 1] };
  throwsWith(() => triangulate(ok, { keep: 'outside' }), TypeError,
    /options.keep must be 'all' or 'inside', got "outside"/);
  throwsWith(() => triangulate(ok, { keep: 'toString' }), TypeError, /options.keep/);
  throwsWith(() => triangulate(ok, { fillRule: 'winding' }), TypeError,
    /options.fillRule must be 'evenodd' or 'nonzero'/);
  throwsWith(() => triangulate(ok, { insideFlags: 1 }), TypeError,
    /options.insideFlags must be a boolean/);
  throwsWith(() => triangulate(ok, 'inside'), TypeError, /options must be an object/);
  stillWorks();
});

test('an option a call does not take is refused by name, with the nearest one', () => {
  const ok = { points: [0, 0, 1, 0, 0, 1] };
  throwsWith(() => triangulate(ok, { kep: 'inside' }), TypeError,
    /triangulate\(\) has no option 'kep' \(did you mean 'keep'\?\); it takes keep, fillRule,/);
  throwsWith(() => triangulate(ok, { refine: { minAngel: 25 } }), TypeError,
    /options\.refine has no option 'minAngel' \(did you mean 'minAngle'\?\)/);
  throwsWith(() => triangulate(ok, { maxError: 1 }), TypeError,
    /triangulate\(\) has no option 'maxError'; it takes/);
  const raster = { heights: new Float64Array(9), width: 3, height: 3 };
  throwsWith(() => triangulateRaster(raster, { maxErorr: 5 }), TypeError,
    /triangulateRaster\(\) has no option 'maxErorr' \(did you mean 'maxError'\?\)/);
  throwsWith(() => triangulateRaster(raster, { MinAngle: 20 }), TypeError,
    /did you mean 'minAngle'/);
  const square = { type: 'Polygon', coordinates: [[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]] };
  throwsWith(() => triangulateGeoJSON(square, { outptu: 'arrays' }), TypeError,
    /triangulateGeoJSON\(\) has no option 'outptu' \(did you mean 'output'\?\)/);
  const polygons = { coords: [0, 0, 1, 0, 0, 1], ringOffsets: [0, 3], polygonOffsets: [0, 1] };
  throwsWith(() => triangulatePolygons(polygons, { fill: 'nonzero' }), TypeError,
    /triangulatePolygons\(\) has no option 'fill'/);
  throwsWith(() => voronoi(ok, { lloyd: { iteration: 3 } }), TypeError,
    /options\.lloyd has no option 'iteration' \(did you mean 'iterations'\?\)/);
  throwsWith(() => voronoiGeoJSON({ type: 'MultiPoint', coordinates: [[0, 0], [1, 1]] },
    { clipp: 'hull' }), TypeError, /voronoiGeoJSON\(\) has no option 'clipp'/);
  // Every option each call documents is taken (undefined: its default).
  triangulate(ok, { keep: 'all', fillRule: 'evenodd', insideFlags: false,
    segmentSources: false, valuesPerPoint: 1, refine: { minAngle: 20, maxArea: undefined,
      maxSteinerPoints: undefined }, onProgress: undefined });
  triangulateRaster(raster, { maxError: 1, maxTriangles: undefined, maxVertices: undefined,
    decimate: false, noData: undefined, breaklines: undefined, breaklineHeights: undefined,
    minAngle: 0, bbox: undefined });
  stillWorks();
});

test('the incremental class refuses options it does not take', () => {
  throwsWith(() => new Triangulation({ valuesPerPoints: 2 }), TypeError,
    /new Triangulation\(\) has no option 'valuesPerPoints' \(did you mean 'valuesPerPoint'\?\)/);
  const t = new Triangulation();
  try {
    throwsWith(() => t.insertPoints([0, 0, 1, 0, 0, 1], { onprogress() {} }), TypeError,
      /insertPoints\(\) has no option 'onprogress' \(did you mean 'onProgress'\?\)/);
    assert.equal(t.vertexCount, 0, 'nothing inserted');
    t.insertPoints([0, 0, 1, 0, 0, 1]);
    throwsWith(() => t.interpolate([0.2, 0.2], { methd: 'natural' }), TypeError,
      /interpolate\(\) has no option 'methd'/);
    throwsWith(() => t.refine({ minAngle: 20, maxAera: 1 }), TypeError,
      /refine\(\) has no option 'maxAera' \(did you mean 'maxArea'\?\)/);
    throwsWith(() => t.results({ insideflags: true }), TypeError,
      /results\(\) has no option 'insideflags' \(did you mean 'insideFlags'\?\)/);
    throwsWith(() => t.rasterize({ bbox: [0, 0, 1, 1], width: 2, height: 2, mehtod: 'linear' }),
      TypeError, /rasterize\(\) has no option 'mehtod'/);
    assert.equal(t.results().triangles.length, 3);
  } finally {
    t.dispose();
  }
});

test('init() refuses an option it does not take, as a rejected promise', async () => {
  await assert.rejects(init({ warmup: false }), (error) => error instanceof TypeError
    && /init\(\) has no option 'warmup' \(did you mean 'warmUp'\?\)/.test(error.message));
});

test('the incremental class checks its input too, and keeps its state on bad input', () => {
  const t = new Triangulation();
  t.insertPoints([0, 0, 1, 0, 0, 1]);
  throwsWith(() => t.insertPoints([0, 0, NaN, 1]), RangeError,
    /points\[2\] \(x of point 1\) is NaN/);
  throwsWith(() => t.insertPolyline([0, 0, 1]), RangeError, /polyline has an odd length/);
  throwsWith(() => t.locate('1', 2), TypeError, /locate\(x, y\) takes two numbers/);
  throwsWith(() => t.results({ keep: 1 }), TypeError, /options.keep/);
  assert.equal(t.vertexCount, 3);
  assert.equal(t.results().triangles.length, 3);
  t.dispose();
  throwsWith(() => t.insertPoints([2, 2]), Error, /disposed/);
  t.dispose();  // twice is harmless
});

test('nothing is left allocated by failed calls', () => {
  stillWorks();
  const baseline = memoryUsage().allocatedBytes;
  for (let i = 0; i < 100; i++) {
    assert.throws(() => triangulate({ points: [0, 0, 1, NaN] }));
    assert.throws(() => triangulate({ points: [0, 0, 1] }));
  }
  assert.equal(memoryUsage().allocatedBytes, baseline);
});
