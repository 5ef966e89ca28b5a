// The exact paths behind the inline filters of predicates.h.
#include "geocdt/predicates.h"

#include <cmath>
#include <cstdint>

#include "exact/expansion.h"
#include "exact/predicates_bigint.h"
#include "exact/predicates_range.h"
#include "exact/scaled_filters.h"

namespace geocdt::detail {
namespace {

// Stage C: the exact determinant of the rounded differences (an expansion B) plus the
// first-order effect of the difference tails (T1, in floating point). Each tail is at most
// u times its difference, so, relative to the permanent of the rounded differences, the
// second-order terms stay below 1u^2 (orient2d) and 6u^2 (incircle), and computing T1 in
// floating point errs by below 8u^2 and 44u^2 (its terms total at most 2u, resp. 4u, and
// pass through a few roundings). The constants leave a margin over those sums.
constexpr double kOrient2dTailBound = 16.0 * kUnitRoundoff * kUnitRoundoff;
constexpr double kIncircleTailBound = 96.0 * kUnitRoundoff * kUnitRoundoff;
// Covers the roundings of the bound computations themselves.
constexpr double kBoundMargin = 1.0 + 0x1p-38;

// The full orientation determinant of the raw coordinates: ab + bc + ca, where
// pq = px * qy - qx * py. Exact whatever the differences would have lost.
Sign orient2d_from_coordinates(const double* v) {
  const double ax = v[0], ay = v[1], bx = v[2], by = v[3], cx = v[4], cy = v[5];
  double ab[4], bc[4], ca[4], abbc[8], det[12];
  const int ab_len = two_two_product_diff(ax, by, bx, ay, ab);
  const int bc_len = two_two_product_diff(bx, cy, cx, by, bc);
  const int ca_len = two_two_product_diff(cx, ay, ax, cy, ca);
  const int abbc_len = expansion_sum(ab, ab_len, bc, bc_len, abbc);
  const int det_len = expansion_sum(abbc, abbc_len, ca, ca_len, det);
  return expansion_sign(det, det_len);
}

Sign orient2d_expansion(const double* v) {
  double acx, acx_tail, bcx, bcx_tail, acy, acy_tail, bcy, bcy_tail;
  two_diff(v[0], v[4], acx, acx_tail);
  two_diff(v[1], v[5], acy, acy_tail);
  two_diff(v[2], v[4], bcx, bcx_tail);
  two_diff(v[3], v[5], bcy, bcy_tail);
  double det[4];
  const int det_len = two_two_product_diff(acx, bcy, acy, bcx, det);
  // Exact differences (the usual case: nearby coordinates) make this the exact answer.
  if (acx_tail == 0.0 && acy_tail == 0.0 && bcx_tail == 0.0 && bcy_tail == 0.0) {
    return expansion_sign(det, det_len);
  }
  double estimate_error;
  const double estimated = estimate(det, det_len, estimate_error);
  const double first_order = (acx * bcy_tail + acx_tail * bcy) - (acy * bcx_tail + acy_tail * bcx);
  const double corrected = estimated + first_order;
  const double permanent = std::fabs(acx * bcy) + std::fabs(acy * bcx);
  const double bound = (estimate_error + kOrient2dTailBound * permanent) * kBoundMargin;
  if (corrected > bound) return Sign::Positive;
  if (-corrected > bound) return Sign::Negative;
  return orient2d_from_coordinates(v);
}

// h = e * (x^2 + y^2), for e of at most 12 components. h needs room for 8 * e_len
// components; returns its length.
int multiply_by_lift(const double* e, int e_len, double x, double y, double* h) {
  double ex[2 * 12], exx[4 * 12], ey[2 * 12], eyy[4 * 12];
  const int ex_len = scale_expansion(e, e_len, x, ex);
  const int exx_len = scale_expansion(ex, ex_len, x, exx);
  const int ey_len = scale_expansion(e, e_len, y, ey);
  const int eyy_len = scale_expansion(ey, ey_len, y, eyy);
  return expansion_sum(exx, exx_len, eyy, eyy_len, h);
}

void negate(double* e, int e_len) {
  for (int i = 0; i < e_len; ++i) e[i] = -e[i];
}

// The 4x4 determinant |x y x^2+y^2 1| of the raw coordinates, expanded along the lift
// column: alift * bcd - blift * cda + clift * dab - dlift * abc, where pqr is the
// orientation determinant pq + qr + rp of three points.
Sign incircle_from_coordinates(const double* v) {
  const double ax = v[0], ay = v[1], bx = v[2], by = v[3];
  const double cx = v[4], cy = v[5], dx = v[6], dy = v[7];
  // The eight 2x2 minors pq = px * qy - qx * py that the four orientations use.
  double ab[4], bc[4], cd[4], da[4], ac[4], ca[4], bd[4], db[4];
  const int ab_len = two_two_product_diff(ax, by, bx, ay, ab);
  const int bc_len = two_two_product_diff(bx, cy, cx, by, bc);
  const int cd_len = two_two_product_diff(cx, dy, dx, cy, cd);
  const int da_len = two_two_product_diff(dx, ay, ax, dy, da);
  const int ac_len = two_two_product_diff(ax, cy, cx, ay, ac);
  const int ca_len = two_two_product_diff(cx, ay, ax, cy, ca);
  const int bd_len = two_two_product_diff(bx, dy, dx, by, bd);
  const int db_len = two_two_product_diff(dx, by, bx, dy, db);

  auto sum3 = [](const double* p, int p_len, const double* q, int q_len, const double* r, int r_len,
                 double* out) {
    double pq[8];
    const int pq_len = expansion_sum(p, p_len, q, q_len, pq);
    return expansion_sum(pq, pq_len, r, r_len, out);
  };
  double bcd[12], cda[12], dab[12], abc[12];
  const int bcd_len = sum3(bc, bc_len, cd, cd_len, db, db_len, bcd);
  const int cda_len = sum3(cd, cd_len, da, da_len, ac, ac_len, cda);
  const int dab_len = sum3(da, da_len, ab, ab_len, bd, bd_len, dab);
  const int abc_len = sum3(ab, ab_len, bc, bc_len, ca, ca_len, abc);
  negate(cda, cda_len);
  negate(abc, abc_len);

  double a_term[96], b_term[96], c_term[96], d_term[96], ab_sum[192], cd_sum[192], det[384];
  const int a_len = multiply_by_lift(bcd, bcd_len, ax, ay, a_term);
  const int b_len = multiply_by_lift(cda, cda_len, bx, by, b_term);
  const int c_len = multiply_by_lift(dab, dab_len, cx, cy, c_term);
  const int d_len = multiply_by_lift(abc, abc_len, dx, dy, d_term);
  const int ab_sum_len = expansion_sum(a_term, a_len, b_term, b_len, ab_sum);
  const int cd_sum_len = expansion_sum(c_term, c_len, d_term, d_len, cd_sum);
  const int det_len = expansion_sum(ab_sum, ab_sum_len, cd_sum, cd_sum_len, det);
  return expansion_sign(det, det_len);
}

Sign incircle_expansion(const double* v) {
  double adx, adx_tail, ady, ady_tail, bdx, bdx_tail, bdy, bdy_tail, cdx, cdx_tail, cdy, cdy_tail;
  two_diff(v[0], v[6], adx, adx_tail);
  two_diff(v[1], v[7], ady, ady_tail);
  two_diff(v[2], v[6], bdx, bdx_tail);
  two_diff(v[3], v[7], bdy, bdy_tail);
  two_diff(v[4], v[6], cdx, cdx_tail);
  two_diff(v[5], v[7], cdy, cdy_tail);

  // The determinant of the rounded differences, exactly.
  double bc[4], ca[4], ab[4], a_term[32], b_term[32], c_term[32], ab_sum[64], det[96];
  const int bc_len = two_two_product_diff(bdx, cdy, cdx, bdy, bc);
  const int ca_len = two_two_product_diff(cdx, ady, adx, cdy, ca);
  const int ab_len = two_two_product_diff(adx, bdy, bdx, ady, ab);
  const int a_len = multiply_by_lift(bc, bc_len, adx, ady, a_term);
  const int b_len = multiply_by_lift(ca, ca_len, bdx, bdy, b_term);
  const int c_len = multiply_by_lift(ab, ab_len, cdx, cdy, c_term);
  const int ab_sum_len = expansion_sum(a_term, a_len, b_term, b_len, ab_sum);
  const int det_len = expansion_sum(ab_sum, ab_sum_len, c_term, c_len, det);
  const bool tails_zero = adx_tail == 0.0 && ady_tail == 0.0 && bdx_tail == 0.0 &&
                          bdy_tail == 0.0 && cdx_tail == 0.0 && cdy_tail == 0.0;
  if (tails_zero) return expansion_sign(det, det_len);

  // First-order effect of the tails on lift * cross, summed over the three points.
  auto first_order = [](double xd, double xt, double yd, double yt, double pd, double pt, double qd,
                        double qt, double rd, double rt, double sd, double st) {
    const double lift = xd * xd + yd * yd;
    const double lift_tail = 2.0 * (xd * xt + yd * yt);
    const double cross = pd * qd - rd * sd;
    const double cross_tail = (pd * qt + pt * qd) - (rd * st + rt * sd);
    return lift * cross_tail + lift_tail * cross;
  };
  double estimate_error;
  const double estimated = estimate(det, det_len, estimate_error);
  const double corrected = estimated + (first_order(adx, adx_tail, ady, ady_tail, bdx, bdx_tail,
                                                    cdy, cdy_tail, cdx, cdx_tail, bdy, bdy_tail) +
                                        first_order(bdx, bdx_tail, bdy, bdy_tail, cdx, cdx_tail,
                                                    ady, ady_tail, adx, adx_tail, cdy, cdy_tail) +
                                        first_order(cdx, cdx_tail, cdy, cdy_tail, adx, adx_tail,
                                                    bdy, bdy_tail, bdx, bdx_tail, ady, ady_tail));
  const double permanent = (adx * adx + ady * ady) * (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) +
                           (bdx * bdx + bdy * bdy) * (std::fabs(cdx * ady) + std::fabs(adx * cdy)) +
                           (cdx * cdx + cdy * cdy) * (std::fabs(adx * bdy) + std::fabs(bdx * ady));
  const double bound = (estimate_error + kIncircleTailBound * permanent) * kBoundMargin;
  if (corrected > bound) return Sign::Positive;
  if (-corrected > bound) return Sign::Negative;
  return incircle_from_coordinates(v);
}

// Whether every v[i] is an integer of magnitude below 2^25 (lattice points: pixels, tile
// coordinates). Their differences are then integers below 2^26, and their products below
// 2^52: exact in doubles.
bool small_integers(const double* v, int n) {
  bool all = true;
  for (int i = 0; i < n; ++i) {
    const double x = v[i];
    all &= x > -0x1p25 && x < 0x1p25 && static_cast<double>(static_cast<std::int32_t>(x)) == x;
  }
  return all;
}

// The in-circle determinant of small integers as the filter forms it (small_integers holds),
// and whether it is exact: when the permanent is below 2^53, every partial product and sum is
// an integer no larger than it, so nothing rounded. (A computed permanent below 2^53 means the
// true one is: rounding is monotonic.) Cocircular lattice points make the filter give up
// with a determinant of exactly zero; this answers them without expansions.
bool incircle_small_integers(const double* v, Sign& sign) {
  const double adx = v[0] - v[6], ady = v[1] - v[7];
  const double bdx = v[2] - v[6], bdy = v[3] - v[7];
  const double cdx = v[4] - v[6], cdy = v[5] - v[7];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double permanent = alift * (std::fabs(bdxcdy) + std::fabs(cdxbdy)) +
                           blift * (std::fabs(cdxady) + std::fabs(adxcdy)) +
                           clift * (std::fabs(adxbdy) + std::fabs(bdxady));
  if (!(permanent < 0x1p53)) return false;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  sign = det > 0 ? Sign::Positive : det < 0 ? Sign::Negative : Sign::Zero;
  return true;
}

}  // namespace

Sign orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  // Points on a common parallel or meridian (borders, graticules, grids) reach here with both
  // products exactly zero. A difference of doubles is zero exactly when they are equal
  // (subnormals included), so a zero factor on each side makes the determinant zero: no
  // expansion needed. (NaN compares unequal and goes on to the range check.)
  if ((ax == cx || by == cy) && (ay == cy || bx == cx)) return Sign::Zero;
  double v[6] = {ax, ay, bx, by, cx, cy};
  // Small integers: the filter's products and their difference were exact (small_integers).
  if (small_integers(v, 6)) {
    const double det = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
    return det > 0 ? Sign::Positive : det < 0 ? Sign::Negative : Sign::Zero;
  }
  const RangeCheck range = check_range<kOrient2dLsbFloor, kOrient2dExponentCeiling>(v, 6);
  switch (range.range) {
    case Range::NotFinite:
    case Range::AllZero: return Sign::Zero;
    case Range::TooWide: {
      const Sign scaled = orient2d_scaled_filter(v);
      return scaled != Sign::Zero ? scaled : orient2d_bigint(v);
    }
    case Range::Shiftable: shift_exponents(v, 6, range.shift); break;
    case Range::Inside: break;
  }
  return orient2d_expansion(v);
}

Sign incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy) {
  double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
  Sign sign;
  if (small_integers(v, 8) && incircle_small_integers(v, sign)) return sign;
  const RangeCheck range = check_range<kIncircleLsbFloor, kIncircleExponentCeiling>(v, 8);
  switch (range.range) {
    case Range::NotFinite:
    case Range::AllZero: return Sign::Zero;
    case Range::TooWide: {
      const Sign scaled = incircle_scaled_filter(v);
      return scaled != Sign::Zero ? scaled : incircle_bigint(v);
    }
    case Range::Shiftable: shift_exponents(v, 8, range.shift); break;
    case Range::Inside: break;
  }
  return incircle_expansion(v);
}

}  // namespace geocdt::detail
