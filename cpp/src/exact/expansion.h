#pragma once
// Floating-point expansions: a value held exactly as a sum of doubles, stored in
// increasing order of magnitude with nonoverlapping components (Priest, Shewchuk).
// Every routine here is exact provided no intermediate result overflows or needs bits
// below the normal range; the callers guarantee that by scaling (see predicates_range.h).
// They also rely on round-to-nearest binary64 without FMA contraction, hence the
// -ffp-contract=off on the core. Names are snake_case, as in the papers (see predicates.h).
#include <cmath>

#include "geocdt/predicates.h"

namespace geocdt::detail {

// a + b == sum + err exactly.
inline void two_sum(double a, double b, double& sum, double& err) {
  sum = a + b;
  const double b_part = sum - a;
  const double a_part = sum - b_part;
  err = (a - a_part) + (b - b_part);
}

// a - b == diff + err exactly.
inline void two_diff(double a, double b, double& diff, double& err) {
  diff = a - b;
  const double b_part = a - diff;
  const double a_part = diff + b_part;
  err = (a - a_part) + (b_part - b);
}

// Dekker's split: a == hi + lo with each half at most 26 significant bits, so that the
// product of two halves is exact. Needs |a| well below 2^996 (the multiplier adds 27 bits).
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// a * b == product + err exactly, given b already split into b_hi + b_lo.
inline void two_product_presplit(double a, double b, double b_hi, double b_lo, double& product,
                                 double& err) {
  product = a * b;
  double a_hi, a_lo;
  split(a, a_hi, a_lo);
  const double e1 = product - a_hi * b_hi;
  const double e2 = e1 - a_lo * b_hi;
  const double e3 = e2 - a_hi * b_lo;
  err = a_lo * b_lo - e3;
}

// a * b == product + err exactly, without relying on a hardware FMA.
inline void two_product(double a, double b, double& product, double& err) {
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  two_product_presplit(a, b, b_hi, b_lo, product, err);
}

// Zero elimination. A branch, not a branch-free store: on the common exactly degenerate
// inputs (small integers, grids) almost every rounding error is zero, which predicts well
// and beat the branch-free form there (bench/EXPERIMENTS.md, L2).
inline void append_nonzero(double x, double* h, int& h_len) {
  if (x != 0.0) h[h_len++] = x;
}

// GCC cannot see that callers only read the components these functions wrote.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
// h = e + f. h needs room for e_len + f_len components; returns the length of h with
// zero components dropped. Merges by magnitude, then carries a running sum through
// two_sum, emitting each rounding error as a component (Shewchuk's fast expansion sum).
inline int expansion_sum(const double* e, int e_len, const double* f, int f_len, double* h) {
  if (e_len == 0 || f_len == 0) {  // nothing to merge: a copy
    const double* g = e_len == 0 ? f : e;
    const int g_len = e_len == 0 ? f_len : e_len;
    for (int k = 0; k < g_len; ++k) h[k] = g[k];
    return g_len;
  }
  int i = 0, j = 0, h_len = 0;
  double q = std::fabs(e[0]) <= std::fabs(f[0]) ? e[i++] : f[j++];
  double err;
  while (i < e_len && j < f_len) {
    // Written to compile to selects: the merge order is data-dependent and unpredictable.
    const double ei = e[i], fj = f[j];
    const bool take_e = std::fabs(ei) <= std::fabs(fj);
    const double next = take_e ? ei : fj;
    i += take_e;
    j += !take_e;
    two_sum(q, next, q, err);
    append_nonzero(err, h, h_len);
  }
  for (; i < e_len; ++i) {
    two_sum(q, e[i], q, err);
    append_nonzero(err, h, h_len);
  }
  for (; j < f_len; ++j) {
    two_sum(q, f[j], q, err);
    append_nonzero(err, h, h_len);
  }
  if (q != 0.0 || h_len == 0) h[h_len++] = q;
  return h_len;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// h = b * e. h needs room for 2 * e_len components; returns the length of h with zero
// components dropped.
inline int scale_expansion(const double* e, int e_len, double b, double* h) {
  if (e_len == 0) return 0;
  int h_len = 0;
  double b_hi, b_lo, q, err;
  split(b, b_hi, b_lo);
  two_product_presplit(e[0], b, b_hi, b_lo, q, err);
  append_nonzero(err, h, h_len);
  for (int i = 1; i < e_len; ++i) {
    double product, product_err, sum;
    two_product_presplit(e[i], b, b_hi, b_lo, product, product_err);
    two_sum(q, product_err, sum, err);
    append_nonzero(err, h, h_len);
    two_sum(product, sum, q, err);
    append_nonzero(err, h, h_len);
  }
  if (q != 0.0 || h_len == 0) h[h_len++] = q;
  return h_len;
}

// The largest component of a nonoverlapping expansion outweighs all the others together,
// so it carries the sign of the whole.
inline Sign expansion_sign(const double* e, int e_len) {
  for (int i = e_len - 1; i >= 0; --i) {
    if (e[i] > 0.0) return Sign::Positive;
    if (e[i] < 0.0) return Sign::Negative;
  }
  return Sign::Zero;
}

// The floating-point sum of an expansion, smallest component first. error_bound receives
// u times the sum of the magnitudes of the partial sums: each addition errs by at most u
// times its result, so that bounds the distance to the exact value (up to the rounding of
// the bound itself, a relative 2^-40 for any length used here).
inline double estimate(const double* e, int e_len, double& error_bound) {
  double sum = 0.0, partials = 0.0;
  for (int i = 0; i < e_len; ++i) {
    sum += e[i];
    partials += std::fabs(sum);
  }
  error_bound = kUnitRoundoff * partials;
  return sum;
}

// a * b - c * d as an expansion of at most 4 components in h; returns its length. Two
// fixed rounds of growing the expansion by one double each, with no merge to branch on.
inline int two_two_product_diff(double a, double b, double c, double d, double* h) {
  double left_hi, left_lo, right_hi, right_lo;
  two_product(a, b, left_hi, left_lo);
  two_product(c, d, right_hi, right_lo);
  double q, low[3];  // left - right_lo
  two_sum(left_lo, -right_lo, q, low[0]);
  two_sum(left_hi, q, low[2], low[1]);
  int h_len = 0;  // then - right_hi
  q = -right_hi;
  for (int i = 0; i < 3; ++i) {
    double err;
    two_sum(q, low[i], q, err);
    append_nonzero(err, h, h_len);
  }
  if (q != 0.0 || h_len == 0) h[h_len++] = q;
  return h_len;
}

}  // namespace geocdt::detail
