// voronoi() through the wasm build: the cells of uniform, clustered and lattice sites clipped to
// boxes, hulls and the Natural Earth countries tile the domain (their areas sum to its area),
// and random sample points lie in the cell of their nearest site and in no other (exact
// point-in-polygon with robust-predicates); GeoJSON keeps each site's feature; bad input throws
// a clear error and the module stays usable.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import {
  cellsToGeoJSON, init, triangulate, voronoi, voronoiGeoJSON,
} from 'geocdt';
import { orient } from './support/predicates.js';
import { throwsWith } from './support/throws.js';
import {
  countries, flatPolylines, gaussianClusters, lattice, random, uniform,
} from './support/inputs.js';

before(() => init());

// Where (x, y) lies against the closed ring at points b .. e - 1 of coords: 1 inside, 0 outside,
// -1 on it, exactly.
function inRing(coords, b, e, x, y) {
  let w = 0;
  for (let k = b; k + 1 < e; k++) {
    const ax = coords[2 * k], ay = coords[2 * k + 1];
    const bx = coords[2 * k + 2], by = coords[2 * k + 3];
    const o = orient(ax, ay, bx, by, x, y);
    if (o === 0 && Math.min(ax, bx) <= x && x <= Math.max(ax, bx) && Math.min(ay, by) <= y
      && y <= Math.max(ay, by)) return -1;
    if (ay <= y) {
      if (by > y && o > 0) w++;
    } else if (by <= y && o < 0) {
      w--;
    }
  }
  return w !== 0 ? 1 : 0;
}

// Where (x, y) lies against site i's cell: 1 inside, 0 outside, -1 on a ring.
function inCell(c, i, x, y) {
  for (let p = c.siteOffsets[i]; p < c.siteOffsets[i + 1]; p++) {
    let where = 0;
    for (let r = c.polygonOffsets[p]; r < c.polygonOffsets[p + 1]; r++) {
      const inside = inRing(c.coords, c.ringOffsets[r], c.ringOffsets[r + 1], x, y);
      if (inside < 0) return -1;
      if (r === c.polygonOffsets[p]) where = inside;
      else if (inside) where = 0;
    }
    if (where) return 1;
  }
  return 0;
}

function ringArea(coords, b, e) {
  let twice = 0;
  for (let k = b + 1; k + 1 < e; k++) {
    twice += (coords[2 * k] - coords[2 * b]) * (coords[2 * k + 3] - coords[2 * b + 1])
      - (coords[2 * k + 1] - coords[2 * b + 1]) * (coords[2 * k + 2] - coords[2 * b]);
  }
  return twice / 2;
}

// The layout (GeoArrow offsets, closed rings, outer rings counter-clockwise and holes
// clockwise) and the cells' total area.
function checkLayout(c, sites) {
  assert.equal(c.siteOffsets.length, sites + 1);
  assert.equal(c.siteOffsets[0], 0);
  assert.equal(c.polygonOffsets.length, c.siteOffsets[sites] + 1);
  assert.equal(c.ringOffsets.length, c.polygonOffsets[c.polygonOffsets.length - 1] + 1);
  assert.equal(c.coords.length, 2 * c.ringOffsets[c.ringOffsets.length - 1]);
  let area = 0;
  for (let p = 0; p + 1 < c.polygonOffsets.length; p++) {
    for (let r = c.polygonOffsets[p]; r < c.polygonOffsets[p + 1]; r++) {
      const b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
      assert.ok(e - b >= 4, `ring ${r} has ${e - b} points`);
      assert.equal(c.coords[2 * b], c.coords[2 * e - 2]);
      assert.equal(c.coords[2 * b + 1], c.coords[2 * e - 1]);
      const a = ringArea(c.coords, b, e);
      assert.ok(r === c.polygonOffsets[p] ? a > 0 : a < 0, `ring ${r} winds the wrong way`);
      area += a;
    }
  }
  return area;
}

// The nearest site to (x, y) and how much farther the second nearest is (brute force).
function nearest(sites, x, y) {
  let best = -1, first = Infinity, second = Infinity;
  for (let i = 0; i < sites.length / 2; i++) {
    const d = Math.hypot(x - sites[2 * i], y - sites[2 * i + 1]);
    if (d < first) {
      second = first;
      first = d;
      best = i;
    } else if (d < second && d > first) {
      second = d;
    }
  }
  return { best, margin: second - first };
}

// Random points of the box [x0, y0, x1, y1]: each inside the domain (inside(x, y)) lies in the
// cell of its nearest site and in no other; each outside, in no cell. Returns how many counted.
function checkSamples(c, sites, box, inside, count, seed = 1) {
  const rnd = random(seed);
  let checked = 0;
  for (let s = 0; s < count; s++) {
    const x = box[0] + (box[2] - box[0]) * rnd(), y = box[1] + (box[3] - box[1]) * rnd();
    const isIn = inside(x, y);
    if (isIn === null) continue;
    const { best, margin } = nearest(sites, x, y);
    if (margin <= 1e-9 * (1 + Math.abs(x) + Math.abs(y))) continue;
    let holders = 0;
    for (let i = 0; i < sites.length / 2; i++) {
      const where = inCell(c, i, x, y);
      assert.notEqual(where, -1, `sample ${x}, ${y} on a cell's edge`);
      if (where === 1) {
        assert.equal(i, best, `sample ${x}, ${y} in site ${i}'s cell, nearest ${best}`);
        holders++;
      }
    }
    assert.equal(holders, isIn ? 1 : 0, `sample ${x}, ${y} in ${holders} cells`);
    checked++;
  }
  return checked;
}

// The area of a mesh's triangles.
function meshArea({ points: p, triangles: t }) {
  let area = 0;
  for (let k = 0; k < t.length; k += 3) {
    const [a, b, c] = [2 * t[k], 2 * t[k + 1], 2 * t[k + 2]];
    area += ((p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[b + 1] - p[a + 1]) * (p[c] - p[a])) / 2;
  }
  return area;
}

const inBox = ([x0, y0, x1, y1]) => (x, y) => x > x0 && x < x1 && y > y0 && y < y1;

test('uniform, clustered and lattice sites in a box tile it', () => {
  const box = [0, 0, 1000, 1000];
  const cases = [uniform(600, 1), gaussianClusters(600, 2).map((v) => v * 10), lattice(20)
    .map((v) => v * 50 + 25)];
  for (const sites of cases) {
    const c = voronoi({ points: sites }, { clip: box });
    assert.ok(Math.abs(checkLayout(c, sites.length / 2) - 1e6) <= 1e-9 * 1e6);
    assert.equal(c.stats.domainArea, 1e6);
    assert.ok(checkSamples(c, sites, box, inBox(box), 300) > 250);
  }
});

test('without a clip: the sites\' bounding box; a single site gets it all', () => {
  const sites = uniform(200, 3);
  const c = voronoi({ points: sites });
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < sites.length; i += 2) {
    x0 = Math.min(x0, sites[i]); x1 = Math.max(x1, sites[i]);
    y0 = Math.min(y0, sites[i + 1]); y1 = Math.max(y1, sites[i + 1]);
  }
  const area = (x1 - x0) * (y1 - y0);
  assert.ok(Math.abs(checkLayout(c, 200) - area) <= 1e-9 * area);
  const one = voronoi({ points: [3, 4] }, { clip: [0, 0, 10, 10] });
  assert.deepEqual(Array.from(one.siteOffsets), [0, 1]);
  assert.equal(checkLayout(one, 1), 100);
  // Collinear sites without a clip: their box and hull have no area, so no cell has any.
  const flat = voronoi({ points: [0, 1, 2, 1, 5, 1] });
  assert.deepEqual(Array.from(flat.siteOffsets), [0, 0, 0, 0]);
});

test('hull clip; equal sites: the first gets the cell', () => {
  const sites = [...uniform(300, 4), 10, 10, 20, 20];
  sites.push(sites[0], sites[1], sites[2], sites[3]);
  const c = voronoi({ points: sites }, { clip: 'hull' });
  const n = sites.length / 2;
  checkLayout(c, n);
  assert.equal(c.siteOffsets[n] - c.siteOffsets[n - 2], 0, 'the later equal sites are empty');
  assert.ok(c.siteOffsets[1] > c.siteOffsets[0] && c.siteOffsets[2] > c.siteOffsets[1]);
  const hull = meshArea(triangulate({ points: sites }));
  assert.ok(Math.abs(c.stats.domainArea - hull) <= 1e-12 * hull);
  assert.ok(Math.abs(checkLayout(c, n) - hull) <= 1e-9 * hull);
});

test('cells clipped to the Natural Earth 110m countries sum to the land\'s area', () => {
  const land = countries('110m');
  const rings = [];
  for (const f of land.features) {
    const g = f.geometry;
    const polygons = g.type === 'Polygon' ? [g.coordinates] : g.coordinates;
    for (const polygon of polygons) for (const ring of polygon) rings.push(ring.flat());
  }
  const flat = flatPolylines(rings);
  const area = meshArea(triangulate({ polylines: flat }, { keep: 'inside' }));
  const sites = uniform(2000, 5).map((v, i) => (i % 2 === 0 ? v * 0.36 - 180 : v * 0.17 - 85));
  const c = voronoi({ points: sites, polylines: flat });
  const total = checkLayout(c, 2000);
  assert.ok(Math.abs(total - area) <= 1e-9 * area, `${total} against ${area}`);
  assert.ok(Math.abs(c.stats.domainArea - area) <= 1e-12 * area);
  assert.ok(c.stats.crossings > 1000 && c.stats.clippedCells > 500);
  // Array-of-rings form, nonzero fill: the same domain here (countries do not overlap).
  const nonzero = voronoi({ points: sites, polylines: rings }, { fillRule: 'nonzero' });
  assert.ok(Math.abs(checkLayout(nonzero, 2000) - area) <= 1e-9 * area);
});

test('a domain with a hole, sites outside it reaching in', () => {
  const outer = [0, 0, 100, 0, 100, 100, 0, 100, 0, 0];
  const hole = [30, 30, 70, 30, 70, 70, 30, 70, 30, 30];
  const sites = uniform(150, 6).map((v) => v * 0.14 - 20);
  const c = voronoi({ points: sites, polylines: [outer, hole] });
  assert.ok(Math.abs(checkLayout(c, 150) - 8400) <= 1e-9 * 8400);
  const inside = (x, y) => (x > 0 && x < 100 && y > 0 && y < 100)
    && !(x >= 30 && x <= 70 && y >= 30 && y <= 70);
  assert.ok(checkSamples(c, sites, [-20, -20, 120, 120], inside, 400) > 350);
  let reaching = 0;
  for (let i = 0; i < 150; i++) {
    const [x, y] = [sites[2 * i], sites[2 * i + 1]];
    const outside = x < 0 || x > 100 || y < 0 || y > 100 || (x > 30 && x < 70 && y > 30 && y < 70);
    if (outside && c.siteOffsets[i + 1] > c.siteOffsets[i]) reaching++;
  }
  assert.ok(reaching > 5);
});

test('Lloyd relaxation reports its steps and movement and spreads the sites', () => {
  const sites = gaussianClusters(200, 7);
  const box = [-20, -20, 120, 120];
  const one = voronoi({ points: sites }, { clip: box, lloyd: { iterations: 1 } });
  const many = voronoi({ points: sites }, { clip: box, lloyd: { iterations: 30 } });
  assert.equal(one.lloyd.iterations, 1);
  assert.equal(many.lloyd.iterations, 30);
  assert.ok(many.lloyd.movement < one.lloyd.movement);
  assert.equal(many.points.length, sites.length);
  checkLayout(many, 200);
  assert.ok(checkSamples(many, many.points, box, inBox(box), 200) > 150);
  const early = voronoi({ points: sites },
    { clip: box, lloyd: { iterations: 1000, tolerance: 0.5 } });
  assert.ok(early.lloyd.iterations < 1000 && early.lloyd.movement <= 0.5);
  assert.equal(voronoi({ points: sites }, { clip: box, lloyd: true }).lloyd.iterations, 10);
});

test('voronoiGeoJSON keeps each site\'s feature; cellsToGeoJSON', () => {
  const square = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]];
  const geojson = {
    type: 'FeatureCollection',
    features: [
      { type: 'Feature', id: 'land', properties: { kind: 'land' },
        geometry: { type: 'Polygon', coordinates: [square] } },
      { type: 'Feature', id: 'a', properties: { name: 'A' },
        geometry: { type: 'Point', coordinates: [2, 2] } },
      { type: 'Feature', properties: { name: 'BC' },
        geometry: { type: 'MultiPoint', coordinates: [[8, 8], [30, 30]] } },
    ],
  };
  const fc = voronoiGeoJSON(geojson);
  assert.equal(fc.type, 'FeatureCollection');
  assert.equal(fc.features.length, 3);
  assert.equal(fc.features[0].id, 'a');
  assert.equal(fc.features[0].properties, geojson.features[1].properties);
  assert.equal(fc.features[1].properties, geojson.features[2].properties);
  assert.equal(fc.features[2].properties, geojson.features[2].properties);
  assert.equal(fc.features[0].geometry.type, 'MultiPolygon');
  assert.deepEqual(fc.features[0].geometry.coordinates[0][0][0],
    fc.features[0].geometry.coordinates[0][0].at(-1));
  assert.equal(fc.features[2].geometry, null, 'a site whose cell misses the domain');
  const arrays = voronoiGeoJSON(geojson, { output: 'arrays' });
  assert.equal(arrays.siteFeatures[1], geojson.features[2]);
  assert.equal(checkLayout(arrays, 3), 100);
  const plain = cellsToGeoJSON(voronoi({ points: [1, 1, 2, 2] }, { clip: [0, 0, 3, 3] }));
  assert.deepEqual(plain.features.map((f) => f.id), [0, 1]);
});

test('bad input: a clear error, and the module stays usable', () => {
  const points = [0, 0, 1, 1];
  throwsWith(() => voronoi({ points: [] }), RangeError, /at least one site/);
  throwsWith(() => voronoi(points), TypeError, /voronoi\(\) takes an object/);
  throwsWith(() => voronoi({ points }, { clip: [1, 0, 0, 1] }), RangeError,
    /xmin < xmax and ymin < ymax/);
  throwsWith(() => voronoi({ points }, { clip: [0, 0, 1] }), RangeError, /\[xmin, ymin, xmax, ymax\]/);
  throwsWith(() => voronoi({ points }, { clip: [0, 0, NaN, 1] }), RangeError, /clip\[2\] is NaN/);
  throwsWith(() => voronoi({ points }, { clip: 'box' }), TypeError, /options\.clip/);
  throwsWith(() => voronoi({ points }, { clip: 'rings' }), RangeError, /holds no ring/);
  throwsWith(() => voronoi({ points }, { fillRule: 'odd' }), TypeError, /fillRule/);
  throwsWith(() => voronoi({ points }, { lloyd: { iterations: 0 } }), RangeError, /iterations/);
  throwsWith(() => voronoi({ points: [0, 0, NaN, 1] }), RangeError, /points\[2\] \(x of point 1\) is NaN/);
  throwsWith(() => voronoi({ points: [0, 0, 1, 1], polylines: [[0, 0, 1, 0, Infinity, 1, 0, 0]] }),
    RangeError, /polylines\[0\]\[4\] \(x of point 2 of polyline 0\) is Infinity/);
  const c = voronoi({ points }, { clip: [-1, -1, 2, 2] });
  assert.equal(checkLayout(c, 2), 9);
});
