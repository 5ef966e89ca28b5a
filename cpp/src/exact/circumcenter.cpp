#include "exact/circumcenter.h"

#include <algorithm>
#include <cmath>

#include "exact/bounded.h"
#include "exact/fixed_point.h"

namespace geocdt {
namespace {

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
// (2 d x e). In doubles each difference errs by u (2^-53) of itself, |d|^2 by 4u, the
// numerators by 7u of M = |e.y| |d|^2 + |d.y| |e|^2 (M' alike), d x e by 4u of its permanent P;
// so an offset o = n / (2 det) errs by at most (3.5u M / |det| + |o| (rho + u)) / (1 - rho),
// rho = 4u P / |det|, and the sum with a by u of itself more; a numerator's products that
// underflow add 2^-1075 each. The bound below rounds those constants up (its own roundings
// are far smaller). The exact path's quotients err by 2^-49 of R, the final sums by 2^-53 of
// M + R.
XY circumcenter(XY a, XY b, XY c) {
  constexpr double u = bounded::kUnit;
  const double dx = b.x - a.x, dy = b.y - a.y, ex = c.x - a.x, ey = c.y - a.y;
  const double bl = dx * dx + dy * dy, cl = ex * ex + ey * ey;
  const double det = dx * ey - dy * ex;
  const double ox = (ey * bl - dy * cl) / (2 * det), oy = (dx * cl - ex * bl) / (2 * det);
  const XY centre{a.x + ox, a.y + oy};
  // Plain comparisons rather than fmax: the last test below catches NaN and infinities.
  const auto larger = [](double x, double y) { return x > y ? x : y; };
  // One division for the bound (divisions were most of its time): 1 + 4 rho is at least
  // 1 / (1 - 2 rho) while rho < 1/4, which the test below requires; the reciprocal's rounding
  // is far below the constants' margins.
  const double inverse = 1 / std::fabs(det);
  const double rho = 5 * u * (std::fabs(dx * ey) + std::fabs(dy * ex)) * inverse;
  const double m =
      std::fabs(ey) * bl + std::fabs(dy) * cl + std::fabs(dx) * cl + std::fabs(ex) * bl;
  const double offset = std::fabs(ox) + std::fabs(oy);
  // The numerators' products can underflow where bl, cl and det do not (they are of degree
  // three): each then errs by up to 2^-1075 absolutely, which 2^-1070 / |det| covers.
  const double error =
      (4 * u * m * inverse + 0x1p-1070 * inverse + offset * (rho + u)) * (1 + 4 * rho) +
      u * (std::fabs(centre.x) + std::fabs(centre.y));
  // a's coordinates alone: a tolerance no larger than the stated one.
  const double tolerance = kCircumcenterTolerance * (larger(std::fabs(a.x), std::fabs(a.y)) +
                                                     larger(std::fabs(ox), std::fabs(oy)));
  // rho below 1/4 keeps the bound's first order valid, products above 2^-800 keep their
  // roundings relative (no underflow).
  if (rho < 0.25 && error <= tolerance && bl > 0x1p-800 && cl > 0x1p-800 && inverse < 0x1p800 &&
      std::isfinite(centre.x + centre.y + error))
    return centre;
  return exactCircumcenter(a, b, c);
}

}  // namespace geocdt
