// triangulateGeoJSON(geojson, { perFeature: true }): each Polygon (each part of a
// MultiPolygon, with its holes) filled alone, as renderers fill them, its triangles labelled
// with its feature. Checked against triangulatePolygons() on a batch built here from the
// GeoJSON itself, held to the exact checker of support/polygons.js, and the FeatureCollection
// against the arrays.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulateGeoJSON, triangulatePolygons } from 'geocdt';
import { checkPolygonTriangles } from './support/polygons.js';
import { countries } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

// The batch a renderer would build: one polygon per Polygon and per part of a MultiPolygon
// (its rings, each closed), in feature order; firstParts[f], the first polygon of feature f
// (the features with rings), heights alongside the points.
function partBatch(fc) {
  const coords = [], heights = [], ringOffsets = [0], polygonOffsets = [0];
  const features = [], firstParts = [];
  for (const f of fc.features) {
    const g = f.geometry;
    const parts = g?.type === 'Polygon' ? [g.coordinates]
      : g?.type === 'MultiPolygon' ? g.coordinates : [];
    if (!parts.some((rings) => rings.length > 0)) continue;
    features.push(f);
    firstParts.push(polygonOffsets.length - 1);
    for (const rings of parts) {
      for (const ring of rings) {
        for (const p of ring) {
          coords.push(p[0], p[1]);
          heights.push(p.length > 2 ? p[2] : NaN);
        }
        ringOffsets.push(coords.length / 2);
      }
      polygonOffsets.push(ringOffsets.length - 1);
    }
  }
  firstParts.push(polygonOffsets.length - 1);
  return {
    batch: {
      coords: Float64Array.from(coords), ringOffsets: Uint32Array.from(ringOffsets),
      polygonOffsets: Uint32Array.from(polygonOffsets),
    },
    heights, features, firstParts,
  };
}

const square = (x, y, s, z) => {
  const ring = [[x, y], [x + s, y], [x + s, y + s], [x, y + s], [x, y]];
  return [z === undefined ? ring : ring.map((p) => [...p, z])];
};
const feature = (geometry, properties, id) => ({ type: 'Feature', id, properties, geometry });

// Two overlapping squares, a bow tie (its rings cross: an extra point), a square with a hole
// and an island as a MultiPolygon, a line and a point (no rings: no triangles).
const mixed = {
  type: 'FeatureCollection',
  features: [
    feature({ type: 'Polygon', coordinates: square(0, 0, 10, 5) }, { name: 'A' }, 'a'),
    feature({ type: 'Polygon', coordinates: square(5, 5, 10, 7) }, { name: 'B' }, 'b'),
    feature({ type: 'LineString', coordinates: [[0, 0], [50, 50]] }, { name: 'road' }),
    feature({ type: 'Polygon', coordinates: [[[20, 0], [30, 10], [30, 0], [20, 10], [20, 0]]] },
      { name: 'bow tie' }),
    feature({ type: 'Point', coordinates: [3, 3] }, { name: 'well' }),
    feature({ type: 'Polygon', coordinates: [] }, { name: 'empty' }),
    feature({
      type: 'MultiPolygon',
      coordinates: [[...square(40, 0, 10), [[42, 2], [42, 8], [48, 8], [48, 2], [42, 2]]],
        square(60, 0, 2)],
    }, { name: 'C' }, 7),
    // Parts that overlap (invalid GeoJSON): each is filled, as renderers fill them.
    feature({ type: 'MultiPolygon', coordinates: [square(80, 0, 4), square(82, 2, 4)] },
      { name: 'D' }),
  ],
};

// The features of the triangles of r that hold (x, y) strictly inside, one entry a triangle.
function holders(r, x, y) {
  const found = [];
  for (let t = 0; t < r.triangles.length / 3; t++) {
    const v = [0, 1, 2].map((k) => r.triangles[3 * t + k]);
    const inside = [0, 1, 2].every((k) => {
      const a = v[k], b = v[(k + 1) % 3];
      const [ax, ay, bx, by] = [r.points[2 * a], r.points[2 * a + 1], r.points[2 * b],
        r.points[2 * b + 1]];
      return (bx - ax) * (y - ay) - (by - ay) * (x - ax) > 0;
    });
    if (inside) found.push(r.regions[t]);
  }
  return found.sort();
}

// The arrays against triangulatePolygons() of the batch made here, itself held to the exact
// checker; triangleOffsets and regions group its polygons by feature.
function checkArrays(fc, r, fillRule) {
  const { batch, heights, features, firstParts } = partBatch(fc);
  const direct = triangulatePolygons(batch, { fillRule });
  checkPolygonTriangles(batch, direct, { fillRule });
  const n = batch.coords.length;
  assert.deepEqual(r.points.subarray(0, n), batch.coords, 'the rings\' points first');
  assert.deepEqual(r.points.subarray(n), direct.extraPoints, 'then the extra points');
  assert.deepEqual(r.triangles, direct.triangles);
  assert.equal(r.regionFeatures.length, features.length);
  r.regionFeatures.forEach((f, k) => assert.equal(f, features[k], `feature ${k}`));
  assert.deepEqual(Array.from(r.triangleOffsets),
    firstParts.map((p) => direct.triangleOffsets[p]), 'a feature\'s triangles: its parts\'');
  for (let k = 0; k + 1 < r.triangleOffsets.length; k++) {
    for (let t = r.triangleOffsets[k]; t < r.triangleOffsets[k + 1]; t++) {
      assert.equal(r.regions[t], k, `triangle ${t} names its feature`);
    }
  }
  return { heights, n };
}

test('perFeature: each polygon filled alone, the exact checker on every one', () => {
  for (const fillRule of ['evenodd', 'nonzero']) {
    const r = triangulateGeoJSON(mixed, { perFeature: true, output: 'arrays', fillRule });
    checkArrays(mixed, r, fillRule);
    assert.equal(r.stats.polygons, 8, 'A, B, the bow tie, the empty one, C\'s two parts, D\'s');
    assert.equal(r.stats.crossings, 1, 'the bow tie\'s crossing');
    // Overlapping features keep their own triangles, and so do overlapping parts of one.
    assert.deepEqual(holders(r, 7.25, 7.5), [0, 1]);
    assert.deepEqual(holders(r, 83.25, 3.5), [4, 4]);
  }
});

test('perFeature: the FeatureCollection carries ids, properties and heights', () => {
  const withHeights = structuredClone(mixed);
  withHeights.features[0].geometry.coordinates = square(0, 0, 10, 5);
  withHeights.features[1].geometry.coordinates = square(5, 5, 10, 7);
  const r = triangulateGeoJSON(withHeights, { perFeature: true, output: 'arrays' });
  const { heights, n } = checkArrays(withHeights, r, 'evenodd');
  assert.deepEqual(Array.from(r.values.subarray(0, n / 2)), heights);
  assert.ok(r.values.subarray(n / 2).every(Number.isNaN), 'no height at the extra points');
  const fc = triangulateGeoJSON(withHeights, { perFeature: true });
  assert.equal(fc.type, 'FeatureCollection');
  assert.equal(fc.features.length, r.triangles.length / 3);
  fc.features.forEach((f, t) => {
    const source = r.regionFeatures[r.regions[t]];
    assert.equal(f.id, source.id);
    assert.equal(f.properties, source.properties, 'the feature\'s own properties object');
    const ring = f.geometry.coordinates[0];
    assert.equal(ring.length, 4);
    assert.deepEqual(ring[3], ring[0]);
    for (let k = 0; k < 3; k++) {
      const v = r.triangles[3 * t + k];
      const z = r.values[v];
      assert.deepEqual(ring[k], Number.isNaN(z) ? [r.points[2 * v], r.points[2 * v + 1]]
        : [r.points[2 * v], r.points[2 * v + 1], z]);
    }
  });
  const empty = triangulateGeoJSON({ type: 'LineString', coordinates: [[0, 0], [1, 1]] },
    { perFeature: true, output: 'arrays' });
  assert.equal(empty.triangles.length, 0);
  assert.deepEqual(Array.from(empty.triangleOffsets), [0]);
  assert.deepEqual(triangulateGeoJSON(mixed.features[2], { perFeature: true }).features, []);
});

test('perFeature: Natural Earth 1:110m and 1:50m countries, every polygon checked', () => {
  for (const scale of ['110m', '50m']) {
    const world = countries(scale);
    const r = triangulateGeoJSON(world, { perFeature: true, output: 'arrays' });
    checkArrays(world, r, 'evenodd');
    assert.equal(r.regionFeatures.length, world.features.filter((f) => f.geometry).length);
  }
});

test('perFeature: options it does not take, and a bad value, are TypeErrors', () => {
  throwsWith(() => triangulateGeoJSON(mixed, { perFeature: 1 }), TypeError,
    /options\.perFeature must be true or false, got 1/);
  for (const [key, value] of [['refine', true], ['keep', 'all'], ['insideFlags', true],
    ['segmentSources', true]]) {
    throwsWith(() => triangulateGeoJSON(mixed, { perFeature: true, [key]: value }), TypeError,
      new RegExp(`options\\.${key} does not apply with perFeature: true`));
  }
  throwsWith(() => triangulateGeoJSON(mixed, { perFeature: true, fillRule: 'odd' }), TypeError,
    /fillRule/);
  // keep: 'inside' is what it does anyway, an option left undefined is no option, and
  // perFeature: false is the usual call.
  assert.equal(triangulateGeoJSON(mixed, { perFeature: true, refine: undefined }).type,
    'FeatureCollection');
  const inside = triangulateGeoJSON(mixed, { perFeature: true, keep: 'inside', output: 'arrays' });
  assert.equal(inside.triangles.length,
    triangulateGeoJSON(mixed, { perFeature: true, output: 'arrays' }).triangles.length);
  const together = triangulateGeoJSON(mixed, { perFeature: false, output: 'arrays' });
  assert.ok(together.halfedges instanceof Int32Array, 'one triangulation of everything');
});
