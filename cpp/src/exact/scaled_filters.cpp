#include "exact/scaled_filters.h"

#include <cmath>
#include <limits>

namespace geocdt::detail {
namespace {

// Scales the n differences by one power of two so that the largest lies in [1, 2). The sign
// of a determinant homogeneous in them is kept: each difference that stays normal is scaled
// exactly, and one that becomes subnormal is off by at most 2^-1075, which the filters'
// underflow slack covers as it covers an underflowing product. False when a difference
// overflowed or all are zero.
bool scale_to_unit(double* d, int n) {
  double top = 0;
  for (int i = 0; i < n; ++i) {
    const double a = std::fabs(d[i]);
    if (!(a <= std::numeric_limits<double>::max())) return false;
    if (a > top) top = a;
  }
  if (top == 0) return false;
  const int shift = -std::ilogb(top);
  for (int i = 0; i < n; ++i) d[i] = std::scalbn(d[i], shift);
  return true;
}

}  // namespace

Sign orient2d_scaled_filter(const double* v) {
  double d[4] = {v[0] - v[4], v[1] - v[5], v[2] - v[4], v[3] - v[5]};  // acx, acy, bcx, bcy
  if (!scale_to_unit(d, 4)) return Sign::Zero;
  return orient2d_filter(d[0], d[1], d[2], d[3], [] { return Sign::Zero; });
}

Sign incircle_scaled_filter(const double* v) {
  double d[6] = {v[0] - v[6], v[1] - v[7], v[2] - v[6], v[3] - v[7], v[4] - v[6], v[5] - v[7]};
  if (!scale_to_unit(d, 6)) return Sign::Zero;
  return incircle_filter(d[0], d[1], d[2], d[3], d[4], d[5], [] { return Sign::Zero; });
}

}  // namespace geocdt::detail
