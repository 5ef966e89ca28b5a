// GeoJSON in, triangles out (as a FeatureCollection or as typed arrays).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { geoJSONToInput, init, meshToGeoJSON, triangulate, triangulateGeoJSON } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { random } from './support/inputs.js';

before(() => init());

const small =
  JSON.parse(readFileSync(new URL('./fixtures/small.geojson', import.meta.url), 'utf8'));

test('geometries become points and polylines', () => {
  const input = geoJSONToInput(small);
  assert.deepEqual(Array.from(input.points), [-4, -4, 14, 14, 8, 1.5, 1, 1]);
  assert.equal(input.polylines.length, 3);
  assert.deepEqual(Array.from(input.polylines[1]), [3, 3, 3, 6, 6, 6, 6, 3, 3, 3]);
  assert.deepEqual(Array.from(input.polylines[2]), [-2, 8, 12, 8]);
  assert.ok(input.polylines.every((l) => l instanceof Float64Array));
});

test('every geometry type, a bare geometry and a Feature', () => {
  const multi = {
    type: 'GeometryCollection',
    geometries: [
      { type: 'MultiLineString', coordinates: [[[0, 0], [1, 1]], [[2, 2], [3, 3], [4, 2]]] },
      {
        type: 'MultiPolygon',
        coordinates: [[[[0, 0], [1, 0], [1, 1], [0, 0]]], [[[5, 5], [6, 5], [6, 6], [5, 5]]]],
      },
    ],
  };
  const input = geoJSONToInput(multi);
  assert.equal(input.polylines.length, 4);
  const feature = { type: 'Feature', geometry: { type: 'Point', coordinates: [3, 4] } };
  assert.equal(geoJSONToInput(feature).points[1], 4);
});

test('an unclosed ring is closed', () => {
  const { polylines } =
    geoJSONToInput({ type: 'Polygon', coordinates: [[[0, 0], [4, 0], [4, 4]]] });
  assert.deepEqual(Array.from(polylines[0]), [0, 0, 4, 0, 4, 4, 0, 0]);
});

// What readGeoJSON() must give, written the plain way: number[] grown a value at a time.
function referenceInput(geojson) {
  const points = { xy: [], z: [] }, rings = { xy: [], z: [], offsets: [0] };
  const lines = { xy: [], z: [], offsets: [0] };
  const polygons = [0];
  let heights = false;
  const position = (p, to) => {
    to.xy.push(p[0], p[1]);
    to.z.push(p.length > 2 ? p[2] : NaN);
    heights ||= p.length > 2;
  };
  const line = (positions, close, to) => {
    for (const p of positions) position(p, to);
    const [a, b] = [positions[0], positions.at(-1)];
    if (close && positions.length >= 2 && (a[0] !== b[0] || a[1] !== b[1])) {
      to.xy.push(a[0], a[1]);
      to.z.push(a.length > 2 ? a[2] : NaN);
    }
    to.offsets.push(to.xy.length / 2);
  };
  const geometry = (g) => {
    const c = g.coordinates;
    if (g.type === 'Point') position(c, points);
    if (g.type === 'MultiPoint') c.forEach((p) => position(p, points));
    if (g.type === 'LineString') line(c, false, lines);
    if (g.type === 'MultiLineString') c.forEach((l) => line(l, false, lines));
    if (g.type === 'Polygon') c.forEach((r) => line(r, true, rings));
    if (g.type === 'MultiPolygon') c.forEach((poly) => poly.forEach((r) => line(r, true, rings)));
    if (g.type === 'GeometryCollection') g.geometries.forEach(geometry);
  };
  for (const f of geojson.features) {
    const before = rings.offsets.length;
    geometry(f.geometry);
    if (rings.offsets.length > before) polygons.push(rings.offsets.length - 1);
  }
  const ringCount = rings.offsets.length - 1;
  return {
    points: points.xy,
    coords: [...rings.xy, ...lines.xy],
    offsets: [...rings.offsets, ...lines.offsets.slice(1).map((o) => o + rings.xy.length / 2)],
    polygons: ringCount > 0 ? polygons : undefined,
    values: heights ? [...points.z, ...rings.z, ...lines.z] : undefined,
  };
}

// Random features of every geometry type: rings closed or not, some positions with heights.
function randomFeatures(seed, count) {
  const next = random(seed);
  const position = (z) => (z && next() < 0.5 ? [next(), next(), next()] : [next(), next()]);
  const positions = (n, z) => Array.from({ length: n }, () => position(z));
  const ring = (z) => {
    const r = positions(1 + Math.floor(4 * next()), z);
    if (next() < 0.7) r.push([...r[0]]);
    return r;
  };
  const geometry = (depth, z) => {
    const kinds = ['Point', 'MultiPoint', 'LineString', 'MultiLineString', 'Polygon',
      'MultiPolygon', 'GeometryCollection'];
    const type = kinds[Math.floor(next() * (depth > 1 ? 6 : 7))];
    const some = (f) => Array.from({ length: Math.floor(3 * next()) }, f);
    if (type === 'Point') return { type, coordinates: position(z) };
    if (type === 'MultiPoint') return { type, coordinates: positions(Math.floor(3 * next()), z) };
    if (type === 'LineString') return { type, coordinates: positions(2 + (next() < 0.5), z) };
    if (type === 'MultiLineString') return { type, coordinates: some(() => positions(2, z)) };
    if (type === 'Polygon') return { type, coordinates: some(() => ring(z)) };
    if (type === 'MultiPolygon') return { type, coordinates: some(() => some(() => ring(z))) };
    return { type, geometries: some(() => geometry(depth + 1, z)) };
  };
  return {
    type: 'FeatureCollection',
    features: Array.from({ length: count }, () => ({
      type: 'Feature', properties: {}, geometry: geometry(0, seed % 2 === 0),
    })),
  };
}

test('GeoJSON of every geometry type reads as a plain reader reads it', () => {
  for (const seed of [11, 12, 13, 14, 15, 16]) {
    const geojson = randomFeatures(seed, 200);
    const want = referenceInput(geojson);
    const got = geoJSONToInput(geojson, { flat: true });
    assert.deepEqual(Array.from(got.points), want.points, `seed ${seed}: points`);
    assert.deepEqual(Array.from(got.polylines.coords), want.coords, `seed ${seed}: coords`);
    assert.deepEqual(Array.from(got.polylines.offsets), want.offsets, `seed ${seed}: offsets`);
    assert.deepEqual(got.polygons && Array.from(got.polygons), want.polygons, `seed ${seed}`);
    assert.deepEqual(got.values && Array.from(got.values), want.values, `seed ${seed}: values`);
    for (const a of [got.points, got.polylines.coords, got.values ?? got.points]) {
      assert.equal(a.buffer.byteLength, a.byteLength, `seed ${seed}: an array sized to fit`);
    }
  }
});

test('bad GeoJSON names the place', () => {
  const at = (geometry) => () =>
    geoJSONToInput({ type: 'FeatureCollection', features: [{ type: 'Feature', geometry }] });
  assert.throws(at({ type: 'Point', coordinates: [1] }),
    { name: 'TypeError', message: /features\[0\].geometry.coordinates must be a position/ });
  assert.throws(at({ type: 'LineString', coordinates: [[0, 0], [1, 'a']] }),
    { name: 'TypeError', message: /coordinates\[1\]\[1\] must be a number/ });
  assert.throws(at({ type: 'Polygon', coordinates: [[[0, 0], [NaN, 1], [1, 1], [0, 0]]] }),
    { name: 'RangeError', message: /coordinates\[0\]\[1\]\[0\] is NaN/ });
  assert.throws(at({ type: 'Circle', coordinates: [] }),
    { name: 'TypeError', message: /"Circle" is not a GeoJSON geometry type/ });
  assert.throws(() => geoJSONToInput('{}'), TypeError);
  assert.throws(() => triangulateGeoJSON(small, { output: 'svg' }),
    { name: 'TypeError', message: /options.output/ });
});

test('meshToGeoJSON writes one counter-clockwise triangle per feature', () => {
  const r = triangulate({ points: [0, 0, 4, 0, 0, 3, 5, 5] }, { insideFlags: true });
  const fc = meshToGeoJSON(r);
  assert.equal(fc.type, 'FeatureCollection');
  assert.equal(fc.features.length, r.triangles.length / 3);
  for (const [t, f] of fc.features.entries()) {
    assert.equal(f.id, t);
    assert.equal(f.geometry.type, 'Polygon');
    const ring = f.geometry.coordinates[0];
    assert.equal(ring.length, 4);
    assert.deepEqual(ring[0], ring[3]);
    const [[ax, ay], [bx, by], [cx, cy]] = ring;
    assert.ok((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0);
    assert.equal(f.properties.inside, false);
  }
});

test('triangulateGeoJSON: a FeatureCollection of triangles, or the arrays', () => {
  const arrays = triangulateGeoJSON(small, { output: 'arrays' });
  const input = geoJSONToInput(small);
  checkMesh(arrays, input);
  assert.equal(arrays.inputToVertex.length, 4 + 5 + 5 + 2);
  const fc = triangulateGeoJSON(small);
  assert.equal(fc.features.length, arrays.triangles.length / 3);
  assert.deepEqual(fc, meshToGeoJSON(arrays));
});

test('keep inside keeps the island without its lake (constraints)', () => {
  const fc = triangulateGeoJSON(small, { keep: 'inside' });
  let sum = 0;
  for (const f of fc.features) {
    const [[ax, ay], [bx, by], [cx, cy]] = f.geometry.coordinates[0];
    sum += ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2;
    assert.equal(f.properties, small.features[0].properties);  // the island's, as given
  }
  assert.equal(sum, 100 - 9);
  const flagged = triangulateGeoJSON(small, { keep: 'inside', insideFlags: true });
  for (const f of flagged.features) {
    assert.deepEqual(f.properties, { name: 'island', inside: true });
  }
});
