#pragma once
// Exact decisions about perpendicular bisectors, the lines that bound Voronoi cells: which of
// two sites a point is nearer, which of two bisectors a segment meets first, and in which order
// two segments meet one bisector. Each is a floating-point filter (exact/bounded.h) with a
// fixed-point big-integer fallback (exact/fixed_point.h): exact for every finite input.
//
// With f(c, t, x) = |x - c|^2 - |x - t|^2 = (t - c) . (2x - c - t), the bisector of sites c and
// t is f = 0; f < 0 on c's side. Along a segment from p to q, f is linear: the segment meets
// the bisector at lambda = A / (A - B) of its length, A = f(c, t, p), B = f(c, t, q).
#include "exact/bounded.h"
#include "geocdt/predicates.h"

namespace geocdt {

struct XY {
  double x = 0, y = 0;
};

inline bool operator==(XY a, XY b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(XY a, XY b) { return !(a == b); }

// f(c, t, x) in doubles, with a bound on its error.
Bounded bisectorValue(XY c, XY t, XY x);

// The sign of f(c, t, p): Positive when p is nearer t, Negative when nearer c, Zero when
// equidistant.
Sign bisectorSide(XY c, XY t, XY p);

// For a segment p -> q that ends beyond the bisectors of (c, t) and (c, u) and starts on c's
// side of both (A <= 0 < B for each): Positive when it meets the bisector of (c, t) first,
// Negative when that of (c, u), Zero when both at one point. The sign of A_t B_u - A_u B_t.
Sign firstBisectorCrossed(XY c, XY t, XY u, XY p, XY q);

// Two segments p1 -> q1 and p2 -> q2 that each cross the bisector of (c, t) (neither parallel
// to it): the sign of (X2 - X1) . n, X1 and X2 where they cross it, n = (t - c) turned a
// quarter counter-clockwise. Zero when they cross it at one point.
Sign crossingsAlongBisector(XY c, XY t, XY p1, XY q1, XY p2, XY q2);

// Where p -> q meets the bisector of (c, t) (A != B), from A and B computed exactly: the offset
// from the nearer end, p (lambda <= 1/2) or q, to the crossing, each coordinate within 2^-50 of
// itself (plus 2^-1075 where it is subnormal). For the crossings whose floating-point estimate
// is too poor: coordinates whose products underflow, segments nearly along the bisector, and
// crossings so near an end that lambda itself would underflow.
struct BisectorCrossingOffset {
  bool fromP;
  XY offset;
};
BisectorCrossingOffset bisectorCrossingOffset(XY c, XY t, XY p, XY q);

// The sign of (t - c) . (q - p): whether p -> q runs towards t's side of the bisector.
Sign bisectorApproach(XY c, XY t, XY p, XY q);

}  // namespace geocdt
