#pragma once
// Where a boundary segment crosses a bisector, rounded to doubles: a vertex shared by the two
// cells on either side and lying on the boundary. Computed once per crossing, so both cells
// hold the same doubles.
#include "exact/bisector_predicates.h"

namespace geocdt {

struct CrossingPoint {
  XY at;
  // A bound on |at - exact crossing| along the bisector's dominant axis (bisectorAxis), for
  // sorting the crossings of one bisector: rounded points further apart than their bounds are
  // in order; closer ones are compared exactly.
  double error = 0;
};

// The axis along which points of the bisector of (c, t) spread most: 0 (x) when the bisector
// is closer to vertical, that is |t.y - c.y| >= |t.x - c.x|, else 1 (y).
inline int bisectorAxis(XY c, XY t) {
  const double gx = t.x - c.x, gy = t.y - c.y;
  return (gy < 0 ? -gy : gy) >= (gx < 0 ? -gx : gx) ? 0 : 1;
}

// The point where p -> q crosses the bisector of (c, t), which it does (p on c's side or on it,
// q beyond): p or q exactly when that end lies on the bisector, else p + lambda (q - p) from
// whichever end is nearer, so that a coordinate along which the segment does not move is kept
// exactly (a box's sides stay straight).
CrossingPoint crossingPoint(XY c, XY t, XY p, XY q);

}  // namespace geocdt
