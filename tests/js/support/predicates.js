// Exact predicates with y up: robust-predicates assumes y down, so its signs are flipped here
// once, and the flip is asserted on known triangles rather than trusted.
import assert from 'node:assert/strict';
import { orient2d, incircle } from 'robust-predicates';

// > 0 when a, b, c turn counter-clockwise with y up.
export function orient(ax, ay, bx, by, cx, cy) {
  return -orient2d(ax, ay, bx, by, cx, cy);
}

// > 0 when d lies strictly inside the circle through the counter-clockwise a, b, c (y up).
export function inCircle(ax, ay, bx, by, cx, cy, dx, dy) {
  return incircle(ax, ay, bx, by, cx, cy, dx, dy);
}

assert.ok(orient(0, 0, 1, 0, 0, 1) > 0, 'orient sign convention');
assert.ok(inCircle(0, 0, 1, 0, 0, 1, 0.3, 0.3) > 0, 'incircle sign convention (inside)');
assert.ok(inCircle(0, 0, 1, 0, 0, 1, 2, 2) < 0, 'incircle sign convention (outside)');
assert.equal(inCircle(0, 0, 1, 0, 0, 1, 1, 1), 0, 'incircle sign convention (on)');
