// triangulateGeoJSON(geojson, { perFeature: true }): each feature's rings filled alone, as a
// renderer fills them. The arrays are checked polygon by polygon by the exact checker of
// triangulatePolygons() (support/polygons.js) against a batch built here from the GeoJSON
// itself, and the FeatureCollection against the arrays.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulateGeoJSON } from 'geocdt';
import { checkPolygonTriangles } from './support/polygons.js';
import { countries } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

// The batch a renderer would build: per feature with rings, all of its Polygons' rings (each
// closed), in feature order; ringPoints is where each ring's points start, heights alongside.
function featureBatch(fc) {
  const coords = [], heights = [], ringOffsets = [0], polygonOffsets = [0], features = [];
  for (const f of fc.features) {
    const g = f.geometry;
    const polygons = g?.type === 'Polygon' ? [g.coordinates]
      : g?.type === 'MultiPolygon' ? g.coordinates : [];
    if (polygons.length === 0) continue;
    for (const rings of polygons) {
      for (const ring of rings) {
        for (const p of ring) {
          coords.push(p[0], p[1]);
          heights.push(p.length > 2 ? p[2] : NaN);
        }
        ringOffsets.push(coords.length / 2);
      }
    }
    polygonOffsets.push(ringOffsets.length - 1);
    features.push(f);
  }
  return {
    batch: {
      coords: Float64Array.from(coords), ringOffsets: Uint32Array.from(ringOffsets),
      polygonOffsets: Uint32Array.from(polygonOffsets),
    },
    heights, features,
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
    feature({
      type: 'MultiPolygon',
      coordinates: [[...square(40, 0, 10), [[42, 2], [42, 8], [48, 8], [48, 2], [42, 2]]],
        square(60, 0, 2)],
    }, { name: 'C' }, 7),
  ],
};

// The arrays against the exact checker, on the batch made from the GeoJSON here.
function checkArrays(fc, r, fillRule) {
  const { batch, heights, features } = featureBatch(fc);
  const n = batch.coords.length;
  assert.deepEqual(r.points.subarray(0, n), batch.coords, 'the rings\' points first');
  checkPolygonTriangles(batch, {
    triangles: r.triangles, extraPoints: r.points.slice(n), triangleOffsets: r.triangleOffsets,
  }, { fillRule });
  assert.equal(r.regionFeatures.length, features.length);
  r.regionFeatures.forEach((f, p) => assert.equal(f, features[p], `feature of polygon ${p}`));
  for (let p = 0; p + 1 < r.triangleOffsets.length; p++) {
    for (let t = r.triangleOffsets[p]; t < r.triangleOffsets[p + 1]; t++) {
      assert.equal(r.regions[t], p, `triangle ${t} names its feature`);
    }
  }
  return { heights, n };
}

test('perFeature: each feature filled alone, the exact checker on every polygon', () => {
  for (const fillRule of ['evenodd', 'nonzero']) {
    const r = triangulateGeoJSON(mixed, { perFeature: true, output: 'arrays', fillRule });
    checkArrays(mixed, r, fillRule);
    assert.equal(r.stats.polygons, 4);
    assert.equal(r.stats.crossings, 1, 'the bow tie\'s crossing');
    // Overlapping features keep their own triangles: both squares cover (7, 7).
    const holders = new Set();
    for (let t = 0; t < r.triangles.length / 3; t++) {
      const [a, b, c] = [0, 1, 2].map((k) => r.triangles[3 * t + k]);
      const x = [a, b, c].map((v) => r.points[2 * v]);
      const y = [a, b, c].map((v) => r.points[2 * v + 1]);
      const inside = [0, 1, 2].every((k) => {
        const j = (k + 1) % 3;
        return (x[j] - x[k]) * (7.5 - y[k]) - (y[j] - y[k]) * (7.25 - x[k]) >= 0;
      });
      if (inside) holders.add(r.regions[t]);
    }
    assert.deepEqual([...holders].sort(), [0, 1]);
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
  // keep: 'inside' is what it does anyway; perFeature: false is the usual call.
  const inside = triangulateGeoJSON(mixed, { perFeature: true, keep: 'inside', output: 'arrays' });
  assert.equal(inside.triangles.length,
    triangulateGeoJSON(mixed, { perFeature: true, output: 'arrays' }).triangles.length);
  const together = triangulateGeoJSON(mixed, { perFeature: false, output: 'arrays' });
  assert.ok(together.halfedges instanceof Int32Array, 'one triangulation of everything');
});
