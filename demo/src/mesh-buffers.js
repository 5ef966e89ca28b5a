// Turns a triangulation (delaunator layout) into what the map draws, in the worker so the
// page never walks a million triangles itself:
// - triangles reordered inside-first, so "inside" and "outside" are two index ranges;
// - each edge once, as vertex pairs, grouped [inside only | both | outside only] by the
//   triangles on its two sides, so any view of inside/outside is one contiguous range;
//   constrained edges the same way in their own array;
// - positions split into float32 high and low parts (hx, hy, lx, ly per vertex) so WebGL
//   keeps centimetre precision on Mercator metres of up to 2e7.

import { SURFACE_BINS } from './mesh-style.js';

export function meshBuffers({ points, triangles, halfedges, constrained, inside }) {
  const triangleCount = triangles.length / 3;
  const isInside = (t) => (inside ? inside[t] === 1 : false);

  const sortedTriangles = new Uint32Array(triangles.length);
  let front = 0;
  let back = triangleCount;
  for (let t = 0; t < triangleCount; t++) {
    const at = isInside(t) ? front++ : --back;
    sortedTriangles[3 * at] = triangles[3 * t];
    sortedTriangles[3 * at + 1] = triangles[3 * t + 1];
    sortedTriangles[3 * at + 2] = triangles[3 * t + 2];
  }

  // group 0: inside only, 1: both sides differ, 2: outside only
  const groupOf = (e) => {
    const twin = halfedges[e];
    const a = isInside((e / 3) | 0);
    const b = twin < 0 ? a : isInside((twin / 3) | 0);
    return a && b ? 0 : !a && !b ? 2 : 1;
  };
  const isConstrained = (e) =>
    constrained[e] === 1 || (halfedges[e] >= 0 && constrained[halfedges[e]] === 1);
  const edgeCounts = [0, 0, 0];
  const constraintCounts = [0, 0, 0];
  for (let e = 0; e < halfedges.length; e++) {
    if (halfedges[e] > e) continue; // visit each edge from one side
    (isConstrained(e) ? constraintCounts : edgeCounts)[groupOf(e)]++;
  }
  const edges = new Uint32Array(2 * (edgeCounts[0] + edgeCounts[1] + edgeCounts[2]));
  const constraintTotal = constraintCounts[0] + constraintCounts[1] + constraintCounts[2];
  const constraints = new Uint32Array(2 * constraintTotal);
  const edgeAt = [0, edgeCounts[0], edgeCounts[0] + edgeCounts[1]];
  const constraintAt = [0, constraintCounts[0], constraintCounts[0] + constraintCounts[1]];
  for (let e = 0; e < halfedges.length; e++) {
    if (halfedges[e] > e) continue;
    const from = triangles[e];
    const to = triangles[e % 3 === 2 ? e - 2 : e + 1];
    const g = groupOf(e);
    const [array, at] = isConstrained(e) ? [constraints, constraintAt] : [edges, edgeAt];
    array[2 * at[g]] = from;
    array[2 * at[g] + 1] = to;
    at[g]++;
  }

  // A typical edge length, from the mean area per triangle: lets the map fade edges that
  // would be too dense to see at the current zoom.
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let i = 0; i < points.length; i += 2) {
    minX = Math.min(minX, points[i]);
    maxX = Math.max(maxX, points[i]);
    minY = Math.min(minY, points[i + 1]);
    maxY = Math.max(maxY, points[i + 1]);
  }
  const typicalEdge =
    triangleCount ? Math.sqrt((2 * (maxX - minX) * (maxY - minY)) / triangleCount) : 0;

  const positions = new Float32Array(2 * points.length);
  for (let i = 0; i < points.length; i += 2) {
    const hx = Math.fround(points[i]);
    const hy = Math.fround(points[i + 1]);
    positions[2 * i] = hx;
    positions[2 * i + 1] = hy;
    positions[2 * i + 2] = points[i] - hx;
    positions[2 * i + 3] = points[i + 1] - hy;
  }

  return {
    points, // Float64Array of Mercator metres, for the canvas renderer
    positions,
    triangles: sortedTriangles,
    insideTriangles: front,
    edges,
    edgeCounts,
    constraints,
    constraintCounts,
    typicalEdge,
  };
}

// The surface view: triangles grouped by the mean of their vertices' values into
// SURFACE_BINS equal bins between the lowest and the highest value, lowest first, so that each
// bin is one range drawn in one colour. Triangles with a vertex without a value (NaN, as
// points clicked in) are left out.
export function surfaceBuffers({ triangles, values }) {
  let low = Infinity, high = -Infinity;
  for (const v of values) {
    if (v < low) low = v;
    if (v > high) high = v;
  }
  const count = triangles.length / 3;
  const bins = new Uint8Array(count);
  const surfaceCounts = new Uint32Array(SURFACE_BINS);
  const scale = high > low ? SURFACE_BINS / (high - low) : 0;
  for (let t = 0; t < count; t++) {
    const mean = (values[triangles[3 * t]] + values[triangles[3 * t + 1]]
      + values[triangles[3 * t + 2]]) / 3;
    if (Number.isNaN(mean)) {
      bins[t] = 255;
      continue;
    }
    bins[t] = Math.min(SURFACE_BINS - 1, Math.floor((mean - low) * scale));
    surfaceCounts[bins[t]]++;
  }
  const at = new Uint32Array(SURFACE_BINS);
  for (let b = 1; b < SURFACE_BINS; b++) at[b] = at[b - 1] + surfaceCounts[b - 1];
  const surfaceTriangles = new Uint32Array(3 * (at[SURFACE_BINS - 1]
    + surfaceCounts[SURFACE_BINS - 1]));
  for (let t = 0; t < count; t++) {
    if (bins[t] === 255) continue;
    surfaceTriangles.set(triangles.subarray(3 * t, 3 * t + 3), 3 * at[bins[t]]++);
  }
  return { surfaceTriangles, surfaceCounts, surfaceRange: [low, high] };
}

export function transferablesOf(mesh) {
  const arrays = [mesh.points, mesh.positions, mesh.triangles, mesh.edges, mesh.constraints];
  if (mesh.surfaceTriangles) arrays.push(mesh.surfaceTriangles, mesh.surfaceCounts);
  return arrays.map((a) => a.buffer);
}
