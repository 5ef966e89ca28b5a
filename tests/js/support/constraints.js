// Constraint invariants on the JS output: each input segment is a chain of constrained edges
// whose vertices lie within the documented bound of it (two spacings of doubles at its
// largest coordinate, decided exactly) in order along it, no constrained edge lies beyond the
// bound of every input segment, provenance names the polylines an edge came from, and inside
// flags follow the fill rule over the rings.
import assert from 'node:assert/strict';
import { chainBound, signAlong, withinDistance } from './exact.js';
import { orient } from './predicates.js';

const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

// [minX, minY, maxX, maxY] of a polyline, widened a little for rounded crossing points.
function boxOf(line) {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let k = 0; k < line.length; k += 2) {
    minX = Math.min(minX, line[k]); maxX = Math.max(maxX, line[k]);
    minY = Math.min(minY, line[k + 1]); maxY = Math.max(maxY, line[k + 1]);
  }
  const pad = 1e-9 * (Math.abs(minX) + Math.abs(maxX) + Math.abs(minY) + Math.abs(maxY) + 1);
  return [minX - pad, minY - pad, maxX + pad, maxY + pad];
}

function segmentsOf(line) {
  const out = [];
  for (let k = 0; k + 3 < line.length; k += 2) {
    if (line[k] !== line[k + 2] || line[k + 1] !== line[k + 3]) {
      out.push([line[k], line[k + 1], line[k + 2], line[k + 3]]);
    }
  }
  return out;
}

// Whether (x, y) lies within the documented bound of segment s.
function withinBound(s, x, y) {
  return withinDistance(s, x, y, chainBound(s));
}

// Whether (x, y) lies exactly on segment s: on its line, within its box.
function exactlyOn([ax, ay, bx, by], x, y) {
  return orient(ax, ay, bx, by, x, y) === 0 && Math.min(ax, bx) <= x && x <= Math.max(ax, bx)
    && Math.min(ay, by) <= y && y <= Math.max(ay, by);
}

export function isRing(line) {
  const n = line.length;
  return n >= 8 && line[0] === line[n - 2] && line[1] === line[n - 1];
}

// With keepAll false (keep: 'inside') constrained edges between two outside triangles are
// gone, so the segment coverage is not checked; provenance still is. With overlaps false, an
// edge exactly on a segment need not name its polyline: in tangles of crossings a few ulps
// apart, overlapping segments can take chains that part (README, "Known limitations").
export function checkConstraints(r, input, { keepAll = true, overlaps = true } = {}) {
  const { points, triangles, halfedges, constrained } = r;
  const polylines = input.polylines ?? [];
  const x = (v) => points[2 * v], y = (v) => points[2 * v + 1];
  const neighbours = new Map();
  const edges = [];
  for (let e = 0; e < triangles.length; e++) {
    if (!constrained[e]) continue;
    const a = triangles[e], b = triangles[next(e)];
    if (!neighbours.has(a)) neighbours.set(a, []);
    neighbours.get(a).push(b);
    if (halfedges[e] === -1 || halfedges[e] > e) edges.push(e);
    if (halfedges[e] === -1) {  // a hull edge: walkable both ways
      if (!neighbours.has(b)) neighbours.set(b, []);
      neighbours.get(b).push(a);
    }
  }

  // With segmentSources, the input segments each constrained edge lies on (its route): keyed
  // by the edge's two vertices.
  const routes = r.segmentSources === undefined ? null : new Map();
  const edgeKey = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  if (routes) {
    assert.equal(r.segmentOffsets.length, r.constraintEdges.length + 1);
    r.constraintEdges.forEach((e, i) => {
      routes.set(edgeKey(triangles[e], triangles[next(e)]),
        new Set(r.segmentSources.subarray(r.segmentOffsets[i], r.segmentOffsets[i + 1])));
    });
  }

  // Every input segment is covered by a chain of constrained edges whose vertices lie within
  // the bound of it, each further along it than the one before: a search from its first
  // vertex (several vertices can lie within the bound where vertices are a few ulps apart),
  // along the edges that name it when the result says which segments each edge lies on.
  let pointBase = (input.points?.length ?? 0) / 2;
  const numbered = [];  // [segment, polyline], numbered as segmentSources numbers them
  polylines.forEach((line, j) => {
    for (let k = 0; k + 3 < line.length; k += 2) {
      const s = [line[k], line[k + 1], line[k + 2], line[k + 3]];
      const from = r.inputToVertex[pointBase + k / 2];
      const to = r.inputToVertex[pointBase + k / 2 + 1];
      if (from === to) continue;
      const index = numbered.length;
      numbered.push([s, j]);
      if (!keepAll) continue;
      const seen = new Set([from]), frontier = [from];
      for (let i = 0; i < frontier.length && !seen.has(to); i++) {
        const at = frontier[i];
        for (const w of neighbours.get(at) ?? []) {
          if (routes && !routes.get(edgeKey(at, w))?.has(index)) continue;
          if (seen.has(w) || !withinBound(s, x(w), y(w))) continue;
          if (signAlong(s, x(at), y(at), x(w), y(w)) <= 0) continue;
          seen.add(w);
          frontier.push(w);
        }
      }
      assert.ok(seen.has(to), `polyline ${j} segment ${k / 2} is not covered by a chain of`
        + ' constrained edges within the bound, in order');
    }
    pointBase += line.length / 2;
  });

  // Provenance: each constrained edge names exactly the polylines that have a segment
  // containing it, so none lies off every input segment and overlaps name every polyline.
  const { constraintEdges, sourceOffsets, sources } = r;
  assert.equal(constraintEdges.length, edges.length, 'one provenance entry per constrained edge');
  assert.equal(sourceOffsets.length, constraintEdges.length + 1,
    'sourceOffsets has one more entry');
  assert.equal(sourceOffsets[sourceOffsets.length - 1], sources.length);
  const segments = polylines.map(segmentsOf);
  const boxes = polylines.map(boxOf);
  const listed = new Set();
  constraintEdges.forEach((e, i) => {
    assert.ok(constrained[e], `constraintEdges[${i}] = ${e} is not a constrained half-edge`);
    const key = Math.min(e, halfedges[e] === -1 ? e : halfedges[e]);
    assert.ok(!listed.has(key), `edge ${e} is listed twice`);
    listed.add(key);
    const a = triangles[e], b = triangles[next(e)];
    const [ax, ay, bx, by] = [x(a), y(a), x(b), y(b)];
    // Within the bound of a segment (it may be named), exactly on one (it must be named).
    const may = [], must = [];
    segments.forEach((list, j) => {
      const [minX, minY, maxX, maxY] = boxes[j];
      if (Math.min(ax, bx) < minX || Math.max(ax, bx) > maxX) return;
      if (Math.min(ay, by) < minY || Math.max(ay, by) > maxY) return;
      if (list.some((s) => withinBound(s, ax, ay) && withinBound(s, bx, by))) may.push(j);
      if (list.some((s) => exactlyOn(s, ax, ay) && exactlyOn(s, bx, by))) must.push(j);
    });
    const named = Array.from(sources.subarray(sourceOffsets[i], sourceOffsets[i + 1]));
    const where = `edge ${e} (${ax},${ay})-(${bx},${by})`;
    assert.ok(may.length > 0, `constrained ${where} lies within the bound of no input segment`);
    for (const j of named) {
      assert.ok(may.includes(j), `${where} names polyline ${j}, beyond its segments' bound`);
    }
    for (const j of overlaps ? must : []) {
      assert.ok(named.includes(j), `${where} lies on polyline ${j} but names only ${named}`);
    }
    // Its route: segments it lies within the bound of, of polylines it names.
    for (const t of routes?.get(edgeKey(a, b)) ?? []) {
      assert.ok(t < numbered.length, `${where} names segment ${t} of ${numbered.length}`);
      const [seg, j] = numbered[t];
      assert.ok(withinBound(seg, ax, ay) && withinBound(seg, bx, by),
        `${where} lies on segment ${t} by its route, beyond that segment's bound`);
      assert.ok(named.includes(j), `${where} lies on segment ${t} of polyline ${j}, not named`);
    }
    if (routes) assert.ok(routes.get(edgeKey(a, b)).size > 0, `${where} lies on no segment`);
  });
}

// Even-odd or nonzero over the rings, at a point strictly inside a triangle.
export function insideRings(rings, px, py, fillRule = 'evenodd') {
  let crossings = 0, winding = 0;
  for (const { box, segments } of rings) {
    if (py < box[1] || py > box[3] || px > box[2]) continue;  // the ray to +x misses it
    for (const [ax, ay, bx, by] of segments) {
      if ((ay > py) === (by > py)) continue;
      const xAt = ax + ((py - ay) * (bx - ax)) / (by - ay);
      if (xAt > px) {
        crossings++;
        winding += by > ay ? 1 : -1;
      }
    }
  }
  return fillRule === 'evenodd' ? crossings % 2 === 1 : winding !== 0;
}

export function checkInsideFlags(r, input, fillRule = 'evenodd') {
  const { points, triangles, inside } = r;
  assert.equal(inside.length, triangles.length / 3, 'one inside flag per triangle');
  const rings = (input.polylines ?? []).filter(isRing)
    .map((l) => ({ box: boxOf(l), segments: segmentsOf(l) }));
  for (let t = 0; t < inside.length; t++) {
    let cx = 0, cy = 0;
    for (let k = 0; k < 3; k++) {
      cx += points[2 * triangles[3 * t + k]] / 3;
      cy += points[2 * triangles[3 * t + k] + 1] / 3;
    }
    assert.equal(inside[t] === 1, insideRings(rings, cx, cy, fillRule),
      `triangle ${t}: inside flag disagrees with the ${fillRule} rule`);
  }
}

export function area(r) {
  let sum = 0;
  const { points: p, triangles: tr } = r;
  for (let t = 0; t < tr.length; t += 3) {
    const [a, b, c] = [tr[t], tr[t + 1], tr[t + 2]];
    sum += ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1])
      - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2;
  }
  return sum;
}
