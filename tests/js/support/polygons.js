// The checker of triangulatePolygons(), polygon by polygon, with exact predicates
// (robust-predicates) and exact areas (BigInt), independent of the C++ one:
//  - every triangle strictly counter-clockwise with y up; every index an input or extra point;
//  - each directed edge (by position) used once in its polygon;
//  - every border edge (its twin unused) on a ring segment: exactly, or within the crossings'
//    rounding bound (two ulps of the segment's largest coordinate) where rings cross;
//  - every triangle inside by the fill rule: the winding number at a point strictly inside it,
//    counted exactly, no ring segment through it (on large polygons, a sample);
//  - constrained Delaunay: an edge between two of the polygon's triangles that lies on no ring
//    segment has the fourth point outside or on the circle through the other three;
//  - the area inside equal (exactly, where floating point cannot tell) to that of
//    triangulate({ polylines: rings }, { keep: 'inside' }) with the same fill rule.
import assert from 'node:assert/strict';
import { triangulate } from 'geocdt';
import { chainBound, integers, withinDistance } from './exact.js';
import { inCircle, orient } from './predicates.js';

// Twice the area of the triangles (flat x, y of each corner, 6 numbers a triangle), exactly:
// the numbers as BigInts over their lowest common unit.
function exactDoubledArea(corners) {
  const n = integers(Array.from(corners));
  let sum = 0n;
  for (let i = 0; i < n.length; i += 6) {
    sum += (n[i + 2] - n[i]) * (n[i + 5] - n[i + 1]) - (n[i + 3] - n[i + 1]) * (n[i + 4] - n[i]);
  }
  return sum;
}

function doubledArea(corners) {
  let sum = 0, magnitude = 0;
  for (let i = 0; i < corners.length; i += 6) {
    const a = (corners[i + 2] - corners[i]) * (corners[i + 5] - corners[i + 1])
      - (corners[i + 3] - corners[i + 1]) * (corners[i + 4] - corners[i]);
    sum += a;
    magnitude += Math.abs(a);
  }
  return { sum, magnitude };
}

// The rings of polygon p, each as a closed Float64Array, and their non-degenerate segments.
export function polygonRings({ coords, ringOffsets, polygonOffsets }, p) {
  const rings = [];
  for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) {
    const ring = Array.from(coords.slice(2 * ringOffsets[r], 2 * ringOffsets[r + 1]), Number);
    const n = ring.length;
    if (n >= 4 && (ring[0] !== ring[n - 2] || ring[1] !== ring[n - 1])) ring.push(ring[0], ring[1]);
    rings.push(Float64Array.from(ring));
  }
  return rings;
}

function segmentsOf(rings) {
  const segments = [];
  for (const ring of rings) {
    for (let k = 0; k + 3 < ring.length; k += 2) {
      if (ring[k] !== ring[k + 2] || ring[k + 1] !== ring[k + 3]) {
        segments.push([ring[k], ring[k + 1], ring[k + 2], ring[k + 3]]);
      }
    }
  }
  return segments;
}

const key = (x, y) => `${x},${y}`;

function onSegment([ax, ay, bx, by], x, y) {
  return orient(ax, ay, bx, by, x, y) === 0 && Math.min(ax, bx) <= x && x <= Math.max(ax, bx)
    && Math.min(ay, by) <= y && y <= Math.max(ay, by);
}

// Whether edge (x0, y0)-(x1, y1) lies on one of the segments: exactly, or within the bound of
// crossings.
function onRing(segments, exactEdges, x0, y0, x1, y1) {
  if (exactEdges.has(`${key(x0, y0)}|${key(x1, y1)}`)) return true;
  for (const s of segments) {
    if (onSegment(s, x0, y0) && onSegment(s, x1, y1)) return true;
  }
  for (const s of segments) {
    const d = chainBound(s);
    if (withinDistance(s, x0, y0, d) && withinDistance(s, x1, y1, d)) return true;
  }
  return false;
}

// The winding number of (x, y) against the segments, exactly; null when it lies on one.
function winding(segments, x, y) {
  let w = 0;
  for (const s of segments) {
    const [ux, uy, vx, vy] = s;
    const o = orient(ux, uy, vx, vy, x, y);
    if (o === 0 && onSegment(s, x, y)) return null;
    if (uy <= y) {
      if (vy > y && o > 0) w++;
    } else if (vy <= y && o < 0) {
      w--;
    }
  }
  return w;
}

const insideBy = (w, fillRule) => (fillRule === 'evenodd' ? (w & 1) !== 0 : w !== 0);

// Checks result (triangulatePolygons' output) for input; options.area: false skips the
// reference triangulation (the slowest part).
export function checkPolygonTriangles(input, result, { fillRule = 'evenodd', area = true } = {}) {
  const { coords, polygonOffsets } = input;
  const { triangles, extraPoints, triangleOffsets } = result;
  const n = coords.length / 2, m = polygonOffsets.length - 1;
  assert.ok(triangles instanceof Uint32Array && extraPoints instanceof Float64Array
    && triangleOffsets instanceof Uint32Array, 'typed arrays out');
  assert.equal(triangleOffsets.length, m + 1, 'an offset per polygon, plus one');
  assert.equal(triangleOffsets[0], 0);
  assert.equal(3 * triangleOffsets[m], triangles.length, 'offsets end at the triangle count');
  assert.equal(extraPoints.length % 2, 0);
  const x = (i) => (i < n ? Number(coords[2 * i]) : extraPoints[2 * (i - n)]);
  const y = (i) => (i < n ? Number(coords[2 * i + 1]) : extraPoints[2 * (i - n) + 1]);
  for (let p = 0; p < m; p++) {
    assert.ok(triangleOffsets[p + 1] >= triangleOffsets[p], `offsets never decrease (${p})`);
    const rings = polygonRings(input, p);
    const segments = segmentsOf(rings);
    const exactEdges = new Set();
    for (const [ax, ay, bx, by] of segments) {
      exactEdges.add(`${key(ax, ay)}|${key(bx, by)}`).add(`${key(bx, by)}|${key(ax, ay)}`);
    }
    const first = triangleOffsets[p], last = triangleOffsets[p + 1];
    const edges = new Map();  // directed edge -> [x0, y0, x1, y1, apex x, apex y]
    const corners = new Float64Array(6 * (last - first));
    const stride = 1 + Math.floor((last - first) * segments.length / 2_000_000);
    for (let t = first; t < last; t++) {
      const c = [triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]];
      for (const i of c) assert.ok(i < n + extraPoints.length / 2, `polygon ${p}: index ${i}`);
      const px = c.map(x), py = c.map(y);
      corners.set([px[0], py[0], px[1], py[1], px[2], py[2]], 6 * (t - first));
      assert.ok(orient(px[0], py[0], px[1], py[1], px[2], py[2]) > 0,
        `polygon ${p} triangle ${t} is counter-clockwise`);
      for (let k = 0; k < 3; k++) {
        const j = (k + 1) % 3, l = (k + 2) % 3;
        const e = `${key(px[k], py[k])}|${key(px[j], py[j])}`;
        assert.ok(!edges.has(e), `polygon ${p} triangle ${t}: an edge used twice`);
        edges.set(e, [px[k], py[k], px[j], py[j], px[l], py[l]]);
      }
      if ((t - first) % stride !== 0 || c.some((i) => i >= n)) continue;
      const cx = (px[0] + px[1] + px[2]) / 3, cy = (py[0] + py[1] + py[2]) / 3;
      if ([0, 1, 2].some((k) => orient(px[k], py[k], px[(k + 1) % 3], py[(k + 1) % 3], cx, cy)
        <= 0)) continue;  // a sliver whose rounded centroid is not strictly inside it
      const w = winding(segments, cx, cy);
      assert.notEqual(w, null, `polygon ${p} triangle ${t}: a ring segment passes through it`);
      assert.ok(insideBy(w, fillRule), `polygon ${p} triangle ${t} is inside (winding ${w})`);
    }
    for (const [e, [x0, y0, x1, y1, ax, ay]] of edges) {
      const twin = edges.get(`${key(x1, y1)}|${key(x0, y0)}`);
      if (twin === undefined) {
        assert.ok(onRing(segments, exactEdges, x0, y0, x1, y1),
          `polygon ${p}: border edge ${e} lies on a ring segment`);
      } else if (inCircle(x0, y0, x1, y1, ax, ay, twin[4], twin[5]) > 0) {
        assert.ok(onRing(segments, exactEdges, x0, y0, x1, y1),
          `polygon ${p}: edge ${e} is constrained Delaunay`);
      }
    }
    if (area) checkArea(rings, corners, fillRule, p);
  }
}

function checkArea(rings, corners, fillRule, p) {
  const reference = triangulate({ polylines: rings }, { keep: 'inside', fillRule });
  const { points, triangles } = reference;
  const theirs = new Float64Array(2 * triangles.length);
  for (let i = 0; i < triangles.length; i++) {
    theirs[2 * i] = points[2 * triangles[i]];
    theirs[2 * i + 1] = points[2 * triangles[i] + 1];
  }
  const a = doubledArea(corners), b = doubledArea(theirs);
  if (Math.abs(a.sum - b.sum) <= 1e-14 * (a.magnitude + b.magnitude)) return;
  assert.equal(exactDoubledArea(corners), exactDoubledArea(theirs),
    `polygon ${p}: the area of triangulate(keep: 'inside')`);
}
