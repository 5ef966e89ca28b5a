#include "exact/bisector_predicates.h"

#include <cmath>

#include "exact/fixed_point.h"

namespace geocdt {
namespace {

using bounded::exact;
using fixed::Number;

Sign times(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

// (b - a) . (d - c) and the cross product (b - a) x (d - c), in doubles.
Bounded dot(XY a, XY b, XY c, XY d) {
  return (exact(b.x) - exact(a.x)) * (exact(d.x) - exact(c.x)) +
         (exact(b.y) - exact(a.y)) * (exact(d.y) - exact(c.y));
}
Bounded cross(XY a, XY b, XY c, XY d) {
  return (exact(b.x) - exact(a.x)) * (exact(d.y) - exact(c.y)) -
         (exact(b.y) - exact(a.y)) * (exact(d.x) - exact(c.x));
}

// The same in fixed point on the unit 2^base.
struct Exact {
  int base;
  Number x(XY p) const { return fixed::fixed(p.x, base); }
  Number y(XY p) const { return fixed::fixed(p.y, base); }
  Number bisectorValue(XY c, XY t, XY p) const {
    using fixed::difference;
    const Number hx = fixed::sum(difference(p.x, c.x, base), difference(p.x, t.x, base));
    const Number hy = fixed::sum(difference(p.y, c.y, base), difference(p.y, t.y, base));
    return fixed::sum(fixed::product(difference(t.x, c.x, base), hx),
                      fixed::product(difference(t.y, c.y, base), hy));
  }
  Number dot(XY a, XY b, XY c, XY d) const {
    using fixed::difference;
    return fixed::sum(fixed::product(difference(b.x, a.x, base), difference(d.x, c.x, base)),
                      fixed::product(difference(b.y, a.y, base), difference(d.y, c.y, base)));
  }
  Number cross(XY a, XY b, XY c, XY d) const {
    using fixed::difference;
    return fixed::difference(
        fixed::product(difference(b.x, a.x, base), difference(d.y, c.y, base)),
        fixed::product(difference(b.y, a.y, base), difference(d.x, c.x, base)));
  }
};

}  // namespace

// (t - c) . ((x - c) + (x - t)).
Bounded bisectorValue(XY c, XY t, XY x) {
  const Bounded gx = exact(t.x) - exact(c.x), gy = exact(t.y) - exact(c.y);
  const Bounded hx = (exact(x.x) - exact(c.x)) + (exact(x.x) - exact(t.x));
  const Bounded hy = (exact(x.y) - exact(c.y)) + (exact(x.y) - exact(t.y));
  return gx * hx + gy * hy;
}

Sign bisectorSide(XY c, XY t, XY p) {
  const Sign s = bounded::decided(bisectorValue(c, t, p));
  if (s != Sign::Zero) return s;
  const Exact e{fixed::baseOf({c.x, c.y, t.x, t.y, p.x, p.y})};
  return fixed::signOf(e.bisectorValue(c, t, p));
}

// lambda = A / (A - B) is not rounded on the way: a crossing a subnormal distance from p along
// a long segment has a lambda below the doubles' range, its offset not.
BisectorCrossingOffset bisectorCrossingOffset(XY c, XY t, XY p, XY q) {
  const int base = fixed::baseOf({c.x, c.y, t.x, t.y, p.x, p.y, q.x, q.y});
  const Exact e{base};
  const Number a = e.bisectorValue(c, t, p), b = e.bisectorValue(c, t, q);
  const Number span = fixed::difference(a, b);
  const bool fromP = std::fabs(fixed::quotient(a, span, 0)) <= 0.5;
  // From p: A / (A - B) (q - p); from q: B / (B - A) (p - q) = B / (A - B) (q - p).
  const Number& part = fromP ? a : b;
  const Number wx = fixed::difference(q.x, p.x, base), wy = fixed::difference(q.y, p.y, base);
  return {fromP,
          {fixed::quotient(fixed::product(part, wx), span, base),
           fixed::quotient(fixed::product(part, wy), span, base)}};
}

Sign bisectorApproach(XY c, XY t, XY p, XY q) {
  const Sign s = bounded::decided(dot(c, t, p, q));
  if (s != Sign::Zero) return s;
  const Exact e{fixed::baseOf({c.x, c.y, t.x, t.y, p.x, p.y, q.x, q.y})};
  return fixed::signOf(e.dot(c, t, p, q));
}

Sign firstBisectorCrossed(XY c, XY t, XY u, XY p, XY q) {
  const Bounded at = bisectorValue(c, t, p), bt = bisectorValue(c, t, q);
  const Bounded au = bisectorValue(c, u, p), bu = bisectorValue(c, u, q);
  const Sign s = bounded::decided(at * bu - au * bt);
  if (s != Sign::Zero) return s;
  const Exact e{fixed::baseOf({c.x, c.y, t.x, t.y, u.x, u.y, p.x, p.y, q.x, q.y})};
  const Number left = fixed::product(e.bisectorValue(c, t, p), e.bisectorValue(c, u, q));
  const Number right = fixed::product(e.bisectorValue(c, u, p), e.bisectorValue(c, t, q));
  return fixed::signOf(fixed::difference(left, right));
}

// With g = t - c, w_i = q_i - p_i: X2 - X1 = mu n, and mu (g . w1) = orient(p1, q1, X2), whose
// sign is that of E = -2 orient(p1, q1, p2) (g . w2) + A2 (w1 x w2) times -(g . w2)
// (X2 = p2 + lambda2 w2 with lambda2 = A2 / (A2 - B2) and A2 - B2 = -2 g . w2).
Sign crossingsAlongBisector(XY c, XY t, XY p1, XY q1, XY p2, XY q2) {
  const Sign approach1 = bisectorApproach(c, t, p1, q1);
  const Sign approach2 = bisectorApproach(c, t, p2, q2);
  const Bounded orient = cross(p1, q1, p1, p2), gw2 = dot(c, t, p2, q2);
  const Bounded along = bisectorValue(c, t, p2) * cross(p1, q1, p2, q2);
  Sign s = bounded::decided(along - twice(orient * gw2));
  if (s == Sign::Zero) {
    const Exact e{
        fixed::baseOf({c.x, c.y, t.x, t.y, p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y})};
    const Number first = fixed::product(e.cross(p1, q1, p1, p2), e.dot(c, t, p2, q2));
    const Number second = fixed::product(e.bisectorValue(c, t, p2), e.cross(p1, q1, p2, q2));
    s = fixed::signOf(fixed::difference(second, fixed::sum(first, first)));
  }
  return times(times(s, approach1), times(approach2, Sign::Negative));
}

}  // namespace geocdt
