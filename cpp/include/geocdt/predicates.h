#pragma once
// The geometric kernel: the only place that decides orientation and in-circle.
// Convention: y up, counter-clockwise positive. Every answer is exact for finite inputs
// with |coordinate| <= 1e150 (see kMaxCoordinate), including subnormal coordinates.
//
// How: an inline floating-point filter with a static error bound decides almost every call.
// When it cannot, an out-of-line exact path takes over:
//  - inputs whose exponents fit the window of the expansion code (orient2d: every nonzero
//    |coordinate| in [2^-398, 2^501); incircle: [2^-173, 2^251)) go straight to adaptive
//    expansion arithmetic: the exact determinant of the rounded differences; if some
//    difference was inexact, plus a first-order correction for the lost bits with an error
//    bound; if that is still undecided, the full determinant of the raw coordinates;
//  - otherwise, when the span from the largest exponent to the lowest significant bit is
//    at most 950 bits (orient2d) or 475 bits (incircle), all coordinates are multiplied by
//    one power of two, which is exact and keeps the sign, to land in that window;
//  - wider spans (say 1e150 with 1e-300, or 1.0 with a subnormal, in one call) take the
//    filter again on the differences scaled by one power of two, which most of them had
//    only overflowed, and are otherwise evaluated with fixed-point big integers on the
//    common lowest exponent.
// So the answers are in fact exact for every finite double; kMaxCoordinate is the limit
// the triangulation accepts, not a limit of these functions. Non-finite inputs give Zero.
// Requires IEEE binary64 arithmetic rounding to nearest (x86-64 SSE2, ARM64, wasm). The
// filters stay valid if a compiler fuses their multiply-adds; the exact path is compiled
// with -ffp-contract=off and uses Dekker splitting, never a hardware FMA.
//
// Naming: the exact layer (the detail namespace here, expansion.h, bigint.h,
// predicates_range.h, predicates*.cpp) is written in snake_case, after the papers it
// follows (Shewchuk's two_sum, two_product, scale_expansion, b_hi/b_lo, e_len), so that
// it reads side by side with them. Everything else in geocdt is camelCase.
#include <cmath>
#include <cstdint>

namespace geocdt {

enum class Sign : std::int8_t { Negative = -1, Zero = 0, Positive = 1 };

// Positive when a, b, c turn counter-clockwise, Negative when clockwise, Zero when collinear.
Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// Positive when d lies strictly inside the circle through a, b, c (given counter-clockwise),
// Negative when strictly outside, Zero when the four points are cocircular.
Sign incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
              double dy);

namespace detail {

// The exact paths, out of line so that the filters stay small enough to inline.
Sign orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy);
Sign incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy);

// u = 2^-53 is the unit roundoff. The relative bounds hold while nothing underflows; with
// underflow every product may also be off by up to 2^-1075 (half the smallest subnormal).
// kUnderflowSlack covers that with a wide margin, and is the smallest normal double so
// that the bound is never computed in subnormals, which are slow on x86.
inline constexpr double kUnitRoundoff = 1.0 / 9007199254740992.0;
// (3u + 64u^2): error of det = (acx * bcy) - (acy * bcx) relative to |left| + |right|.
inline constexpr double kOrient2dBound = (3.0 + 64.0 * kUnitRoundoff) * kUnitRoundoff;
// (10u + 256u^2): error of the lifted 3x3 determinant relative to its permanent.
inline constexpr double kIncircleBound = (10.0 + 256.0 * kUnitRoundoff) * kUnitRoundoff;
inline constexpr double kUnderflowSlack = 0x1p-1022;

// |x| by clearing the sign bit: `x < 0 ? -x : x` must keep -0.0, which compiles to a
// branch on the sign, mispredicted half the time on the filters' products (bench/
// EXPERIMENTS.md, P2).
inline double magnitude(double x) { return std::fabs(x); }

// The filters, on coordinate differences (each rounded once): Positive or Negative when the
// bound decides, else whatever undecided() returns (the exact path's answer, for the public
// predicates).
template <class Undecided>
inline Sign orient2d_filter(double acx, double acy, double bcx, double bcy, Undecided undecided) {
  const double left = acx * bcy;
  const double right = acy * bcx;
  const double det = left - right;
  const double magnitude = detail::magnitude(left) + detail::magnitude(right);
  // Overflow makes the bound infinite or NaN, so both tests fail and undecided() answers.
  const double bound = kOrient2dBound * magnitude + kUnderflowSlack;
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  return undecided();
}

template <class Undecided>
inline Sign incircle_filter(double adx, double ady, double bdx, double bdy, double cdx, double cdy,
                            Undecided undecided) {
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double across = magnitude(bdxcdy) + magnitude(cdxbdy);
  const double bcross = magnitude(cdxady) + magnitude(adxcdy);
  const double ccross = magnitude(adxbdy) + magnitude(bdxady);
  const double permanent = alift * across + blift * bcross + clift * ccross;
  // An underflowing product's absolute error gets multiplied by a lift or a cross term:
  // bound those amplifiers by their sum.
  const double amplifiers = (alift + blift + clift) + (across + bcross + ccross) + 1.0;
  const double bound = kIncircleBound * permanent + kUnderflowSlack * amplifiers;
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  return undecided();
}

}  // namespace detail

inline Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return detail::orient2d_filter(ax - cx, ay - cy, bx - cx, by - cy,
                                 [&] { return detail::orient2d_exact(ax, ay, bx, by, cx, cy); });
}

inline Sign incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                     double dy) {
  return detail::incircle_filter(ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy, [&] {
    return detail::incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
  });
}

}  // namespace geocdt
