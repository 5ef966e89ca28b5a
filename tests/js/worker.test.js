// geocdt/worker in Node's worker_threads: the same calls, with buffers transferred.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { createWorker } from 'geocdt/worker';
import {
  init, triangulate, triangulateGeoJSON, triangulatePolygons, earcut, voronoi, voronoiGeoJSON,
} from 'geocdt';
import { createHost } from '../../web/worker-host.js';
import { checkMesh } from './support/invariants.js';
import { flatPolylines, uniform } from './support/inputs.js';

const worker = createWorker();
after(() => worker.terminate());

test('triangulate in the worker equals triangulate here', async () => {
  await init();
  await worker.init();
  const xy = uniform(20_000, 31);
  const here = triangulate({ points: xy });
  const there = await worker.triangulate({ points: xy.slice() });
  checkMesh(there, { points: xy });
  for (const key of ['points', 'triangles', 'halfedges', 'constrained', 'inputToVertex']) {
    assert.deepEqual(there[key], here[key], key);
  }
  assert.equal(there.stats.inserted, 20_000);
});

test('triangulatePolygons and earcut in the worker equal them here', async () => {
  await init();
  const batch = () => ({
    coords: new Int32Array([0, 0, 8, 0, 8, 8, 0, 8, 0, 0, 2, 2, 2, 6, 6, 6, 6, 2, 2, 2,
      20, 0, 24, 4, 24, 0, 20, 4]),
    ringOffsets: new Uint32Array([0, 5, 10, 14]),
    polygonOffsets: new Uint32Array([0, 2, 3]),
  });
  const here = triangulatePolygons(batch());
  const sent = batch();
  const there = await worker.triangulatePolygons(sent, { fillRule: 'evenodd' });
  assert.equal(sent.coords.byteLength, 0, 'the batch was transferred');
  for (const key of ['triangles', 'extraPoints', 'triangleOffsets']) {
    assert.deepEqual(there[key], here[key], key);
  }
  assert.equal(there.stats.crossings, 1);
  const bow = await worker.earcut([0, 0, 4, 4, 4, 0, 0, 4], null, 2);
  assert.deepEqual(bow, earcut([0, 0, 4, 4, 4, 0, 0, 4]));
  assert.deepEqual(bow.extraPoints, new Float64Array([2, 2]));
  await assert.rejects(() => worker.triangulatePolygons({ coords: [0, NaN], ringOffsets: [0, 1],
    polygonOffsets: [0, 1] }), (e) => e instanceof RangeError && e.polygon === 0);
});

test('input buffers are transferred (detached here), unless transfer: false', async () => {
  const xy = uniform(1_000, 32);
  await worker.triangulate({ points: xy });
  assert.equal(xy.byteLength, 0, 'the caller\'s Float64Array was transferred');

  const kept = uniform(1_000, 33);
  await worker.triangulate({ points: kept }, { transfer: false });
  assert.equal(kept.length, 2_000);

  const view = uniform(1_000, 34).subarray(2);  // a view cannot be handed over whole: copied
  await worker.triangulate({ points: view });
  assert.equal(view.length, 1_998);

  const array = Array.from(uniform(100, 35));
  assert.equal((await worker.triangulate({ points: array })).points.length, 200);
});

test('the host transfers every result buffer back', async () => {
  await init();
  const sent = [];
  const api = { init, triangulate };
  const onMessage = createHost(api, (message, transfer) => sent.push({ message, transfer }));
  await onMessage({ id: 1, op: 'triangulate', args: [{ points: uniform(100, 36) }] });
  const [{ message, transfer }] = sent;
  assert.ok(message.ok);
  const arrays = Object.values(message.value).filter((v) => ArrayBuffer.isView(v));
  assert.ok(arrays.length >= 8);
  assert.deepEqual(new Set(transfer), new Set(arrays.map((a) => a.buffer)));
});

test('errors keep their type and message across the worker', async () => {
  await assert.rejects(worker.triangulate({ points: [0, 0, 1] }),
    { name: 'RangeError', message: /odd length/ });
  await assert.rejects(worker.triangulate({ points: [0, 0, 1, NaN] }),
    { name: 'RangeError', message: /points\[3\]/ });
  await assert.rejects(worker.triangulate({ points: [0, 0] }, { keep: 'most' }),
    { name: 'TypeError' });
  const t = worker.createTriangulation();
  await t.dispose();
  await assert.rejects(t.insertPoints([0, 0]), { message: /no Triangulation 1 in this worker/ });
  const r = await worker.triangulate({ points: [0, 0, 1, 0, 0, 1] });
  assert.equal(r.triangles.length, 3, 'the worker still works');
});

test('Voronoi cells in the worker equal those made here', async () => {
  await init();
  const points = uniform(5_000, 37);
  const rings = [[100, 100, 900, 100, 900, 900, 100, 900, 100, 100],
    [300, 300, 300, 700, 700, 700, 700, 300, 300, 300]];
  const here = voronoi({ points, polylines: rings }, { lloyd: { iterations: 2 } });
  const there = await worker.voronoi({ points: points.slice(), polylines: rings },
    { lloyd: { iterations: 2 } });
  for (const key of ['coords', 'ringOffsets', 'polygonOffsets', 'siteOffsets', 'points']) {
    assert.deepEqual(there[key], here[key], key);
  }
  assert.deepEqual(there.lloyd, here.lloyd);
  const geojson = { type: 'FeatureCollection', features: [
    { type: 'Feature', id: 7, properties: { a: 1 },
      geometry: { type: 'Point', coordinates: [1, 1] } },
    { type: 'Feature', properties: null,
      geometry: { type: 'Polygon', coordinates: [[[0, 0], [4, 0], [4, 4], [0, 0]]] } }] };
  assert.deepEqual(await worker.voronoiGeoJSON(geojson), voronoiGeoJSON(geojson));
  await assert.rejects(worker.voronoi({ points: [] }), { name: 'RangeError' });
  await assert.rejects(worker.voronoi({ points: [0, 0] }, { clip: [1, 1, 0, 0] }),
    { name: 'RangeError', message: /xmin < xmax/ });
});

test('a Triangulation living in the worker', async () => {
  const t = worker.createTriangulation();
  const ids = await t.insertPoints([0, 0, 10, 0, 0, 10, 10, 10]);
  assert.deepEqual(Array.from(ids), [0, 1, 2, 3]);
  const hit = await t.locate(2, 1);
  assert.equal(hit.kind, 'face');
  assert.equal(hit.vertices.length, 3);
  assert.equal((await t.locate(20, 20)).kind, 'outside');
  const r = await t.results();
  checkMesh(r);
  assert.equal(r.triangles.length, 6);
  assert.deepEqual(await t.counts(), { vertexCount: 4, triangleCount: 2, polylineCount: 0 });
  assert.equal((await t.stats()).inserted, 4);
  await t.dispose();
});

test('memoryUsage and GeoJSON through the worker', async () => {
  const fc = { type: 'MultiPoint', coordinates: [[0, 0], [1, 0], [0, 1], [1, 1]] };
  assert.deepEqual(await worker.triangulateGeoJSON(fc), triangulateGeoJSON(fc));
  const arrays = await worker.triangulateGeoJSON(fc, { output: 'arrays' });
  assert.equal(arrays.triangles.length, 6);
  const usage = await worker.memoryUsage();
  assert.ok(usage.heapBytes >= usage.allocatedBytes && usage.allocatedBytes > 0);
});

test('regions, heights and GeoJSON features through the worker', async () => {
  const polylines = [[0, 0, 10, 0, 10, 10, 0, 10, 0, 0], [2, 2, 2, 8, 8, 8, 8, 2, 2, 2],
    [-1, 5, 11, 5]];
  const values = Array.from({ length: 2 + 5 + 5 + 2 }, (_, i) => i);
  const input = { points: [-5, -5, 15, 15], polylines, polygons: [0, 1, 2], values };
  const here = triangulate(input);
  const there = await worker.triangulate(
    { ...input, polygons: new Uint32Array([0, 1, 2]), values: Float64Array.from(values) });
  assert.deepEqual(there.regions, here.regions);
  assert.deepEqual(there.values, here.values);
  assert.ok(there.regions.includes(0) && there.regions.includes(1));

  const square = [[0, 0, 1], [4, 0, 2], [4, 4, 3], [0, 4, 4], [0, 0, 1]];
  const fc = { type: 'FeatureCollection', features: [{
    type: 'Feature', id: 'a', properties: { name: 'square' },
    geometry: { type: 'Polygon', coordinates: [square] },
  }] };
  const geojson = await worker.triangulateGeoJSON(fc);
  assert.deepEqual(geojson, triangulateGeoJSON(fc));
  assert.ok(geojson.features.every((f) => f.id === 'a' && f.properties.name === 'square'));
  const arrays = await worker.triangulateGeoJSON(fc, { output: 'arrays' });
  assert.equal(arrays.regionFeatures[0], fc.features[0], 'the features stay on this thread');
  // Each feature filled alone: a second square overlapping the first, and a bow tie.
  fc.features.push({ type: 'Feature', properties: { name: 'overlap' }, geometry: {
    type: 'MultiPolygon', coordinates: [[[[2, 2], [6, 2], [6, 6], [2, 6], [2, 2]]],
      [[[10, 0], [14, 4], [14, 0], [10, 4], [10, 0]]]],
  } });
  for (const output of ['geojson', 'arrays']) {
    const options = { perFeature: true, output, fillRule: 'nonzero' };
    const untimed = ({ stats: _stats, ...rest }) => rest;
    const filled = await worker.triangulateGeoJSON(fc, options);
    const here = triangulateGeoJSON(fc, options);
    assert.deepEqual(output === 'arrays' ? untimed(filled) : filled,
      output === 'arrays' ? untimed(here) : here);
  }
  const filled = await worker.triangulateGeoJSON(fc, { perFeature: true, output: 'arrays' });
  assert.equal(filled.regionFeatures[1], fc.features[1]);
  assert.equal(filled.stats.crossings, 1);
  await assert.rejects(worker.triangulateGeoJSON(fc, { perFeature: true, refine: true }),
    TypeError);

  const t = worker.createTriangulation();
  await t.insertPolyline(polylines[0]);
  await t.insertPolyline(polylines[1]);
  const labelled = await t.results({ polygons: [0, 2] });
  assert.equal(labelled.regions.length, labelled.triangles.length / 3);
  await assert.rejects(t.results({ polygons: [0, 3] }), RangeError);
  await t.dispose();
});

test('an idle worker does not keep node running', async () => {
  const { spawnSync } = await import('node:child_process');
  const script = "import { createWorker } from 'geocdt/worker'; const w = createWorker(); "
    + 'const r = await w.triangulate({ points: [0, 0, 1, 0, 0, 1] }); '
    + 'console.log(r.triangles.length);';
  const p = spawnSync(process.execPath, ['--input-type=module', '-e', script],
    { encoding: 'utf8', timeout: 20_000 });
  assert.equal(p.status, 0, p.stderr);
  assert.equal(p.stdout.trim(), '3');
});

test('the worker takes every input form, and transfers any typed array', async () => {
  const xy = Int16Array.from(uniform(500, 37), (v) => Math.round(v));
  const lines = [[0, 0, 1000, 1000], [0, 1000, 1000, 0, 500, 0]];
  const flat = flatPolylines(lines);
  const here = triangulate({ points: xy, polylines: lines });
  const sent = { points: xy.slice(), polylines: { coords: Float32Array.from(flat.coords),
    offsets: Int32Array.from(flat.offsets) } };
  const { coords, offsets } = sent.polylines;
  const there = await worker.triangulate(sent);
  for (const key of ['points', 'triangles', 'halfedges', 'constrained', 'inputToVertex',
    'sources']) {
    assert.deepEqual(there[key], here[key], key);
  }
  assert.equal(coords.byteLength, 0, 'the flat coordinates were transferred');
  assert.equal(offsets.byteLength, 0, 'the offsets were transferred');
  const mixed = await worker.triangulate({ points: Array.from(xy), polylines: lines });
  assert.deepEqual(mixed.triangles, here.triangles);
  await assert.rejects(worker.triangulate({ points: [0, 0, 1, 'x'] }),
    { name: 'TypeError', message: /points\[3\] must be a number, got string/ });
  const bad = { polylines: { coords: [0, 0, NaN, 1], offsets: [0, 2] } };
  await assert.rejects(worker.triangulate(bad), {
    name: 'RangeError',
    message: /polylines\.coords\[2\] \(x of point 1 of polyline 0\) is NaN/,
  });
});

test('createWorker({ threads }): the worker loads the threaded build', async () => {
  assert.throws(() => createWorker({ threads: 0 }), RangeError);
  assert.throws(() => createWorker({ threads: '2' }), TypeError);
  const worker = createWorker({ threads: 2 });
  try {
    const points = uniform(100_000, 21);
    const r = await worker.triangulate({ points }, { transfer: false });
    assert.equal(r.stats.threads, 2);
    await init();
    assert.equal(r.triangles.length, triangulate({ points }).triangles.length);
  } finally {
    worker.terminate();
  }
});

test('the worker refuses options a call does not take, as the main entry does', async () => {
  const rejectsWith = (promise, pattern) => assert.rejects(promise,
    (e) => e instanceof TypeError && pattern.test(e.message));
  const xy = uniform(100, 35);
  await rejectsWith(worker.triangulate({ points: xy }, { trasnfer: false }),
    /triangulate\(\) has no option 'trasnfer' \(did you mean 'transfer'\?\)/);
  assert.equal(xy.length, 200, 'refused before anything was sent');
  await rejectsWith(worker.triangulate({ points: xy }, { transfer: false,
    refine: { maxarea: 1 } }),
    /options\.refine has no option 'maxarea' \(did you mean 'maxArea'\?\)/);
  await rejectsWith(worker.triangulateRaster({ heights: [1, 2, 3, 4], width: 2, height: 2 },
    { maxErr: 1 }), /triangulateRaster\(\) has no option 'maxErr'/);
  await rejectsWith(worker.voronoi({ points: xy }, { transfer: false, lloyds: true }),
    /voronoi\(\) has no option 'lloyds' \(did you mean 'lloyd'\?\)/);
  assert.throws(() => worker.createTriangulation({ valuePerPoint: 2 }),
    /new Triangulation\(\) has no option 'valuePerPoint'/);
  assert.throws(() => createWorker({ thread: 2 }),
    /createWorker\(\) has no option 'thread' \(did you mean 'threads'\?\)/);
  const t = worker.createTriangulation();
  await rejectsWith(t.insertPoints(xy, { onProgres() {} }),
    /insertPoints\(\) has no option 'onProgres' \(did you mean 'onProgress'\?\)/);
  await rejectsWith(t.refine({ minAngel: 20 }), /refine\(\) has no option 'minAngel'/);
  await rejectsWith(t.results({ polygon: [0] }),
    /results\(\) has no option 'polygon' \(did you mean 'polygons'\?\)/);
  assert.equal((await t.insertPoints(xy, { transfer: false })).length, 100);
  await t.dispose();
});
