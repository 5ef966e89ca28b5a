#pragma once
// Double-double numbers (hi + lo, about 106 bits) from IEEE operations alone, so that they
// round alike on every platform: a second filter between double and big integers where
// double cannot decide, e.g. which side of a rounding midpoint a crossing lies on. Each
// operation errs by a few units of 2^-106 of its operands' magnitudes (no more relative to
// the result: sums may cancel); overflow and underflow show up as non-finite or lost parts,
// which the callers' bounds and finiteness checks catch.
#include "exact/expansion.h"

namespace geocdt {

struct DoubleDouble {
  double hi = 0, lo = 0;
};

inline DoubleDouble normalized(double hi, double lo) {
  const double s = hi + lo;
  return {s, lo - (s - hi)};
}

// a - b exactly.
inline DoubleDouble exactDifference(double a, double b) {
  DoubleDouble r;
  detail::two_diff(a, b, r.hi, r.lo);
  return r;
}

// a + b exactly.
inline DoubleDouble exactSum(double a, double b) {
  DoubleDouble r;
  detail::two_sum(a, b, r.hi, r.lo);
  return r;
}

inline DoubleDouble operator+(DoubleDouble a, DoubleDouble b) {
  double s, e;
  detail::two_sum(a.hi, b.hi, s, e);
  return normalized(s, e + (a.lo + b.lo));
}

inline DoubleDouble operator-(DoubleDouble a) { return {-a.hi, -a.lo}; }
inline DoubleDouble operator-(DoubleDouble a, DoubleDouble b) { return a + -b; }

inline DoubleDouble operator*(DoubleDouble a, DoubleDouble b) {
  double p, e;
  detail::two_product(a.hi, b.hi, p, e);
  return normalized(p, e + (a.hi * b.lo + a.lo * b.hi));
}

inline DoubleDouble operator/(DoubleDouble a, DoubleDouble b) {
  const double q = a.hi / b.hi;
  const DoubleDouble r = a - DoubleDouble{q} * b;
  return normalized(q, r.hi / b.hi);
}

}  // namespace geocdt
