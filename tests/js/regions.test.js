// Region labels and heights through the JS API and GeoJSON: each triangle names the input
// polygon that holds it (the innermost where they nest), GeoJSON triangles carry their
// feature's id and properties, and heights survive. The expected labels come from exact
// point-in-polygon tests (robust-predicates) of each triangle's centroid against the input.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import {
  geoJSONToInput, init, meshToGeoJSON, triangulate, triangulateGeoJSON, Triangulation,
} from 'geocdt';
import { orient } from './support/predicates.js';
import { throwsWith } from './support/throws.js';
import { checkMesh } from './support/invariants.js';
import { countries } from './support/inputs.js';

before(() => init());

const square = (x0, y0, x1, y1, ccw = true) => (ccw
  ? [x0, y0, x1, y0, x1, y1, x0, y1, x0, y0]
  : [x0, y0, x0, y1, x1, y1, x1, y0, x0, y0]);

// Winding number of (x, y) about a closed ring (x, y pairs), exactly: +1 for each edge going
// up with the point on its left, -1 for each going down with the point on its right.
function winding(ring, x, y) {
  let w = 0;
  for (let k = 0; k + 3 < ring.length; k += 2) {
    const [ax, ay, bx, by] = [ring[k], ring[k + 1], ring[k + 2], ring[k + 3]];
    const side = orient(ax, ay, bx, by, x, y);
    if (ay <= y && by > y && side > 0) w++;
    if (by <= y && ay > y && side < 0) w--;
  }
  return w;
}

// Whether the rings of one polygon hold (x, y), even-odd.
const holds = (rings, x, y) => rings.reduce((w, ring) => w + winding(ring, x, y), 0) % 2 !== 0;

// The centroid of triangle t, or null when rounding puts it on or beyond an edge.
function centroid(r, t) {
  const p = r.points;
  const [a, b, c] = [r.triangles[3 * t], r.triangles[3 * t + 1], r.triangles[3 * t + 2]];
  const x = (p[2 * a] + p[2 * b] + p[2 * c]) / 3;
  const y = (p[2 * a + 1] + p[2 * b + 1] + p[2 * c + 1]) / 3;
  const inside = orient(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y) > 0
    && orient(p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], x, y) > 0
    && orient(p[2 * c], p[2 * c + 1], p[2 * a], p[2 * a + 1], x, y) > 0;
  return inside ? [x, y] : null;
}

// An island in a lake in an island, as three polygons, the lake wound the other way; a frame
// of points around. Expected: the innermost polygon holding the centroid.
const island = square(0, 0, 100, 100), lake = square(20, 20, 80, 80, false);
const islet = square(40, 40, 60, 60);
const frame = [-20, -20, 120, -20, 120, 120, -20, 120];
const nested = (x, y) => {
  if (holds([islet], x, y)) return 2;
  if (holds([lake], x, y)) return 1;
  return holds([island], x, y) ? 0 : -1;
};

function expectLabels(r, expected) {
  assert.ok(r.regions instanceof Int32Array);
  assert.equal(r.regions.length, r.triangles.length / 3);
  const seen = new Set();
  for (let t = 0; t < r.regions.length; t++) {
    const at = centroid(r, t);
    assert.ok(at, `triangle ${t} is a sliver`);
    assert.equal(r.regions[t], expected(...at), `triangle ${t} at ${at}`);
    seen.add(r.regions[t]);
  }
  return seen;
}

test('input.polygons: the innermost of nested polygons, -1 outside, in both polyline forms', () => {
  const polylines = [island, lake, islet];
  const r = triangulate({ points: frame, polylines, polygons: [0, 1, 2, 3] });
  checkMesh(r, { points: frame, polylines });
  assert.deepEqual([...expectLabels(r, nested)].sort(), [-1, 0, 1, 2]);
  const coords = Float64Array.from(polylines.flat());
  const flat = triangulate({
    points: frame, polylines: { coords, offsets: new Uint32Array([0, 5, 10, 15]) },
    polygons: new Int32Array([0, 1, 2, 3]),
  });
  assert.deepEqual(flat.regions, r.regions);
  const nonzero = triangulate({ points: frame, polylines, polygons: [0, 1, 2, 3] },
    { fillRule: 'nonzero' });
  expectLabels(nonzero, nested);
  // Without features, meshToGeoJSON numbers the triangles and puts the region in properties.
  for (const [t, f] of meshToGeoJSON(r).features.entries()) {
    assert.deepEqual([f.id, f.properties], [t, { region: r.regions[t] }]);
  }
});

test('a polygon with a hole, an island in the hole, polylines of no polygon', () => {
  const road = [-20, 50, 120, 50];
  const polylines = [road, island, lake, islet, [-20, 10, 120, 90]];
  // Polygon 0: the island with its lake as a hole; polygon 1: the islet. The road before and
  // the line after the polygons belong to none.
  const r = triangulate({ points: frame, polylines, polygons: [1, 3, 4] });
  const seen = expectLabels(r, (x, y) => {
    if (holds([islet], x, y)) return 1;
    return holds([island, lake], x, y) ? 0 : -1;
  });
  assert.deepEqual([...seen].sort(), [-1, 0, 1]);
  // Rings of no polygon still bound the inside of keep and insideFlags.
  const all = triangulate({ points: frame, polylines }, { insideFlags: true });
  assert.equal(all.regions, undefined, 'no polygons, no regions');
  assert.equal(all.inside.length, r.regions.length);
});

test('keep inside: the kept triangles keep their labels', () => {
  const input = { points: frame, polylines: [island, lake, islet], polygons: [0, 1, 2, 3] };
  const all = triangulate(input);
  const kept = triangulate(input, { keep: 'inside' });
  const key = (r, t) => [r.triangles[3 * t], r.triangles[3 * t + 1], r.triangles[3 * t + 2]]
    .sort((a, b) => a - b).join();
  const labelOf = new Map();
  for (let t = 0; t < all.regions.length; t++) labelOf.set(key(all, t), all.regions[t]);
  assert.equal(kept.regions.length, kept.triangles.length / 3);
  for (let t = 0; t < kept.regions.length; t++) {
    assert.equal(kept.regions[t], labelOf.get(key(kept, t)));
  }
  // Even-odd over all rings drops the lake, a region of its own.
  assert.deepEqual([...new Set(kept.regions)].sort(), [0, 2]);
});

test('bad polygons name the offset', () => {
  const polylines = [island, islet];
  const bad = (polygons) => () => triangulate({ polylines, polygons });
  throwsWith(bad(new Float64Array([0, 1])), TypeError, /polygons must be a Uint32Array/);
  throwsWith(bad([]), RangeError, /polygons is empty/);
  throwsWith(bad([0, 2, 1]), RangeError, /polygons\[2\] is 1: below polygons\[1\] = 2/);
  throwsWith(bad(new Uint32Array([0, 5])), RangeError, /polygons\[1\] is 5: past the 2 polylines/);
  throwsWith(bad([0, -1]), RangeError, /polygons\[1\] must be an integer from 0/);
  throwsWith(bad([0, 1.5]), RangeError, /polygons\[1\] must be an integer from 0/);
  assert.equal(triangulate({ polylines, polygons: [2] }).regions.every((r) => r === -1), true);
});

test('Triangulation.results({ polygons }) labels the polylines inserted so far', () => {
  const t = new Triangulation();
  t.insertPoints(frame);
  t.insertPolyline(island);
  t.insertPolyline(lake);
  t.insertPoints([50, 50, 30, 70]);
  t.insertPolyline(islet);
  expectLabels(t.results({ polygons: [0, 1, 2, 3] }), nested);
  expectLabels(t.results({ polygons: [0, 2], keep: 'all' }),
    (x, y) => (holds([island, lake], x, y) ? 0 : -1));
  assert.equal(t.results().regions, undefined);
  throwsWith(() => t.results({ polygons: [0, 9] }), RangeError,
    /options.polygons\[1\] is 9: past the 3 polylines/);
  throwsWith(() => t.results({ polygons: 'all' }), TypeError, /options.polygons must be/);
  t.dispose();
});

test('values: input points keep their values, crossings interpolate along constraints', () => {
  // Two lines crossing at (5, 0): 1/2 along the first (values 0 .. 10) and 1/4 along the
  // second (values 100 .. 200); a free point with no value; a point given twice, first
  // without a value.
  const points = [20, 20, 1, 1, 1, 1];
  const polylines = [[0, 0, 10, 0], [5, -1, 5, 3]];
  const values = [NaN, NaN, 7, 0, 10, 100, 200];
  const r = triangulate({ points, polylines, values });
  assert.ok(r.values instanceof Float64Array);
  assert.equal(r.values.length, r.points.length / 2);
  const id = r.inputToVertex;
  assert.ok(Number.isNaN(r.values[id[0]]));
  assert.equal(r.values[id[1]], 7);
  assert.deepEqual([3, 4, 5, 6].map((i) => r.values[id[i]]), [0, 10, 100, 200]);
  const crossing = r.points.length / 2 - 1;
  assert.deepEqual([r.points[2 * crossing], r.points[2 * crossing + 1]], [5, 0]);
  // The constraints disagree (5 against 125): the mean, counted.
  assert.equal(r.values[crossing], 65);
  assert.equal(r.stats.valueDisagreements, 1);
  // Where both constraints agree, the crossing has their value.
  const level = triangulate({ polylines, values: [0, 10, 3, 11] });
  assert.equal(level.values[level.points.length / 2 - 1], 5);
  assert.equal(level.stats.valueDisagreements, 0);
  assert.equal(triangulate({ points }).values, undefined, 'no values, none out');
  throwsWith(() => triangulate({ points, values: [1, 2] }), RangeError,
    /values has 2 numbers for 3 points/);
  throwsWith(() => triangulate({ points, values: [1, '2', 3] }), TypeError,
    /values\[1\] must be a number/);
  throwsWith(() => triangulate({ points, values: 'high' }), TypeError,
    /values must be a Float64Array/);
  throwsWith(() => triangulate({ points, z: [1, 2, 3] }), TypeError, /input.z is now input.values/);
});

// Features with ids and properties: an island in a lake in an island (three features), a
// MultiPolygon of two parts, a polygon without id, a road, and heights on some positions.
const position = (ring, z) => {
  const out = [];
  for (let k = 0; k < ring.length; k += 2) {
    out.push(z === undefined ? [ring[k], ring[k + 1]] : [ring[k], ring[k + 1], z + k]);
  }
  return out;
};
const features = {
  type: 'FeatureCollection',
  features: [
    { type: 'Feature', id: 'big', properties: { name: 'island' },
      geometry: { type: 'Polygon', coordinates: [position(island, 100)] } },
    { type: 'Feature', id: 3, properties: { name: 'lake', depth: 12 },
      geometry: { type: 'Polygon', coordinates: [position(lake)] } },
    { type: 'Feature', properties: { name: 'road' },
      geometry: { type: 'LineString', coordinates: [[-20, 10, 1], [130, 10, 2]] } },
    { type: 'Feature', id: 7, properties: { name: 'islet' },
      geometry: { type: 'GeometryCollection', geometries: [
        { type: 'Polygon', coordinates: [position(islet)] },
        { type: 'Point', coordinates: [50, 50, 999] }] } },
    { type: 'Feature', id: 'twins', properties: { name: 'twins' },
      geometry: { type: 'MultiPolygon', coordinates: [[position(square(110, 0, 120, 10))],
        [position(square(110, 20, 120, 30))]] } },
    { type: 'Feature', properties: null,
      geometry: { type: 'Polygon', coordinates: [position(square(110, 40, 120, 50))] } },
    { type: 'Feature', properties: { name: 'no geometry' }, geometry: null },
  ],
};
const [bigF, lakeF, , isletF, twinsF, anonymousF] = features.features;
const featureAt = (x, y) => {
  if (holds([islet], x, y)) return isletF;
  if (holds([lake], x, y)) return lakeF;
  if (holds([island], x, y)) return bigF;
  if (holds([square(110, 0, 120, 10), square(110, 20, 120, 30)], x, y)) return twinsF;
  return holds([square(110, 40, 120, 50)], x, y) ? anonymousF : null;
};

test('triangulateGeoJSON: each triangle has its feature\'s id and properties', () => {
  const arrays = triangulateGeoJSON(features, { output: 'arrays' });
  assert.deepEqual(arrays.regionFeatures, [bigF, lakeF, isletF, twinsF, anonymousF]);
  assert.ok(arrays.regionFeatures.every((f, i) => f === [bigF, lakeF, isletF, twinsF,
    anonymousF][i]), 'the input features themselves');
  const seen = expectLabels(arrays,
    (x, y) => arrays.regionFeatures.indexOf(featureAt(x, y)));
  assert.equal(seen.size, 6);

  const fc = triangulateGeoJSON(features);
  assert.equal(fc.features.length, arrays.triangles.length / 3);
  for (const [t, f] of fc.features.entries()) {
    const source = featureAt(...centroid(arrays, t));
    assert.equal(f.properties, source === null ? null : source.properties, `triangle ${t}`);
    if (source?.id === undefined) assert.ok(!('id' in f), `triangle ${t} has no id`);
    else assert.equal(f.id, source.id);
    assert.equal(f.geometry.type, 'Polygon');
  }
  assert.deepEqual(fc, meshToGeoJSON(arrays));
  // insideFlags: true adds inside to a copy of the properties.
  const flagged = triangulateGeoJSON(features, { insideFlags: true });
  const rings = [island, lake, islet, square(110, 0, 120, 10), square(110, 20, 120, 30),
    square(110, 40, 120, 50)];
  for (const [t, f] of flagged.features.entries()) {
    const at = centroid(arrays, t);
    const source = featureAt(...at);
    assert.deepEqual(f.properties, { ...source?.properties, inside: holds(rings, ...at) });
    assert.notEqual(f.properties, source?.properties);
  }
  // The input without features: one region, no id, properties null.
  const bare = triangulateGeoJSON(bigF.geometry);
  assert.ok(bare.features.every((f) => !('id' in f) && f.properties === null));
  assert.equal(triangulateGeoJSON(bigF.geometry, { output: 'arrays' }).regionFeatures[0], null);
  // geoJSONToInput: the rings first, feature by feature, then the lines.
  const input = geoJSONToInput(features);
  assert.deepEqual(Array.from(input.polygons), [0, 1, 2, 3, 5, 6]);
  assert.equal(input.polylines.length, 7);
  assert.deepEqual(Array.from(input.polylines[6]), [-20, 10, 130, 10]);
  assert.deepEqual(triangulate(input).regions, arrays.regions);
});

test('triangulateGeoJSON keeps z: input positions and crossings', () => {
  const arrays = triangulateGeoJSON(features, { output: 'arrays' });
  const input = geoJSONToInput(features, { flat: true });
  assert.equal(input.values.length, arrays.inputToVertex.length);
  // Each input position's vertex has its height (the first given, when several share it).
  const first = new Map();
  for (let i = 0; i < input.values.length; i++) {
    const v = arrays.inputToVertex[i];
    if (!first.has(v) && !Number.isNaN(input.values[i])) first.set(v, input.values[i]);
  }
  for (const [v, z] of first) assert.equal(arrays.values[v], z, `vertex ${v}`);
  assert.equal(arrays.values[arrays.inputToVertex[0]], 999, 'the point of the GeometryCollection');
  // The road (heights 1 .. 2 over x from -20 to 130) crosses the island at x = 0 and x = 100,
  // where the island's edges (heights 100 + 2k) may cross it too: the road's height, or the
  // mean of both.
  for (const x of [0, 100]) {
    let v = -1;
    for (let i = 0; i < arrays.points.length / 2; i++) {
      if (arrays.points[2 * i] === x && arrays.points[2 * i + 1] === 10) v = i;
    }
    assert.ok(v >= 0, `a vertex at (${x}, 10)`);
    const alongRoad = 1 + (x + 20) / 150;
    const z = arrays.values[v];
    assert.ok(Math.abs(z - alongRoad) < 1e-12 || z >= (alongRoad + 100) / 2 - 1e-9
      || Number.isNaN(z), `crossing at ${x}: ${z}`);
  }
  // GeoJSON positions: [x, y, z] where the vertex has a height, [x, y] where it has none (the
  // lake's corners were given without one).
  const fc = triangulateGeoJSON(features);
  let three = 0, two = 0;
  for (const f of fc.features) {
    for (const p of f.geometry.coordinates[0]) {
      if (p.length === 3) three++;
      else if (p[0] === 20 && p[1] === 20) two++;
    }
  }
  assert.ok(three > 0 && two > 0);
});

function ringsOf(f) {
  const g = f.geometry;
  const parts = g === null ? [] : g.type === 'Polygon' ? [g.coordinates] : g.coordinates;
  return parts.flat().map((ring) => ring.flat());
}

function distanceToRing(ring, x, y) {
  let best = Infinity;
  for (let k = 0; k + 3 < ring.length; k += 2) {
    const [ax, ay, bx, by] = [ring[k], ring[k + 1], ring[k + 2], ring[k + 3]];
    const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    const s = l2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / l2)) : 0;
    best = Math.min(best, Math.hypot(ax + s * dx - x, ay + s * dy - y));
  }
  return best;
}

// Every sampled triangle against an exact point-in-polygon test of its centroid: an inside
// triangle lies in exactly one country and names it; one outside every country names none;
// where countries overlap, the smaller (by the area of the triangles found in each) is named.
function checkCountries(fc, samples) {
  const r = triangulateGeoJSON(fc, { output: 'arrays', insideFlags: true });
  const shapes = fc.features.map((f) => {
    const rings = ringsOf(f);
    const box = [Infinity, Infinity, -Infinity, -Infinity];
    for (const ring of rings) {
      for (let k = 0; k < ring.length; k += 2) {
        box[0] = Math.min(box[0], ring[k]);
        box[1] = Math.min(box[1], ring[k + 1]);
        box[2] = Math.max(box[2], ring[k]);
        box[3] = Math.max(box[3], ring[k + 1]);
      }
    }
    // Fiji, Russia and Antarctica cross the antimeridian: in the plane, some of their rings
    // run across the whole map and overlap other countries.
    return { f, rings, box, area: 0, wraps: box[2] - box[0] > 180 };
  });
  const T = r.triangles.length / 3;
  const all = samples >= T;
  const found = [];
  let checked = 0, inside = 0, outside = 0, shared = 0;
  for (let i = 0; i < Math.min(samples, T); i++) {
    const t = all ? i : Math.floor((i * 2_654_435_761) % T);
    const at = centroid(r, t);
    if (at === null) continue;
    const [x, y] = at;
    const near = 1e-9;
    const holders = [];
    let close = false;
    for (const s of shapes) {
      const [x0, y0, x1, y1] = s.box;
      if (x < x0 - near || y < y0 - near || x > x1 + near || y > y1 + near) continue;
      if (s.rings.some((ring) => distanceToRing(ring, x, y) < near)) close = true;
      if (holds(s.rings, x, y)) holders.push(s);
    }
    if (close) continue;
    checked++;
    const label = r.regions[t];
    assert.equal(r.inside[t] === 1, holders.length % 2 === 1, `inside flag at ${x}, ${y}`);
    if (holders.length === 0) {
      assert.equal(label, -1, `no country at ${x}, ${y}`);
      outside++;
      continue;
    }
    const named = r.regionFeatures[label];
    assert.ok(holders.some((s) => s.f === named),
      `${named?.properties.name} at ${x}, ${y}, inside ${holders.map((s) => s.f.properties.name)}`);
    // Besides the antimeridian's, the data has a few overlaps of its own (Sudan, South Sudan
    // and Ethiopia at 1:110m): an inside triangle lies in one country but there.
    if (r.inside[t] === 1 && !holders.some((s) => s.wraps)) shared += holders.length > 1;
    inside += r.inside[t];
    const p = r.points, tri = r.triangles;
    const [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
    const area = ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1])
      - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2;
    for (const s of holders) s.area += area;
    found.push({ t, holders });
  }
  assert.ok(checked > Math.min(samples, T) / 2 && inside > checked / 4 && outside > 0);
  assert.ok(shared < inside / 200, `${shared} of ${inside} inside triangles in two countries`);
  if (!all) return r;
  let overlaps = 0;
  for (const { t, holders } of found) {
    if (holders.length < 2) continue;
    const [small, next] = [...holders].sort((u, v) => u.area - v.area);
    if (next.area < 1.01 * small.area) continue;
    assert.equal(r.regionFeatures[r.regions[t]], small.f, `overlap at triangle ${t}`);
    overlaps++;
  }
  assert.ok(overlaps > 0, 'the antimeridian rings overlap others in the plane');
  return r;
}

test('Natural Earth 1:110m countries: every triangle names the country holding it', () => {
  const world = countries('110m');
  const r = checkCountries(world, Infinity);
  // As GeoJSON, the inside triangles carry their country's id and properties, and the region
  // arrays name the same country.
  const fc = triangulateGeoJSON(world, { keep: 'inside' });
  const byProperties = new Map(world.features.map((f) => [f.properties, f]));
  assert.equal(fc.features.length, r.inside.reduce((s, f) => s + f, 0));
  const kept = triangulateGeoJSON(world, { keep: 'inside', output: 'arrays' });
  for (const [t, f] of fc.features.entries()) {
    const country = byProperties.get(f.properties);
    assert.ok(country, `triangle ${t} has a country's properties`);
    assert.equal(f.id, country.id);
    assert.equal(kept.regionFeatures[kept.regions[t]], country);
  }
  assert.ok(new Set(fc.features.map((f) => f.properties)).size > 150);
});

test('Natural Earth 1:50m countries: a sample of triangles', () => {
  checkCountries(countries('50m'), 3_000);
});
