// Random dirty inputs through the wasm build itself, checked by the JS invariants. The C++
// fuzzers run natively, where size_t has 64 bits; the module users get has 32-bit size_t and
// pointers, where an index that wraps can land inside the heap instead of far outside it (a
// pair index of -1 once wrote a byte before an array there). The JS checker also holds
// each constrained edge to naming every polyline with a segment through it, which the C++
// checker does not (overlapping segments once took chains of their own here, where a
// crossing rounded off their line). Deterministic: fixed seeds. (20,000 seeds, 1000-10999
// and 20000-29999, also passed the mesh and chain checks in one call each, keep all.) The
// last test feeds it ulp tangles, where snap rounding takes over, without that check (it
// does not hold there: README, "Known limitations").
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation, memoryUsage } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { checkConstraints, checkInsideFlags } from './support/constraints.js';
import { random } from './support/inputs.js';

before(() => init());

// Coordinates on a small grid (repeats, collinear runs, overlapping and crossing segments,
// T-junctions), now and then off it by a fraction; points given before the polylines often
// repeat the polylines' vertices, as GIS layers do.
function dirtyInput(seed) {
  const rnd = random(seed);
  const int = (n) => Math.floor(rnd() * n);
  const grid = 2 + int(12);
  const coordinate = () => (rnd() < 0.9 ? int(grid) : int(grid) + rnd());
  const vertices = [];
  const vertex = () => {
    if (vertices.length > 0 && rnd() < 0.3) return vertices[int(vertices.length)];
    const v = [coordinate(), coordinate()];
    vertices.push(v);
    return v;
  };
  const polylines = [];
  for (let i = int(6); i >= 0; i--) {
    const line = [];
    for (let k = 1 + int(8); k >= 0; k--) line.push(...vertex());
    if (rnd() < 0.4 && line.length >= 6) line.push(line[0], line[1]);  // a ring
    polylines.push(line);
  }
  const points = [];
  for (let i = int(12); i > 0; i--) {
    points.push(...(rnd() < 0.5 ? vertex() : [coordinate(), coordinate()]));
  }
  return { points, polylines };
}

// No triangle at all: every vertex on one line (or, with keep 'inside', nothing inside,
// where the chains are not checked anyway).
const collinear = (r) => r.triangles.length === 0;

const seeds = Array.from({ length: 1000 }, (_, i) => 1000 + i);

test('one call on random dirty inputs gives valid meshes and chains', () => {
  const heap = memoryUsage().allocated;
  for (const seed of seeds) {
    const input = dirtyInput(seed);
    const options = seed % 3 === 0 ? { keep: 'inside', fillRule: 'nonzero' } : {};
    const r = triangulate(input, { insideFlags: true, segmentSources: true, ...options });
    const keepAll = options.keep !== 'inside';
    try {
      checkMesh(r, input, { keepAll });
      // All on a line: no triangles, so no edges to constrain yet (README, limitations).
      if (!collinear(r)) checkConstraints(r, input, { keepAll });
      if (keepAll) checkInsideFlags(r, input, options.fillRule);
    } catch (error) {
      error.message = `seed ${seed}: ${error.message}\n${JSON.stringify(input)}`;
      throw error;
    }
  }
  assert.equal(memoryUsage().allocated, heap, 'the calls leave the heap as they found it');
});

// The points in one call, then one polyline a call; the result checked.
function insertIncrementally(input, constraintOptions) {
  const t = new Triangulation();
  try {
    const ids = [...t.insertPoints(input.points)];
    for (const line of input.polylines) ids.push(...t.insertPolyline(line));
    const r = t.results({ segmentSources: true });
    r.inputToVertex = Uint32Array.from(ids);
    checkMesh(r, input);
    if (!collinear(r)) checkConstraints(r, input, constraintOptions);
  } finally {
    t.dispose();
  }
}

test('incremental insertions of the same inputs, one polyline a call', () => {
  for (const seed of seeds.slice(0, 300)) {
    const input = dirtyInput(seed);
    try {
      insertIncrementally(input);
    } catch (error) {
      error.message = `seed ${seed}: ${error.message}\n${JSON.stringify(input)}`;
      throw error;
    }
  }
});

// A double `steps` neighbours away from x (x > 0, its neighbours too).
const bits = new BigInt64Array(1);
const asDouble = new Float64Array(bits.buffer);
function ulpsFrom(x, steps) {
  asDouble[0] = x;
  bits[0] += BigInt(steps);
  return asDouble[0];
}

// Tangles: every point on an 8 x 8 grid of neighbouring doubles (1 or 2 ulps a step)
// around an offset, so that every crossing rounds onto the same few doubles and computed
// crossings give way to snap rounding. Offsets away from zero: the JS predicates are exact
// for normal numbers only. Signs folded so that each axis steps through doubles of one sign.
const offsets = [[1, 12345.678], [16000000.25, 12345.678], [2 ** 24, 1], [73.98, 40.75]];
function tangleInput(seed) {
  const rnd = random(seed);
  const int = (n) => Math.floor(rnd() * n);
  const [ox, oy] = offsets[seed % offsets.length];
  const step = 1 << int(2);
  const sx = rnd() < 0.5 ? 1 : -1, sy = rnd() < 0.5 ? 1 : -1;
  const vertex = () => [sx * ulpsFrom(ox, step * (int(8) - 4)),
    sy * ulpsFrom(oy, step * (int(8) - 4))];
  const polylines = [];
  for (let i = int(12); i >= 0; i--) {
    const line = [];
    for (let k = 1 + int(12); k >= 0; k--) line.push(...vertex());
    if (rnd() < 0.4 && line.length >= 6) line.push(line[0], line[1]);
    polylines.push(line);
  }
  const points = [];
  for (let i = int(4); i > 0; i--) points.push(...vertex());
  return { points, polylines };
}

test('ulp tangles: snap rounding in the wasm build, one call and one polyline a call', () => {
  const heap = memoryUsage().allocated;
  let snapRounded = 0;
  for (let seed = 1; seed <= 300; seed++) {
    const input = tangleInput(seed);
    try {
      const r = triangulate(input, { segmentSources: true });
      snapRounded += r.stats.snapRoundings > 0;
      checkMesh(r, input);
      if (!collinear(r)) checkConstraints(r, input, { overlaps: false });
      if (seed % 3 === 0) insertIncrementally(input, { overlaps: false });
    } catch (error) {
      error.message = `tangle seed ${seed}: ${error.message}\n${JSON.stringify(input)}`;
      throw error;
    }
  }
  // The inputs are tangles indeed: many of them need snap rounding (about a quarter).
  assert.ok(snapRounded >= 40, `snap-rounded inputs: ${snapRounded} of 300`);
  assert.equal(memoryUsage().allocated, heap, 'the calls leave the heap as they found it');
});
