#include "exact/circumcenter.h"

#include <algorithm>
#include <cmath>

#include "exact/bounded.h"
#include "exact/fixed_point.h"

namespace geocdt {
namespace {

using bounded::exact;

double largestMagnitude(XY a, XY b, XY c) {
  return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y),
                   std::fabs(c.x), std::fabs(c.y)});
}

// n / d and a bound on its distance to the exact quotient, or an infinite bound when d's
// error may reach d.
Bounded quotient(Bounded n, Bounded d) {
  const double q = n.value / d.value;
  const double room = std::fabs(d.value) - d.error;
  if (!(room > 0)) return {q, INFINITY};
  const double spread = (std::fabs(n.value) * d.error / std::fabs(d.value) + n.error) / room;
  return {q, (spread + bounded::kUnit * std::fabs(q) + bounded::kTiny) * bounded::kSafety};
}

XY exactCircumcenter(XY a, XY b, XY c) {
  using fixed::Number;
  const int base = fixed::baseOf({a.x, a.y, b.x, b.y, c.x, c.y});
  const Number dx = fixed::difference(b.x, a.x, base), dy = fixed::difference(b.y, a.y, base);
  const Number ex = fixed::difference(c.x, a.x, base), ey = fixed::difference(c.y, a.y, base);
  const Number bl = fixed::sum(fixed::product(dx, dx), fixed::product(dy, dy));
  const Number cl = fixed::sum(fixed::product(ex, ex), fixed::product(ey, ey));
  const Number det = fixed::difference(fixed::product(dx, ey), fixed::product(dy, ex));
  const Number twiceDet = fixed::sum(det, det);
  const Number nx = fixed::difference(fixed::product(ey, bl), fixed::product(dy, cl));
  const Number ny = fixed::difference(fixed::product(dx, cl), fixed::product(ex, bl));
  return {a.x + fixed::quotient(nx, twiceDet, base), a.y + fixed::quotient(ny, twiceDet, base)};
}

}  // namespace

// With d = b - a, e = c - a: centre = a + (e.y |d|^2 - d.y |e|^2, d.x |e|^2 - e.x |d|^2) /
// (2 d x e). The exact path's quotients err by 2^-49 of R, the final sums by 2^-53 of M + R.
XY circumcenter(XY a, XY b, XY c) {
  const Bounded dx = exact(b.x) - exact(a.x), dy = exact(b.y) - exact(a.y);
  const Bounded ex = exact(c.x) - exact(a.x), ey = exact(c.y) - exact(a.y);
  const Bounded bl = dx * dx + dy * dy, cl = ex * ex + ey * ey;
  const Bounded twiceDet = twice(dx * ey - dy * ex);
  const Bounded ox = quotient(ey * bl - dy * cl, twiceDet);
  const Bounded oy = quotient(dx * cl - ex * bl, twiceDet);
  const Bounded x = exact(a.x) + ox, y = exact(a.y) + oy;
  const double radius = std::max(std::fabs(ox.value), std::fabs(oy.value));
  const double tolerance = kCircumcenterTolerance * (largestMagnitude(a, b, c) + radius);
  if (x.error <= tolerance && y.error <= tolerance) return {x.value, y.value};
  return exactCircumcenter(a, b, c);
}

}  // namespace geocdt
