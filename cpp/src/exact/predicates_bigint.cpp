#include "exact/predicates_bigint.h"

#include "exact/bigint.h"

namespace geocdt::detail {
namespace {

// A finite double is below 2^1024 with its unit bit at or above 2^-1074: relative to the
// smallest unit it is an integer below 2^2098, which 66 limbs hold; a difference of two
// needs one more bit, still within 66 limbs. One spare limb for the carry of an addition.
using Linear = BigInt<67>;
using Quadratic = BigInt<2 * 67>;
using Quartic = BigInt<4 * 67 + 2>;

Sign to_sign(int s) { return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero); }

// The smallest unit exponent among the nonzero inputs: every input is an integer multiple
// of 2^result.
int common_unit_exponent(const double* v, int n) {
  int lowest = 1024;
  for (int i = 0; i < n; ++i) {
    if (v[i] == 0.0) continue;
    std::uint64_t mantissa;
    int unit_exponent;
    decompose(v[i], mantissa, unit_exponent);
    if (unit_exponent < lowest) lowest = unit_exponent;
  }
  return lowest;
}

// The differences p - q for the coordinate pairs (v[2i], v[2n]) and (v[2i+1], v[2n+1]),
// i.e. every point minus the last one.
void differences_to_last(const double* v, int points, Linear* out) {
  const int base = common_unit_exponent(v, 2 * points);
  Linear last_x, last_y, p;
  set_double(last_x, v[2 * (points - 1)], base);
  set_double(last_y, v[2 * (points - 1) + 1], base);
  for (int i = 0; i + 1 < points; ++i) {
    set_double(p, v[2 * i], base);
    add(out[2 * i], p, last_x, true);
    set_double(p, v[2 * i + 1], base);
    add(out[2 * i + 1], p, last_y, true);
  }
}

// lift(x, y) * (p * q - r * s), the contribution of one point to the in-circle determinant.
void lifted_cross(const Linear& x, const Linear& y, const Linear& p, const Linear& q,
                  const Linear& r, const Linear& s, Quartic& out) {
  Quadratic first, second, lift, cross;
  multiply(first, x, x);
  multiply(second, y, y);
  add(lift, first, second);
  multiply(first, p, q);
  multiply(second, r, s);
  add(cross, first, second, true);
  multiply(out, lift, cross);
}

}  // namespace

Sign orient2d_bigint(const double* v) {
  Linear d[4];  // acx, acy, bcx, bcy
  differences_to_last(v, 3, d);
  Quadratic left, right, det;
  multiply(left, d[0], d[3]);
  multiply(right, d[1], d[2]);
  add(det, left, right, true);
  return to_sign(sign(det));
}

Sign incircle_bigint(const double* v) {
  Linear d[6];  // adx, ady, bdx, bdy, cdx, cdy
  differences_to_last(v, 4, d);
  const Linear &adx = d[0], &ady = d[1], &bdx = d[2], &bdy = d[3], &cdx = d[4], &cdy = d[5];
  Quartic a, b, c, ab, det;
  lifted_cross(adx, ady, bdx, cdy, cdx, bdy, a);
  lifted_cross(bdx, bdy, cdx, ady, adx, cdy, b);
  lifted_cross(cdx, cdy, adx, bdy, bdx, ady, c);
  add(ab, a, b);
  add(det, ab, c);
  return to_sign(sign(det));
}

}  // namespace geocdt::detail
