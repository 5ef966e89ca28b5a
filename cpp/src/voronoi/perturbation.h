#pragma once
// Ties between the domain's boundary and the Voronoi diagram (a boundary vertex equidistant from
// two sites, a boundary segment through a Voronoi vertex or along a bisector) are broken as if
// the diagram were shifted by (e, e^2) for an infinitely small e > 0 (Edelsbrunner and Mücke's
// simulation of simplicity). Every decision of the walk and of the assembly is the exact answer
// for that one shifted configuration, so they agree with each other, and the cells still
// partition the domain: a tie only makes a zero-length edge or a zero-area piece, which the
// output drops.
//
// Shifting the diagram by d is shifting the boundary by -d. Below, g = t - c for sites c, t.
#include "exact/bisector_predicates.h"

namespace geocdt {

// Whether p (a boundary point) is nearer t than c. On the bisector, f(c, t, p - d) =
// -2 g . d decides: nearer t when g.x < 0, or g.x = 0 and g.y < 0.
inline bool nearerTo(XY c, XY t, XY p) {
  const Sign s = bisectorSide(c, t, p);
  if (s != Sign::Zero) return s == Sign::Positive;
  return t.x != c.x ? t.x < c.x : t.y < c.y;
}

// Whether the boundary segment p -> q, leaving cell c beyond the bisectors of (c, t) and
// (c, u), meets (c, t)'s first. At a tie both meet at a Voronoi vertex X of c on the segment's
// line; the shifted X lies left of the segment when (q - p) x d > 0, that is q.y < p.y, or
// q.y = p.y and q.x > p.x. Passing right of X, the segment leaves through the cell edge before
// X counter-clockwise around c: (c, t)'s when u follows t, orient(c, t, u) > 0.
inline bool crossesFirst(XY c, XY t, XY u, XY p, XY q) {
  const Sign s = firstBisectorCrossed(c, t, u, p, q);
  if (s != Sign::Zero) return s == Sign::Positive;
  const bool xOnLeft = q.y != p.y ? q.y < p.y : q.x > p.x;
  const bool uFollowsT = orient2d(c.x, c.y, t.x, t.y, u.x, u.y) == Sign::Positive;
  return xOnLeft == uFollowsT;
}

// Two boundary segments crossing the bisector of (c, t) (their ends given): whether the second
// crosses it further along n = (t - c) turned a quarter counter-clockwise. At a tie they share
// an end r on the bisector; the shifted bisector leaves r on c's side when g.x > 0, or g.x = 0
// and g.y > 0, and then the crossings come in the order of the segments' other ends a, b
// counter-clockwise around r (reversed on t's side). Segments that share no end never tie.
inline bool crossesFurther(XY c, XY t, XY p1, XY q1, XY p2, XY q2) {
  const Sign s = crossingsAlongBisector(c, t, p1, q1, p2, q2);
  if (s != Sign::Zero) return s == Sign::Positive;
  XY r, a, b;
  if (p1 == p2 || p1 == q2) {
    r = p1;
    a = q1;
    b = p1 == p2 ? q2 : p2;
  } else {
    r = q1;
    a = p1;
    b = q1 == p2 ? q2 : p2;
  }
  const bool onC = t.x != c.x ? t.x > c.x : t.y > c.y;
  const Sign turn = orient2d(r.x, r.y, a.x, a.y, b.x, b.y);
  return onC ? turn == Sign::Positive : turn == Sign::Negative;
}

}  // namespace geocdt
