#include "exact/exact_geometry.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "exact/bigint.h"
#include "exact/double_double.h"
#include "exact/fixed_point.h"
#include "geocdt/predicates.h"

namespace geocdt {
namespace {

using detail::BigInt;
// Fixed-point numbers in units of the smallest unit among the inputs: a finite double, or a
// power of two from 2^-1075 up, with room for products of up to four of them.
using fixed::baseOf;
using fixed::difference;
using fixed::Number;
using fixed::product;
using fixed::sum;

// The filters are in double, with error bounds for double: long double's precision varies
// (64 bits on x86, 53 on MSVC and under valgrind, 113 in wasm), and an answer must not.
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Covers what underflow can take from the products and sums of a filter.
constexpr double kUnderflow = 0x1p-1000;

Number integer(std::uint32_t v) {
  Number r;
  r.limb[0] = v;
  r.size = v != 0;
  return r;
}

Number power(int exponent, int base) {
  Number r;
  const int shift = exponent - base, word = shift / 32;
  for (int i = 0; i < word; ++i) r.limb[i] = 0;
  r.limb[word] = std::uint32_t{1} << (shift % 32);
  r.size = word + 1;
  return r;
}

template <int A, int B>
int compare(const BigInt<A>& a, const BigInt<B>& b) {
  const int sa = detail::sign(a), sb = detail::sign(b);
  if (sa != sb) return sa < sb ? -1 : 1;
  const int m = detail::compare_magnitude(a, b);
  return sa >= 0 ? m : -m;
}

template <int C>
void negate(BigInt<C>& a) {
  if (a.size > 0) a.negative = !a.negative;
}

// The value of a, about: its top three limbs (96 bits, held to about 106) times
// 2^exponent, apart so that neither overflows. Only an estimate.
template <int C>
DoubleDouble approximate(const BigInt<C>& a, int& exponent) {
  const int low = std::max(0, a.size - 3);
  DoubleDouble v;
  for (int i = a.size - 1; i >= low; --i)
    v = DoubleDouble{v.hi * 0x1p32, v.lo * 0x1p32} + DoubleDouble{static_cast<double>(a.limb[i])};
  exponent = 32 * low;
  return a.negative ? -v : v;
}

// One coordinate X (axis 0: x, 1: y) of the crossing of the lines of s and t, compared with
// midpoints of doubles. The filters' parts that do not depend on the midpoint are computed
// once: most crossings take four comparisons.
class CrossingCoordinate {
 public:
  CrossingCoordinate(const InputSegment& s, const InputSegment& t, int axis)
      : s_(s), t_(t), axis_(axis) {
    // Each difference errs by eps/2 of itself, so num and den by 3 eps of their magnitudes
    // (numError, denError); the quotient by (3 eps)(numError / |num| + denError / |den|) of
    // itself, and the last products and sums by a few eps more. Sixteen times that.
    const double dx = s.bx - s.ax, dy = s.by - s.ay, fx = t.bx - t.ax, fy = t.by - t.ay;
    const double gx = t.ax - s.ax, gy = t.ay - s.ay;
    const double den = dx * fy - dy * fx, num = gx * fy - gy * fx;
    const double denError = std::fabs(dx * fy) + std::fabs(dy * fx);
    const double numError = std::fabs(gx * fy) + std::fabs(gy * fx);
    const double a = axis == 0 ? s.ax : s.ay, d = axis == 0 ? dx : dy;
    const double along = num / den;
    x_ = a + d * along;
    const double relative = numError / std::fabs(num) + denError / std::fabs(den);
    const double magnitude = std::fabs(a) + std::fabs(d * along) * (1 + relative);
    error_ = 16 * kEpsilon * magnitude + kUnderflow;
    // Underflow in num, den or their quotient (whose error d would magnify) leaves it to the
    // exact path.
    usable_ = std::isfinite(error_) && std::isfinite(x_) && std::fabs(den) > 0x1p-900 &&
              std::fabs(num) > 0x1p-900 && std::fabs(along) > 0x1p-900;
    // The same in double-double, with exact differences and eps squared: a crossing rounded
    // to the nearest double lies within half a spacing of it, too near the midpoints for
    // double's bound.
    const DoubleDouble ex = exactDifference(s.bx, s.ax), ey = exactDifference(s.by, s.ay);
    const DoubleDouble ux = exactDifference(t.bx, t.ax), uy = exactDifference(t.by, t.ay);
    const DoubleDouble vx = exactDifference(t.ax, s.ax), vy = exactDifference(t.ay, s.ay);
    const DoubleDouble den2 = ex * uy - ey * ux, num2 = vx * uy - vy * ux;
    const DoubleDouble along2 = num2 / den2, d2 = axis == 0 ? ex : ey;
    xx_ = DoubleDouble{a} + d2 * along2;
    const double relative2 = numError / std::fabs(num2.hi) + denError / std::fabs(den2.hi);
    error2_ =
        16 * kEpsilon * kEpsilon * (std::fabs(a) + std::fabs(d2.hi * along2.hi) * (1 + relative2)) +
        kUnderflow;
    usable2_ = std::isfinite(error2_) && std::isfinite(xx_.hi) && std::isfinite(xx_.lo) &&
               std::fabs(den2.hi) > 0x1p-900 && std::fabs(num2.hi) > 0x1p-900 &&
               std::fabs(along2.hi) > 0x1p-900;
  }

  // Sign of 2 X - (c + n): whether X lies above the midpoint of c and its neighbour n.
  int against(double c, double n) const {
    if (usable_) {
      const double v = 2 * x_ - (c + n);
      if (std::isfinite(v)) {
        const double bound = 2 * error_ + 4 * kEpsilon * std::fabs(c + n);
        if (v > bound) return 1;
        if (-v > bound) return -1;
      }
    }
    if (usable2_) {
      const DoubleDouble w = DoubleDouble{2 * xx_.hi, 2 * xx_.lo} - exactSum(c, n);
      const double bound = 2 * error2_ + 4 * kEpsilon * kEpsilon * std::fabs(c + n);
      if (w.hi > bound) return 1;
      if (-w.hi > bound) return -1;
    }
    return exactAgainst(c, n);
  }

 private:
  int exactAgainst(double c, double n) const {
    const InputSegment& s = s_;
    const InputSegment& t = t_;
    const int base = baseOf({s.ax, s.ay, s.bx, s.by, t.ax, t.ay, t.bx, t.by, c, n});
    const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
    const Number fx = difference(t.bx, t.ax, base), fy = difference(t.by, t.ay, base);
    const Number gx = difference(t.ax, s.ax, base), gy = difference(t.ay, s.ay, base);
    // X = a + d * num / den along the axis.
    Number den = difference(product(dx, fy), product(dy, fx));
    const Number num = difference(product(gx, fy), product(gy, fx));
    const Number a = fixed::fixed(axis_ == 0 ? s.ax : s.ay, base);
    Number scaled = sum(product(a, den), product(axis_ == 0 ? dx : dy, num));
    if (detail::sign(den) < 0) {
      negate(den);
      negate(scaled);
    }
    const Number twice = sum(scaled, scaled);
    const Number midpoint = product(sum(fixed::fixed(c, base), fixed::fixed(n, base)), den);
    return compare(twice, midpoint);
  }

  const InputSegment& s_;
  const InputSegment& t_;
  int axis_;
  double x_ = 0, error_ = 0, error2_ = 0;
  DoubleDouble xx_;
  bool usable_ = false, usable2_ = false;
};

// The double whose rounding interval (halfway cases upward) holds the crossing coordinate,
// starting from an estimate and, should it be far off, bisecting [lo, hi]. False where the
// crossing lies outside [lo, hi] (beyond the intervals of its ends).
bool roundCoordinate(const InputSegment& s, const InputSegment& t, int axis, double guess,
                     double lo, double hi, double& rounded) {
  const CrossingCoordinate crossing(s, t, axis);
  const auto below = [&](double c) {  // the crossing lies below c's interval
    return crossing.against(c, std::nextafter(c, -INFINITY)) < 0;
  };
  const auto above = [&](double c) {  // the crossing lies at or above c's interval's end
    return crossing.against(c, std::nextafter(c, INFINITY)) >= 0;
  };
  double c = std::clamp(guess, lo, hi);
  for (int step = 0; step < 4; ++step) {
    if (below(c)) {
      c = std::nextafter(c, -INFINITY);
    } else if (above(c)) {
      c = std::nextafter(c, INFINITY);
    } else {
      rounded = c;
      return true;
    }
  }
  // Doubles in order are integers in order once negative ones are mirrored.
  const auto key = [](double v) {
    std::int64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const auto value = [](std::int64_t k) {
    const std::int64_t bits = k < 0 ? std::numeric_limits<std::int64_t>::min() - k : k;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  };
  // The first double from lo whose interval ends above the crossing.
  std::int64_t first = key(lo), last = key(hi);
  while (first < last) {
    const std::int64_t middle =
        first + static_cast<std::int64_t>(
                    (static_cast<std::uint64_t>(last) - static_cast<std::uint64_t>(first)) / 2);
    if (above(value(middle))) {
      first = middle + 1;
    } else {
      last = middle;
    }
  }
  rounded = value(first);
  return !below(rounded) && !above(rounded);
}

// An estimate of where the lines of s and t cross, from their exact numerators and
// denominator, each to 64 bits; false where the lines are parallel.
bool estimateCrossing(const InputSegment& s, const InputSegment& t, double& x, double& y) {
  const int base = baseOf({s.ax, s.ay, s.bx, s.by, t.ax, t.ay, t.bx, t.by});
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number fx = difference(t.bx, t.ax, base), fy = difference(t.by, t.ay, base);
  const Number ox = difference(t.ax, s.ax, base), oy = difference(t.ay, s.ay, base);
  const Number den = difference(product(dx, fy), product(dy, fx));
  if (detail::sign(den) == 0) return false;
  const Number num = difference(product(ox, fy), product(oy, fx));
  const Number nx = sum(product(fixed::fixed(s.ax, base), den), product(dx, num));
  const Number ny = sum(product(fixed::fixed(s.ay, base), den), product(dy, num));
  // Units: den counts 2^(2 base), nx and ny 2^(3 base). Only a guess, rounded to double
  // from about 100 bits: roundCoordinate's steps from it find the one double whose interval
  // holds the crossing, whatever the guess.
  int de = 0, xe = 0, ye = 0;
  const DoubleDouble d = approximate(den, de), ax = approximate(nx, xe), ay = approximate(ny, ye);
  x = std::ldexp((ax / d).hi, xe - de + base);
  y = std::ldexp((ay / d).hi, ye - de + base);
  return true;
}

// Distance from (x, y) to the closed segment, in floating point, with a bound on its error;
// an infinite error where the magnitudes are too small for a bound (squares underflow).
double approximateDistance(const InputSegment& s, double x, double y, double& error) {
  const double magnitude = std::fmax(std::fmax(std::fmax(std::fabs(s.ax), std::fabs(s.ay)),
                                               std::fmax(std::fabs(s.bx), std::fabs(s.by))),
                                     std::fmax(std::fabs(x), std::fabs(y)));
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((x - s.ax) * dx + (y - s.ay) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = s.ax + t * dx - x, ey = s.ay + t * dy - y;
  // The differences err by eps of the magnitude, the projection's parameter moves the
  // nearest point by a few more: 128 eps covers it with room.
  error = magnitude > 0x1p-900 && length2 > 0x1p-900 ? 128 * kEpsilon * magnitude + kUnderflow
                                                     : INFINITY;
  return std::sqrt(ex * ex + ey * ey);
}

// Whether (x, y) lies within `bound` of the closed segment s, decided from the cross and dot
// products of the differences, each known to within a few roundings of its own terms: 1
// within, 0 beyond, -1 undecided. approximateDistance's error is relative to the
// coordinates' magnitude, a few spacings there, as the chains' bound is: it cannot tell
// whether a point computed on a segment lies within that bound. Here the error is relative
// to the segment's length and the point's offset along it, far below the bound for a
// segment short against its coordinates, and nothing where it runs along an axis.
int withinDistanceFilter(const InputSegment& s, double x, double y, double bound) {
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double length2 = dx * dx + dy * dy, limit = bound * bound * length2;
  // Away from underflow and overflow, so that the margins below can be relative.
  if (!(length2 >= 0x1p-800 && limit >= 0x1p-900 && limit <= 0x1p900)) return -1;
  // Each difference rounds once, each product and the sum once more: the result is within
  // 2 eps of the terms' magnitudes (3 eps for room), plus what underflow may take.
  const auto near = [](double p, double q, double& error) {
    error = 3 * kEpsilon * (std::fabs(p) + std::fabs(q)) + kUnderflow;
    return p + q;
  };
  const double wx = x - s.ax, wy = y - s.ay;
  double crossError;
  const double cross = std::fabs(near(dx * wy, -(dy * wx), crossError));
  // The distance to the line is |cross| / length: beyond the bound there, beyond the
  // segment too. length2 errs by 2 eps and each square by 1.5 more: 16 eps covers them.
  const double low = cross - crossError, high = cross + crossError;
  if (low > 0 && low * low > limit * (1 + 16 * kEpsilon)) return 0;
  if (!(high * high < limit * (1 - 16 * kEpsilon))) return -1;
  // Within it of the line: of the segment too where the point projects inside it.
  double alongError, backError;
  const double along = near(wx * dx, wy * dy, alongError);
  const double back = near((x - s.bx) * dx, (y - s.by) * dy, backError);
  return along > alongError && -back > backError ? 1 : -1;
}

// One end of the interval of t in [0, 1] along s where a coordinate lies in a box.
struct Bound {
  Number numerator, denominator;  // denominator > 0
  bool open;
};

// -1, 0 or 1 as a/b compares with c/d.
int compareBounds(const Bound& a, const Bound& b) {
  return compare(product(a.numerator, b.denominator), product(b.numerator, a.denominator));
}

}  // namespace

int spacingExponent(double v) {
  const double gap = spacingAt(v);
  int exponent = 0;
  std::frexp(gap, &exponent);
  return exponent - 1;
}

void roundedCrossing(const InputSegment& s, const InputSegment& t, double& x, double& y) {
  // The estimate from exact numbers: long double alone loses a crossing at 1e-140 on a
  // segment from 1e47 to the cancellation.
  double gx = s.ax, gy = s.ay;
  estimateCrossing(s, t, gx, gy);
  // The crossing lies on s: within its box.
  roundCoordinate(s, t, 0, std::isfinite(gx) ? gx : s.ax, std::min(s.ax, s.bx),
                  std::max(s.ax, s.bx), x);
  roundCoordinate(s, t, 1, std::isfinite(gy) ? gy : s.ay, std::min(s.ay, s.by),
                  std::max(s.ay, s.by), y);
  x += 0.0;  // -0 becomes 0: a vertex at the origin prints as one
  y += 0.0;
}

bool roundedLineCrossing(const InputSegment& s, const InputSegment& t, double& x, double& y) {
  // First a guess in double, which the rounding corrects exactly: almost always right or a
  // step away, so that only the filters run. The exact estimate where the guess is no number
  // or the lines may be parallel.
  const double dx = s.bx - s.ax, dy = s.by - s.ay, fx = t.bx - t.ax, fy = t.by - t.ay;
  const double den = dx * fy - dy * fx;
  // Each difference errs by eps/2 of itself, each product and the sum by eps/2 more.
  const double denError = 4 * kEpsilon * (std::fabs(dx * fy) + std::fabs(dy * fx)) + kUnderflow;
  const double along = ((t.ax - s.ax) * fy - (t.ay - s.ay) * fx) / den;
  double gx = s.ax + dx * along, gy = s.ay + dy * along;
  if (!(std::fabs(den) > denError && std::isfinite(gx) && std::isfinite(gy)) &&
      !estimateCrossing(s, t, gx, gy))
    return false;
  if (!roundCoordinate(s, t, 0, std::isfinite(gx) ? gx : s.ax, std::min(s.ax, s.bx),
                       std::max(s.ax, s.bx), x) ||
      !roundCoordinate(s, t, 1, std::isfinite(gy) ? gy : s.ay, std::min(s.ay, s.by),
                       std::max(s.ay, s.by), y))
    return false;
  x += 0.0;
  y += 0.0;
  return true;
}

bool segmentMeetsCell(const InputSegment& s, double x, double y) {
  // The cell is [x - 2^xl, x + 2^xh) x [y - 2^yl, y + 2^yh): half the spacings to the
  // neighbouring doubles.
  const auto halfGap = [](double v, double toward) {
    int exponent = 0;
    std::frexp(std::fabs(std::nextafter(v, toward) - v), &exponent);
    return exponent - 2;
  };
  const int xl = halfGap(x, -INFINITY), xh = halfGap(x, INFINITY);
  const int yl = halfGap(y, -INFINITY), yh = halfGap(y, INFINITY);
  double error;
  const double d = approximateDistance(s, x, y, error);
  const double far = std::ldexp(1.0, std::max({xl, xh, yl, yh}) + 1);  // beyond the cell's corners
  if (d - error > far) return false;

  const int base = std::min({baseOf({s.ax, s.ay, s.bx, s.by, x, y}), xl, xh, yl, yh});
  const Number ax = fixed::fixed(s.ax, base), ay = fixed::fixed(s.ay, base);
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number px = fixed::fixed(x, base), py = fixed::fixed(y, base);
  // a + t d lies in [lo, hi) on each axis, for t in [0, 1].
  Bound lower{integer(0), integer(1), false}, upper{integer(1), integer(1), false};
  const auto tighten = [&](const Number& a, const Number& d, const Number& p, int l, int h) {
    const Number lo = difference(difference(p, power(l, base)), a);  // lo - a
    const Number hi = difference(sum(p, power(h, base)), a);         // hi - a
    const int sd = detail::sign(d);
    if (sd == 0) return detail::sign(lo) <= 0 && detail::sign(hi) > 0;
    Number positive = d;
    positive.negative = false;
    Bound from{lo, positive, false}, to{hi, positive, true};  // d > 0: t in [lo/d, hi/d)
    if (sd < 0) {                                             // d < 0: t in (hi/d, lo/d]
      from = {hi, positive, true};
      to = {lo, positive, false};
      negate(from.numerator);
      negate(to.numerator);
    }
    const int f = compareBounds(from, lower);
    if (f > 0 || (f == 0 && from.open)) lower = from;
    const int u = compareBounds(to, upper);
    if (u < 0 || (u == 0 && to.open)) upper = to;
    return true;
  };
  if (!tighten(ax, dx, px, xl, xh) || !tighten(ay, dy, py, yl, yh)) return false;
  const int c = compareBounds(lower, upper);
  return c < 0 || (c == 0 && !lower.open && !upper.open);
}

bool withinDistance(const InputSegment& s, double x, double y, int e) {
  if ((x == s.ax && y == s.ay) || (x == s.bx && y == s.by)) return true;
  double error;
  const double d = approximateDistance(s, x, y, error), bound = std::ldexp(1.0, e);
  if (d + error < bound) return true;
  if (d - error > bound) return false;
  const int filtered = withinDistanceFilter(s, x, y, bound);
  if (filtered >= 0) return filtered == 1;

  const int base = std::min(baseOf({s.ax, s.ay, s.bx, s.by, x, y}), e);
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number wx = difference(x, s.ax, base), wy = difference(y, s.ay, base);
  const Number r = power(e, base);
  const Number r2 = product(r, r);
  const Number dot = sum(product(wx, dx), product(wy, dy));
  const Number length2 = sum(product(dx, dx), product(dy, dy));
  if (detail::sign(dot) <= 0) return compare(sum(product(wx, wx), product(wy, wy)), r2) <= 0;
  if (compare(dot, length2) >= 0) {
    const Number vx = difference(x, s.bx, base), vy = difference(y, s.by, base);
    return compare(sum(product(vx, vx), product(vy, vy)), r2) <= 0;
  }
  const Number cross = difference(product(dx, wy), product(dy, wx));
  return compare(product(cross, cross), product(r2, length2)) <= 0;
}

int signAlong(const InputSegment& s, double px, double py, double qx, double qy) {
  const double ux = qx - px, uy = qy - py, dx = s.bx - s.ax, dy = s.by - s.ay;
  const double v = ux * dx + uy * dy;
  // Each difference errs by eps/2 of itself, each product and the sum by eps/2 more.
  const double error = 4 * kEpsilon * (std::fabs(ux * dx) + std::fabs(uy * dy)) + kUnderflow;
  if (v > error) return 1;
  if (-v > error) return -1;
  const int base = baseOf({s.ax, s.ay, s.bx, s.by, px, py, qx, qy});
  const Number dot = sum(product(difference(qx, px, base), difference(s.bx, s.ax, base)),
                         product(difference(qy, py, base), difference(s.by, s.ay, base)));
  return detail::sign(dot);
}

bool crossProperly(const InputSegment& s, const InputSegment& t) {
  const int o1 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.ax, t.ay));
  const int o2 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.bx, t.by));
  const int o3 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.ax, s.ay));
  const int o4 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.bx, s.by));
  return o1 * o2 < 0 && o3 * o4 < 0;
}

}  // namespace geocdt
