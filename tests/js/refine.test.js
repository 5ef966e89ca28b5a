// Delaunay refinement through the JS API, the incremental class and the worker: valid
// constrained Delaunay output (exact predicates), the angle and area bounds met where the
// stats say, Steiner records that place their vertices, and option errors.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation } from 'geocdt';
import { createWorker } from 'geocdt/worker';
import { checkMesh } from './support/invariants.js';
import { checkConstraints } from './support/constraints.js';
import { uniform } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

function circle(cx, cy, r, n) {
  const ring = [];
  for (let i = 0; i <= n; i++) {
    const a = (2 * Math.PI * (i % n)) / n;
    ring.push(cx + r * Math.cos(a), cy + r * Math.sin(a));
  }
  return ring;
}

const squareWithHole = {
  polylines: [[0, 0, 10, 0, 10, 10, 0, 10, 0, 0], circle(5, 5, 2, 24)],
};

function smallestAngle(r, t) {
  const p = r.points, tri = r.triangles;
  let smallest = 180;
  for (let k = 0; k < 3; k++) {
    const a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3], c = tri[3 * t + (k + 2) % 3];
    const ux = p[2 * b] - p[2 * a], uy = p[2 * b + 1] - p[2 * a + 1];
    const vx = p[2 * c] - p[2 * a], vy = p[2 * c + 1] - p[2 * a + 1];
    const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
    smallest = Math.min(smallest, (angle * 180) / Math.PI);
  }
  return smallest;
}

function area(r, t) {
  const p = r.points, tri = r.triangles;
  const [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
  return Math.abs((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1])
    - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2;
}

// Triangles (inside ones, when inside flags are given) missing the bounds.
function badTriangles(r, minAngle, maxArea = Infinity) {
  let bad = 0;
  for (let t = 0; t < r.triangles.length / 3; t++) {
    if (r.inside && !r.inside[t]) continue;
    if (smallestAngle(r, t) < minAngle * (1 - 1e-9) || area(r, t) > maxArea * (1 + 1e-9)) bad++;
  }
  return bad;
}

function checkSteiner(r) {
  const n = r.steiner.length;
  assert.equal(r.steinerParents.length, 3 * n);
  assert.equal(r.steinerWeights.length, 3 * n);
  for (let i = 0; i < n; i++) {
    const v = r.steiner[i];
    let x = 0, y = 0, sum = 0;
    for (let k = 0; k < 3; k++) {
      const p = r.steinerParents[3 * i + k], w = r.steinerWeights[3 * i + k];
      if (p === 0xffffffff) {
        assert.equal(w, 0);
        continue;
      }
      assert.ok(p < v, 'parents come before their Steiner vertex');
      x += w * r.points[2 * p];
      y += w * r.points[2 * p + 1];
      sum += w;
    }
    assert.ok(Math.abs(sum - 1) < 1e-9, 'weights sum to 1');
    assert.ok(Math.abs(x - r.points[2 * v]) < 1e-9 && Math.abs(y - r.points[2 * v + 1]) < 1e-9,
      `Steiner vertex ${v} is where its weights put it`);
  }
}

test('refine in triangulate(): 30 degrees inside a square with a hole', () => {
  const r = triangulate(squareWithHole, { refine: { minAngle: 30 }, insideFlags: true });
  checkMesh(r, squareWithHole);
  checkConstraints(r, squareWithHole);
  checkSteiner(r);
  assert.ok(r.steiner.length > 0);
  assert.equal(r.stats.steinerPoints, r.steiner.length);
  assert.equal(r.stats.refineSkipped, 0);
  assert.equal(r.stats.refineCapped, 0);
  assert.equal(badTriangles(r, 30), 0);
});

test('keep: inside refines only the inside; maxArea bounds the areas', () => {
  const inside = triangulate(squareWithHole, {
    keep: 'inside', refine: { minAngle: 25, maxArea: 0.1 },
  });
  checkMesh(inside, squareWithHole, { keepAll: false });
  assert.equal(badTriangles(inside, 25, 0.1), 0);
  for (const v of inside.steiner) {
    const dx = inside.points[2 * v] - 5, dy = inside.points[2 * v + 1] - 5;
    assert.ok(dx * dx + dy * dy > 4 * 0.98, 'no Steiner vertex in the hole');
  }
  const all = triangulate(squareWithHole, { refine: { minAngle: 25, maxArea: 0.1 } });
  assert.ok(all.steiner.length > inside.steiner.length);
});

test('refine: true takes the defaults (20 degrees); points alone refine their hull', () => {
  const input = { points: [0, 0, 64, 0, 64, 64, 0, 64, ...uniform(300, 3, 64)] };
  const r = triangulate(input, { refine: true });
  checkMesh(r, input);
  checkSteiner(r);
  assert.equal(badTriangles(r, 20), r.stats.refineSkipped);
});

test('the cap ends refinement and says so', () => {
  const r = triangulate(squareWithHole, {
    keep: 'inside', refine: { minAngle: 33, maxSteinerPoints: 5 },
  });
  assert.equal(r.steiner.length, 5);
  assert.equal(r.stats.refineCapped, 1);
  assert.ok(r.stats.refineSkipped > 0);
  checkMesh(r, squareWithHole, { keepAll: false });
});

test('Triangulation#refine, then more insertions and again', () => {
  const t = new Triangulation();
  t.insertPolyline(squareWithHole.polylines[0]);
  t.insertPolyline(squareWithHole.polylines[1]);
  const stats = t.refine({ minAngle: 28, keep: 'inside' });
  assert.ok(stats.steinerPoints > 0);
  assert.equal(stats.refineSkipped, 0);
  const first = t.results({ keep: 'inside' });
  checkSteiner(first);
  assert.equal(badTriangles(first, 28), 0);
  t.insertPolyline([1, 1, 9, 2]);
  t.refine({ minAngle: 28 });
  const again = t.results();
  checkSteiner(again);
  assert.ok(again.steiner.length > first.steiner.length);
  assert.equal(badTriangles(again, 28), 0);
  t.dispose();
});

test('bad refine options are TypeErrors and RangeErrors', () => {
  const refine = (value) => () => triangulate(squareWithHole, { refine: value });
  throwsWith(refine('yes'), TypeError, /options\.refine must be an object/);
  throwsWith(refine({ minAngle: '30' }), TypeError, /minAngle must be a number/);
  throwsWith(refine({ minAngle: 60 }), RangeError, /minAngle must be a number of degrees/);
  throwsWith(refine({ minAngle: -1 }), RangeError, /minAngle/);
  throwsWith(refine({ maxArea: 0 }), RangeError, /maxArea must be a positive number/);
  throwsWith(refine({ maxSteinerPoints: 1.5 }), RangeError, /maxSteinerPoints/);
  const t = new Triangulation();
  throwsWith(() => t.refine({ minAngle: NaN }), RangeError, /options\.minAngle/);
  throwsWith(() => t.refine(3), TypeError, /options must be an object/);
  t.dispose();
});

test('the worker refines too', async () => {
  const worker = createWorker();
  try {
    const r = await worker.triangulate(squareWithHole, {
      keep: 'inside', refine: { minAngle: 30 },
    });
    assert.ok(r.steiner.length > 0);
    assert.equal(badTriangles(r, 30), 0);
    const t = worker.createTriangulation();
    await t.insertPolyline(squareWithHole.polylines[0]);
    const stats = await t.refine({ minAngle: 30, maxArea: 1 });
    assert.ok(stats.steinerPoints > 0);
    const mesh = await t.results();
    assert.equal(badTriangles(mesh, 30, 1), 0);
    await t.dispose();
  } finally {
    worker.terminate();
  }
});
