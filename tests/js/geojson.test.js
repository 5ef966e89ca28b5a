// GeoJSON in, triangles out (as a FeatureCollection or as typed arrays).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { geoJSONToInput, init, meshToGeoJSON, triangulate, triangulateGeoJSON } from 'geocdt';
import { checkMesh } from './support/invariants.js';

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
