// Polylines as constraints: crossings split, provenance, inside/outside by even-odd or nonzero.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation, memoryUsage } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { area, checkConstraints, checkInsideFlags } from './support/constraints.js';
import { random, uniform } from './support/inputs.js';
import { isRoundedCrossing } from './support/exact.js';

before(() => init());

function check(input, options = {}) {
  const r = triangulate(input, { insideFlags: true, segmentSources: true, ...options });
  const keepAll = options.keep !== 'inside';
  checkMesh(r, input, { keepAll });
  checkConstraints(r, input, { keepAll });
  checkInsideFlags(r, input, options.fillRule);
  return r;
}

const square = (x0, y0, x1, y1) => [x0, y0, x1, y0, x1, y1, x0, y1, x0, y0];

test('one segment through a cloud becomes constrained edges', () => {
  const input = { points: uniform(2_000, 3), polylines: [[10, 10, 990, 990]] };
  const r = check(input);
  assert.ok(r.constrained.some((c) => c === 1));
  assert.equal(r.stats.polylines, 1);
  assert.equal(r.stats.segments, 1);
});

test('two crossing segments meet at a new vertex', () => {
  const input = { points: [0, 0, 2, 0, 2, 2, 0, 2], polylines: [[-1, 1, 3, 1], [1, -1, 1, 3]] };
  const r = check(input);
  assert.equal(r.points.length / 2, 9, '4 points, 4 polyline ends and 1 crossing');
  assert.equal(r.stats.crossings, 1);
  assert.equal(r.constraintEdges.length, 4);
  let found = false;
  for (let v = 0; v < r.points.length / 2; v++) {
    found ||= r.points[2 * v] === 1 && r.points[2 * v + 1] === 1;
  }
  assert.ok(found, 'the crossing (1, 1) is a vertex');
  assert.deepEqual(Array.from(r.inputToVertex.subarray(4)).every((v) => v < 9), true);
});

test('a crossing is the nearest double to where the segments cross, on every platform', () => {
  // Rounded exactly (native builds and WebAssembly agree bit for bit): the new vertex of each
  // pair of lon/lat segments holds the exact crossing of the two in its rounding interval.
  const rnd = random(11);
  for (let i = 0; i < 300; i++) {
    const px = -180 + 360 * rnd(), py = -85 + 170 * rnd();
    const ends = (angle) => {
      const c = Math.cos(angle), s = Math.sin(angle), r0 = 0.5 + rnd(), r1 = 0.5 + rnd();
      return [px - r0 * c, py - r0 * s, px + r1 * c, py + r1 * s];
    };
    const angle = Math.PI * rnd();
    const s = ends(angle), t = ends(angle + 0.2 + 2.7 * rnd());
    const r = triangulate({ polylines: [s, t] });
    assert.equal(r.points.length, 10, `pair ${i}: one new vertex`);
    assert.ok(isRoundedCrossing(s, t, r.points[8], r.points[9]),
      `pair ${i}: (${r.points[8]}, ${r.points[9]}) is not the crossing rounded`);
  }
});

test('a star of 64 segments through one point', () => {
  const polylines = [];
  for (let i = 0; i < 64; i++) {
    const a = (Math.PI * i) / 64;
    polylines.push([100 * Math.cos(a), 100 * Math.sin(a), -100 * Math.cos(a), -100 * Math.sin(a)]);
  }
  check({ polylines });
});

test('collinear overlapping chains, backtracking, repeated points, zero-length segments', () => {
  const polylines = [
    [0, 0, 10, 0],
    [5, 0, 15, 0, 20, 0],
    [2, 0, 8, 0, 3, 0, 12, 0],       // backtracks over itself and the others
    [1, 1, 1, 1, 4, 4, 4, 4, 4, 4],  // repeated points: zero-length segments
    [0, -5, 20, 5],                  // crosses the chain
  ];
  const r = check({ points: [0, 10, 20, -10], polylines });
  // The overlap of [0,10] with [5,20] names both polylines.
  const bothSources =
    r.constraintEdges.some((e, i) => r.sourceOffsets[i + 1] - r.sourceOffsets[i] >= 2);
  assert.ok(bothSources, 'an overlapping piece lists every polyline it came from');
});

test('a T-junction: a vertex lying on a segment splits it', () => {
  check({ polylines: [[0, 0, 10, 0], [5, 0, 5, 5]] });
});

test('rings: keep inside drops the hole and the outside (even-odd)', () => {
  // An island in a lake.
  const polylines = [square(0, 0, 10, 10), square(3, 3, 6, 6), square(4, 4, 5, 5)];
  const input = { points: [-5, -5, 15, 15, 20, 0], polylines };
  const all = check(input);
  const kept = check(input, { keep: 'inside' });
  assert.equal(area(kept), 100 - 9 + 1);
  assert.ok(kept.inside.every((f) => f === 1));
  assert.equal(kept.triangles.length / 3, all.inside.reduce((s, f) => s + f, 0));
});

test('rings sharing vertices and edges', () => {
  // Two squares side by side share an edge; a third shares one corner.
  const polylines = [square(0, 0, 4, 4), square(4, 0, 8, 4), square(8, 4, 12, 8)];
  const kept = check({ polylines }, { keep: 'inside' });
  assert.equal(area(kept), 48);
});

test('nonzero fill counts overlapping rings once, even-odd cancels them', () => {
  const polylines = [square(0, 0, 4, 4), square(2, 2, 6, 6)];
  const evenodd = check({ polylines }, { keep: 'inside' });
  const nonzero = check({ polylines }, { keep: 'inside', fillRule: 'nonzero' });
  assert.equal(area(evenodd), 32 - 8);
  assert.equal(area(nonzero), 28);
});

test('hundreds of random crossing segments', () => {
  const rnd = random(99);
  const polylines =
    Array.from({ length: 400 }, () => [rnd() * 1e3, rnd() * 1e3, rnd() * 1e3, rnd() * 1e3]);
  const r = check({ points: uniform(5_000, 8), polylines });
  assert.ok(r.stats.crossings > 5_000, `crossings: ${r.stats.crossings}`);
});

test('insertPolyline on a Triangulation, then results with inside flags', () => {
  const t = new Triangulation();
  t.insertPoints(uniform(500, 12).map((v) => v / 100));
  const ring = square(2, 2, 8, 8);
  const ids = t.insertPolyline(ring);
  assert.equal(ids.length, 5);
  assert.equal(ids[0], ids[4]);
  assert.equal(t.polylineCount, 1);
  t.insertPolyline([0, 5, 10, 5]);
  assert.equal(t.polylineCount, 2);
  const r = t.results({ insideFlags: true });
  checkMesh(r);
  checkInsideFlags(r, { polylines: [ring, [0, 5, 10, 5]] });
  assert.ok(Math.abs(area(t.results({ keep: 'inside' })) - 36) < 1e-9);
  t.dispose();
});

test('a tangle a few ulps wide: every chain within two ulps of its segment, in order', () => {
  // Rings and lines within 3e-11 of (1, -12345.678), where every crossing rounds onto the
  // same few doubles: snap-rounded, and held to the bound exactly. (Inside flags follow the
  // snap-rounded rings; triangles an ulp wide cannot be compared with the input's.)
  const polylines = [
    [
      1.0000000000191722, -12345.677999999965, 1.0000000000268119, -12345.677999999991, 1,
      -12345.678, 1.0000000000043656, -12345.677999999998, 1.0000000000009823, -12345.677999999996,
      0.99999999999818101, -12345.677999999987, 1.0000000000021101, -12345.677999999998,
      1.0000000000086766, -12345.677999999976, 1.0000000000023648, -12345.677999999998,
      0.99999999999949063, -12345.677999999998, 1.0000000000040017, -12345.677999999978,
      1.0000000000192086, -12345.677999999994, 1.0000000000137153, -12345.677999999994,
      1.0000000000008002, -12345.677999999998, 0.99999999999818101, -12345.677999999987,
      1.0000000000026739, -12345.677999999996, 1.0000000000191722, -12345.677999999965
    ],
    [
      1.0000000000043656, -12345.677999999998, 0.99999999999770806, -12345.677999999993, 1,
      -12345.678, 1.0000000000006184, -12345.677999999998, 1.0000000000043656, -12345.677999999998
    ],
    [1, -12345.678],
    [1, -12345.678],
    [
      1, -12345.678, 1, -12345.678, 1, -12345.678, 0.99999999999898137, -12345.677999999996,
      0.99999999999210554, -12345.677999999973, 1.0000000000073488, -12345.677999999996,
      1.0000000000043656, -12345.677999999998
    ],
    [
      1.0000000000004274, -12345.677999999993, 1.0000000000147429, -12345.677999999993,
      1.0000000000139244, -12345.677999999971, 1.0000000000082991, -12345.677999999984, 1,
      -12345.678, 1, -12345.678, 1, -12345.678, 1.0000000000174623, -12345.677999999994,
      1.0000000000008731, -12345.678, 1, -12345.678, 1, -12345.678, 1, -12345.678,
      1.0000000000021827, -12345.678, 1.0000000000003091, -12345.678, 1.0000000000201907,
      -12345.677999999969, 1, -12345.678, 1.0000000000004274, -12345.677999999993
    ],
  ];
  const input = { polylines };
  const r = triangulate(input);
  checkMesh(r, input);
  checkConstraints(r, input);
  const t = new Triangulation();
  for (const line of polylines) t.insertPolyline(line);
  checkMesh(t.results());
  t.dispose();
});

// A polyline whose first point repeats the vertex made last before it (id base - 1), going on
// to a new vertex (id base): its first segment joins the two ids around the batch's start.
// In wasm, where size_t has 32 bits, the index of that pair wrapped to -1 and a byte before
// an array was written, which broke the allocator (a trap, or a corrupt heap).
test('a segment from the vertex before a batch to the batch\'s first vertex', () => {
  check({ points: [0, 0], polylines: [[0, 0, 1, 1], [0, 1, 1, 0]] });
  check({ points: [0, 0, 0, 0, 0, 0], polylines: [[0, 0, 1, 1], [0, 1, 1, 0]] });
  for (const n of [10, 200, 3_000]) {
    const points = uniform(n, 5);
    // Then across the cloud, x going up: no crossings of its own.
    const line = [points[2 * n - 2], points[2 * n - 1]];
    for (let i = 0; i < n; i++) line.push((1000 * (i + 0.5)) / n, 500 + 300 * Math.sin(i / 7));
    const r = check({ points, polylines: [line] });
    assert.equal(r.inputToVertex[n], n - 1, 'the polyline starts at the last point');
    assert.equal(r.inputToVertex[n + 1], n, 'and goes on to the first new vertex');
    const t = new Triangulation();
    try {
      const pointIds = t.insertPoints(points);
      const ids = t.insertPolyline(line);
      assert.deepEqual([ids[0], ids[1]], [n - 1, n]);
      const m = t.results({ segmentSources: true });
      m.inputToVertex = Uint32Array.from([...pointIds, ...ids]);
      checkMesh(m, { points, polylines: [line] }, { keepAll: true });
      checkConstraints(m, { points, polylines: [line] }, { keepAll: true });
    } finally {
      t.dispose();
    }
  }
  assert.equal(triangulate({ points: [0, 0, 4, 0, 0, 4] }).triangles.length, 3,
    'the heap is whole: later calls work');
});

test('the checker refuses a chain beyond the bound', () => {
  // Segment (0, 0)-(4, 0) has the bound 2^-49 (two spacings at 4); its crossing with
  // x = 2 moved up by more than that no longer passes.
  const input = { polylines: [[0, 0, 4, 0], [2, -1, 2, 1]] };
  const r = triangulate(input);
  checkConstraints(r, input);
  const crossing = r.points.findIndex((v, i) => i % 2 === 0 && v === 2 && r.points[i + 1] === 0);
  const moved = { ...r, points: Float64Array.from(r.points) };
  moved.points[crossing + 1] = 2 ** -49;
  checkConstraints(moved, input);
  moved.points[crossing + 1] = 1.1 * 2 ** -49;
  assert.throws(() => checkConstraints(moved, input), /bound/);
});

test('constraint calls leave the heap at its baseline', () => {
  const input = {
    points: uniform(50, 1),
    polylines: [[0, 0, 1000, 1000], square(100, 100, 900, 900)],
  };
  triangulate(input);
  const baseline = memoryUsage().allocatedBytes;
  for (let i = 0; i < 2_000; i++) triangulate(input, { keep: i % 2 ? 'inside' : 'all' });
  assert.equal(memoryUsage().allocatedBytes, baseline);
});

test('the checker refuses a route that names the wrong segment', () => {
  // Segments 0 = (0,0)-(4,0) and 1 = (2,-1)-(2,1) cross at (2,0): four edges, each on one.
  const input = { polylines: [[0, 0, 4, 0], [2, -1, 2, 1]] };
  const r = triangulate(input, { segmentSources: true });
  checkConstraints(r, input);
  const swapped = { ...r, segmentSources: r.segmentSources.map((t) => 1 - t) };
  assert.throws(() => checkConstraints(swapped, input), /segment/);
  const none = { ...r, segmentOffsets: new Uint32Array(r.segmentOffsets.length),
    segmentSources: new Uint32Array(0) };
  assert.throws(() => checkConstraints(none, input), /covered|no segment/);
});

test('real data: Natural Earth 110m country rings, shared borders overlapping', async () => {
  const { createRequire } = await import('node:module');
  const { readFileSync } = await import('node:fs');
  const { feature } = await import('topojson-client');
  const require = createRequire(import.meta.url);
  const topology =
    JSON.parse(readFileSync(require.resolve('world-atlas/countries-110m.json'), 'utf8'));
  const polylines = [];
  for (const f of feature(topology, topology.objects.countries).features) {
    const parts = f.geometry.type === 'Polygon' ? [f.geometry.coordinates] : f.geometry.coordinates;
    for (const rings of parts) {
      for (const ring of rings) polylines.push(Float64Array.from(ring.flat()));
    }
  }
  const r = check({ polylines });
  const shared = r.constraintEdges
    .filter((e, i) => r.sourceOffsets[i + 1] - r.sourceOffsets[i] >= 2).length;
  assert.ok(shared > 1_000, `borders shared by two countries: ${shared}`);
  const kept = check({ polylines }, { keep: 'inside' });
  assert.equal(kept.triangles.length / 3, r.inside.reduce((s, f) => s + f, 0));
});

test('segmentSources names the input segments each constrained edge lies on', () => {
  // Segments, numbered across polylines, a repeated point making none: 0 = (0,0)-(4,0),
  // 1 = (4,0)-(4,4), 2 = (2,-1)-(2,5) crossing 0 at (2,0), 3 = (0,0)-(2,0) along 0.
  const polylines = [[0, 0, 4, 0, 4, 0, 4, 4], [2, -1, 2, 5], [0, 0, 2, 0]];
  const r = check({ polylines }, { segmentSources: true });
  assert.equal(r.segmentOffsets.length, r.constraintEdges.length + 1);
  assert.equal(r.segmentOffsets[r.segmentOffsets.length - 1], r.segmentSources.length);
  // Each edge by its end coordinates, with its segments.
  const segmentsOfEdges = (m) => {
    const lies = {};
    m.constraintEdges.forEach((e, i) => {
      const ends = [m.triangles[e], m.triangles[e % 3 === 2 ? e - 2 : e + 1]]
        .map((v) => [m.points[2 * v], m.points[2 * v + 1]])
        .sort((p, q) => p[0] - q[0] || p[1] - q[1]);
      lies[ends.join('-')] = Array.from(
        m.segmentSources.subarray(m.segmentOffsets[i], m.segmentOffsets[i + 1])).sort();
    });
    return lies;
  };
  const expected = {
    '0,0-2,0': [0, 3], '2,0-4,0': [0], '4,0-4,4': [1], '2,-1-2,0': [2], '2,0-2,5': [2],
  };
  assert.deepEqual(segmentsOfEdges(r), expected);
  // Without the option the arrays are not there; the incremental results take it too.
  const plain = triangulate({ polylines });
  assert.equal(plain.segmentSources, undefined);
  assert.equal(plain.segmentOffsets, undefined);
  const t = new Triangulation();
  for (const p of polylines) t.insertPolyline(p);
  assert.deepEqual(segmentsOfEdges(t.results({ segmentSources: true })), expected);
  t.dispose();
  assert.throws(() => triangulate({ polylines }, { segmentSources: 1 }),
    (e) => e instanceof TypeError && /options\.segmentSources must be a boolean/.test(e.message));
});
