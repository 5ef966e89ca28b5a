#include "voronoi/crossing_point.h"

#include <cmath>

#include "exact/bounded.h"
#include "exact/double_double.h"

namespace geocdt {
namespace {

constexpr double kUnit = bounded::kUnit;

// f(c, t, x) in double-double from exact differences: off by a few 2^-106 of `magnitude`.
DoubleDouble bisectorValue(XY c, XY t, XY x, double& magnitude) {
  const DoubleDouble gx = exactDifference(t.x, c.x), gy = exactDifference(t.y, c.y);
  const DoubleDouble hx = exactDifference(x.x, c.x) + exactDifference(x.x, t.x);
  const DoubleDouble hy = exactDifference(x.y, c.y) + exactDifference(x.y, t.y);
  magnitude = std::fabs(gx.hi * hx.hi) + std::fabs(gy.hi * hy.hi);
  return gx * hx + gy * hy;
}

}  // namespace

// In double-double, lambda is good to a few 2^-106 relative to the conditioning of the crossing
// (f's magnitudes over |f(p) - f(q)|), so the rounded point is within about an ulp of its
// coordinate plus an ulp of the segment's length, at any angle between segment and bisector.
// Where that bound is not within 2^-52 of the part of the segment from its nearer end (segments
// nearly along the bisector, coordinates whose scaled products underflow, crossings within
// 2^-900 of the segment's length from an end), the offset comes from exact values instead: so
// every crossing is within about 2^-50 of its distance from the nearer end, plus rounding.
CrossingPoint crossingPoint(XY c, XY t, XY p, XY q) {
  if (bisectorSide(c, t, p) == Sign::Zero) return {p, 0};
  if (bisectorSide(c, t, q) == Sign::Zero) return {q, 0};
  // lambda does not change when every point is scaled by a power of two: scaled so that the
  // largest coordinate is near 1, f's products neither underflow nor overflow.
  const double largest = std::fmax(std::fmax(std::fmax(std::fabs(c.x), std::fabs(c.y)),
                                             std::fmax(std::fabs(t.x), std::fabs(t.y))),
                                   std::fmax(std::fmax(std::fabs(p.x), std::fabs(p.y)),
                                             std::fmax(std::fabs(q.x), std::fabs(q.y))));
  const int shift = -std::ilogb(largest);
  const auto scaled = [shift](XY v) { return XY{std::ldexp(v.x, shift), std::ldexp(v.y, shift)}; };
  double magnitudeA, magnitudeB;
  const DoubleDouble a = bisectorValue(scaled(c), scaled(t), scaled(p), magnitudeA);
  const DoubleDouble b = bisectorValue(scaled(c), scaled(t), scaled(q), magnitudeB);
  const DoubleDouble span = a - b;
  // lambda's error: a's and b's over the span squared, and the roundings (coordinates below
  // 2^-1022 of the largest underflow when scaled, and so do products below that: 2^-1060 covers
  // them).
  const double errorA = 32 * kUnit * kUnit * magnitudeA + 0x1p-1060;
  const double errorB = 32 * kUnit * kUnit * magnitudeB + 0x1p-1060;
  const double room = std::fabs(span.hi) - errorA - errorB;
  // As a sum of ratios: the products of tiny errors with the values underflow.
  const double spread = room > 0 ? std::fabs(b.hi / span.hi) * (errorA / room) +
                                       std::fabs(a.hi / span.hi) * (errorB / room)
                                 : INFINITY;
  const DoubleDouble wx = exactDifference(q.x, p.x), wy = exactDifference(q.y, p.y);
  // From the nearer end, so that the point stays on the segment's line at either end.
  const DoubleDouble lambda = a / span;
  const bool fromP = lambda.hi <= 0.5;
  const DoubleDouble part = fromP ? lambda : b / (b - a);
  double x, y, partError;
  if (spread <= 0x1p-52 * part.hi && part.hi >= 0x1p-900) {
    const double sign = fromP ? 1 : -1;
    const DoubleDouble signedPart{sign * part.hi, sign * part.lo};
    const XY from = fromP ? p : q;
    x = (DoubleDouble{from.x} + signedPart * wx).hi;
    y = (DoubleDouble{from.y} + signedPart * wy).hi;
    partError = spread + 16 * kUnit * kUnit;
  } else {
    const BisectorCrossingOffset exact = bisectorCrossingOffset(c, t, p, q);
    const XY from = exact.fromP ? p : q;
    x = from.x + exact.offset.x;
    y = from.y + exact.offset.y;
    partError = 0x1p-50;  // of the offset, itself at most the segment's extent
  }
  // Within the segment's box: a coordinate along which it does not move stays exact.
  const XY at{std::fmin(std::fmax(x, std::fmin(p.x, q.x)), std::fmax(p.x, q.x)),
              std::fmin(std::fmax(y, std::fmin(p.y, q.y)), std::fmax(p.y, q.y))};
  // A bound for sorting: the part's error times the segment's extent, plus the roundings.
  const int axis = bisectorAxis(c, t);
  const double w = std::fabs(axis == 0 ? wx.hi : wy.hi);
  const double coordinate = std::fabs(axis == 0 ? at.x : at.y);
  const double error = partError * w + kUnit * coordinate + 0x1p-1070;
  return {at, std::isfinite(error) ? 2 * error : INFINITY};
}

}  // namespace geocdt
