// The invariants every geocdt result must satisfy, checked with exact predicates on the JS
// output (the same list as the core's checker).
import assert from 'node:assert/strict';
import { inCircle, orient } from './predicates.js';

const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

// input: { points, polylines } as given to triangulate(); r: its result. With keepAll false
// (keep: 'inside') the mesh covers part of the hull only: hull and Euler checks are skipped.
// With delaunay false (a mesh mapped to other coordinates, whose rounding may break
// cocircular ties), the in-circle check is.
export function checkMesh(r, input = {}, { keepAll = true, delaunay = true } = {}) {
  const { points, triangles, halfedges, constrained } = r;
  const V = points.length / 2;
  const E = triangles.length;
  const T = E / 3;
  assert.equal(E % 3, 0, 'triangles holds 3 ids per triangle');
  assert.equal(halfedges.length, E, 'one twin per half-edge');
  assert.equal(constrained.length, E, 'one constrained flag per half-edge');
  const x = (v) => points[2 * v];
  const y = (v) => points[2 * v + 1];

  // Vertices are distinct.
  const order = Array.from({ length: V }, (_, i) => i).sort((a, b) => x(a) - x(b) || y(a) - y(b));
  for (let i = 1; i < V; i++) {
    const a = order[i - 1], b = order[i];
    assert.ok(x(a) !== x(b) || y(a) !== y(b), `vertices ${a} and ${b} are equal`);
  }

  const used = new Uint8Array(V);
  for (let t = 0; t < T; t++) {
    const [a, b, c] = [triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]];
    assert.ok(a < V && b < V && c < V, `triangle ${t} has a vertex id out of range`);
    used[a] = used[b] = used[c] = 1;
    assert.ok(orient(x(a), y(a), x(b), y(b), x(c), y(c)) > 0,
      `triangle ${t} (${a}, ${b}, ${c}) is not strictly counter-clockwise`);
  }

  let hullEdges = 0;
  const hullNext = new Map();
  for (let e = 0; e < E; e++) {
    const twin = halfedges[e];
    const from = triangles[e];
    const to = triangles[next(e)];
    if (twin === -1) {
      hullEdges++;
      if (keepAll) assert.ok(!hullNext.has(from), `two hull edges leave vertex ${from}`);
      hullNext.set(from, to);
      continue;
    }
    assert.ok(twin >= 0 && twin < E, `halfedges[${e}] out of range`);
    assert.equal(halfedges[twin], e, `half-edges ${e} and ${twin} are not twins`);
    assert.equal(triangles[twin], to, `twin of ${e} does not start where ${e} ends`);
    assert.equal(triangles[next(twin)], from, `twin of ${e} does not end where ${e} starts`);
    assert.equal(constrained[e], constrained[twin], `constrained flag differs across edge ${e}`);
    if (constrained[e] || twin < e || !delaunay) continue;
    // Locally Delaunay: the apex across the edge is not strictly inside the circumcircle.
    const a = triangles[e], b = triangles[next(e)], c = triangles[next(next(e))];
    const d = triangles[next(next(twin))];
    assert.ok(inCircle(x(a), y(a), x(b), y(b), x(c), y(c), x(d), y(d)) <= 0,
      `edge ${e} (${a}-${b}) is not locally Delaunay`);
  }

  if (T > 0 && keepAll) {
    // The boundary is one closed loop with no reflex turn: the convex hull.
    const start = hullNext.keys().next().value;
    let v = start;
    let steps = 0;
    do {
      const w = hullNext.get(v);
      assert.ok(w !== undefined, `the hull is not closed at vertex ${v}`);
      const u = hullNext.get(w);
      assert.ok(orient(x(v), y(v), x(w), y(w), x(u), y(u)) >= 0, `reflex hull turn at vertex ${w}`);
      v = w;
      steps++;
      assert.ok(steps <= hullEdges, 'the hull does not close');
    } while (v !== start);
    assert.equal(steps, hullEdges, 'the hull is more than one loop');
    // Euler's count for a triangulated convex polygon with h boundary vertices.
    assert.equal(T, 2 * V - hullEdges - 2, 'Euler: T = 2V - h - 2');
    for (let v = 0; v < V; v++) assert.ok(used[v], `vertex ${v} is in no triangle`);
  }

  // Every input point is a vertex, at exactly its coordinates.
  if (r.inputToVertex) {
    const all = [input.points ?? [], ...(input.polylines ?? [])];
    let i = 0;
    for (const xy of all) {
      for (let k = 0; k < xy.length; k += 2, i++) {
        const v = r.inputToVertex[i];
        assert.ok(v < V, `inputToVertex[${i}] out of range`);
        assert.ok(x(v) === xy[k] && y(v) === xy[k + 1], `input point ${i} is not vertex ${v}`);
      }
    }
    assert.equal(i, r.inputToVertex.length, 'one inputToVertex entry per input point');
  }
  return { V, T, hullEdges };
}
