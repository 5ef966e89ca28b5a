#include "exact_geometry.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "bigint.h"

namespace geocdt {
namespace {

using detail::BigInt;
// A finite double, or a power of two from 2^-1075 up, is an integer below 2^2101 in units of
// the smallest unit among the inputs: 66 limbs, plus room for the carries of sums; products
// of up to four such numbers need four times that. One type for all (operations touch only
// the limbs in use), so that the arithmetic is compiled once: it is the wasm's size.
using Number = BigInt<276>;

// The filters are in double, with error bounds for double: long double's precision varies
// (64 bits on x86, 53 on MSVC and under valgrind, 113 in wasm), and an answer must not.
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Covers what underflow can take from the products and sums of a filter.
constexpr double kUnderflow = 0x1p-1000;

// The exponent of the lowest set bit's unit: v is an integer multiple of 2^unitExponent(v).
int unitExponent(double v) {
  if (v == 0) return 1 << 20;
  std::uint64_t mantissa;
  int exponent;
  detail::decompose(v, mantissa, exponent);
  return exponent;
}

// The lowest unit among values, so that each is an integer multiple of 2^base.
int baseOf(std::initializer_list<double> values, int lowest = 1 << 20) {
  for (const double v : values) lowest = std::min(lowest, unitExponent(v));
  return lowest;
}

Number fixed(double v, int base) {
  Number r;
  detail::set_double(r, v, base);
  return r;
}

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

Number sum(const Number& a, const Number& b, bool subtract = false) {
  Number r;
  detail::add(r, a, b, subtract);
  return r;
}

Number product(const Number& a, const Number& b) {
  Number r;
  detail::multiply(r, a, b);
  return r;
}

Number difference(double a, double b, int base) {
  return sum(fixed(a, base), fixed(b, base), true);
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

// The value of a times 2^unit, to about 64 bits: its top three limbs (in long double for its
// exponent range; only an estimate).
template <int C>
long double approximate(const BigInt<C>& a, int unit) {
  long double v = 0;
  for (int i = std::max(0, a.size - 3); i < a.size; ++i)
    v += std::ldexp(static_cast<long double>(a.limb[i]), 32 * i + unit);
  return a.negative ? -v : v;
}

// Sign of 2 X - (c + n), where X is the coordinate (axis 0: x, 1: y) of the crossing of the
// lines of s and t: whether X lies above the midpoint of c and its neighbour n.
int crossingAgainstMidpoint(const InputSegment& s, const InputSegment& t, int axis, double c,
                            double n) {
  {  // Decided in floating point unless the crossing lies within its error of the midpoint.
    const double dx = s.bx - s.ax, dy = s.by - s.ay, fx = t.bx - t.ax, fy = t.by - t.ay;
    const double gx = t.ax - s.ax, gy = t.ay - s.ay;
    const double den = dx * fy - dy * fx, num = gx * fy - gy * fx;
    const double denError = std::fabs(dx * fy) + std::fabs(dy * fx);
    const double numError = std::fabs(gx * fy) + std::fabs(gy * fx);
    const double a = axis == 0 ? s.ax : s.ay, d = axis == 0 ? dx : dy;
    const double along = num / den, x = a + d * along;
    // Each difference errs by eps/2 of itself, so num and den by 3 eps of their magnitudes
    // (numError, denError); the quotient by (3 eps)(numError / |num| + denError / |den|) of
    // itself, and the last products and sums by a few eps more. Sixteen times that.
    const double relative = numError / std::fabs(num) + denError / std::fabs(den);
    const double error =
        16 * kEpsilon * (std::fabs(a) + std::fabs(d * along) * (1 + relative)) + kUnderflow;
    const double v = 2 * x - (c + n);
    // Underflow in num, den or their quotient (whose error d would magnify) leaves it to the
    // exact path.
    if (std::isfinite(error) && std::isfinite(v) && std::fabs(den) > 0x1p-900 &&
        std::fabs(num) > 0x1p-900 && std::fabs(along) > 0x1p-900) {
      if (v > 2 * error + 4 * kEpsilon * std::fabs(c + n)) return 1;
      if (-v > 2 * error + 4 * kEpsilon * std::fabs(c + n)) return -1;
    }
  }
  const int base = baseOf({s.ax, s.ay, s.bx, s.by, t.ax, t.ay, t.bx, t.by, c, n});
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number fx = difference(t.bx, t.ax, base), fy = difference(t.by, t.ay, base);
  const Number gx = difference(t.ax, s.ax, base), gy = difference(t.ay, s.ay, base);
  // X = a + d * num / den along the axis.
  Number den = sum(product(dx, fy), product(dy, fx), true);
  const Number num = sum(product(gx, fy), product(gy, fx), true);
  const Number a = fixed(axis == 0 ? s.ax : s.ay, base);
  Number scaled = sum(product(a, den), product(axis == 0 ? dx : dy, num));
  if (detail::sign(den) < 0) {
    negate(den);
    negate(scaled);
  }
  const Number twice = sum(scaled, scaled);
  const Number midpoint = product(sum(fixed(c, base), fixed(n, base)), den);
  return compare(twice, midpoint);
}

// The double whose rounding interval (halfway cases upward) holds the crossing coordinate,
// starting from an estimate and, should it be far off, bisecting [lo, hi], which holds it.
double roundCoordinate(const InputSegment& s, const InputSegment& t, int axis, double guess,
                       double lo, double hi) {
  const auto below = [&](double c) {  // the crossing lies below c's interval
    return crossingAgainstMidpoint(s, t, axis, c, std::nextafter(c, -INFINITY)) < 0;
  };
  const auto above = [&](double c) {  // the crossing lies at or above c's interval's end
    return crossingAgainstMidpoint(s, t, axis, c, std::nextafter(c, INFINITY)) >= 0;
  };
  double c = std::clamp(guess, lo, hi);
  for (int step = 0; step < 4; ++step) {
    if (below(c)) {
      c = std::nextafter(c, -INFINITY);
    } else if (above(c)) {
      c = std::nextafter(c, INFINITY);
    } else {
      return c;
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
  return value(first);
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
  // The estimate comes from the exact numerators and denominator, each to 64 bits: long
  // double alone loses a crossing at 1e-140 on a segment from 1e47 to the cancellation.
  const int base = baseOf({s.ax, s.ay, s.bx, s.by, t.ax, t.ay, t.bx, t.by});
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number fx = difference(t.bx, t.ax, base), fy = difference(t.by, t.ay, base);
  const Number ox = difference(t.ax, s.ax, base), oy = difference(t.ay, s.ay, base);
  const Number den = sum(product(dx, fy), product(dy, fx), true);
  const Number num = sum(product(ox, fy), product(oy, fx), true);
  const Number nx = sum(product(fixed(s.ax, base), den), product(dx, num));
  const Number ny = sum(product(fixed(s.ay, base), den), product(dy, num));
  // Units: den counts 2^(2 base), nx and ny 2^(3 base); scaled apart by 2^base so that
  // neither quotient part overflows long double.
  const long double d = approximate(den, 0);
  const double gx = static_cast<double>(std::ldexp(approximate(nx, 0) / d, base));
  const double gy = static_cast<double>(std::ldexp(approximate(ny, 0) / d, base));
  // The crossing lies on s: within its box.
  x = roundCoordinate(s, t, 0, std::isfinite(gx) ? gx : s.ax, std::min(s.ax, s.bx),
                      std::max(s.ax, s.bx));
  y = roundCoordinate(s, t, 1, std::isfinite(gy) ? gy : s.ay, std::min(s.ay, s.by),
                      std::max(s.ay, s.by));
  x += 0.0;  // -0 becomes 0: a vertex at the origin prints as one
  y += 0.0;
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
  const Number ax = fixed(s.ax, base), ay = fixed(s.ay, base);
  const Number dx = difference(s.bx, s.ax, base), dy = difference(s.by, s.ay, base);
  const Number px = fixed(x, base), py = fixed(y, base);
  // a + t d lies in [lo, hi) on each axis, for t in [0, 1].
  Bound lower{integer(0), integer(1), false}, upper{integer(1), integer(1), false};
  const auto tighten = [&](const Number& a, const Number& d, const Number& p, int l, int h) {
    const Number lo = sum(sum(p, power(l, base), true), a, true);  // lo - a
    const Number hi = sum(sum(p, power(h, base)), a, true);        // hi - a
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
  const Number cross = sum(product(dx, wy), product(dy, wx), true);
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

}  // namespace geocdt
