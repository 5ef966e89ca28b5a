#pragma once
// Fixed-point big integers for the exact paths of the bisector predicates and circumcentres:
// every input double becomes an integer multiple of the smallest unit among the inputs, so
// sums and products of them are exact. Polynomials up to degree four fit (Number's capacity).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "exact/bigint.h"
#include "geocdt/predicates.h"

namespace geocdt::fixed {

// A finite double is an integer below 2^2098 in units of 2^-1074 (66 limbs, 67 with the bit
// of a difference); products of four such numbers need four times that, plus carries.
using Number = detail::BigInt<4 * 67 + 8>;

// The exponent of v's lowest unit: v is an integer multiple of 2^unitExponent(v).
inline int unitExponent(double v) {
  if (v == 0) return 1 << 20;
  std::uint64_t mantissa;
  int exponent;
  detail::decompose(v, mantissa, exponent);
  return exponent;
}

// The lowest unit among values: each is an integer multiple of 2^baseOf(values).
inline int baseOf(std::initializer_list<double> values) {
  int lowest = 1 << 20;
  for (const double v : values) lowest = std::min(lowest, unitExponent(v));
  return lowest == (1 << 20) ? 0 : lowest;
}

inline Number fixed(double v, int base) {
  Number r;
  detail::set_double(r, v, base);
  return r;
}

inline Number sum(const Number& a, const Number& b) {
  Number r;
  detail::add(r, a, b, false);
  return r;
}

inline Number difference(const Number& a, const Number& b) {
  Number r;
  detail::add(r, a, b, true);
  return r;
}

inline Number difference(double a, double b, int base) {
  return difference(fixed(a, base), fixed(b, base));
}

inline Number product(const Number& a, const Number& b) {
  Number r;
  detail::multiply(r, a, b);
  return r;
}

inline Sign signOf(const Number& a) {
  const int s = detail::sign(a);
  return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

// a's value times 2^-(32 * shift) as a double, from its top three limbs: relative error below
// 2^-52 (one rounding of a 96-bit truncation). shift is what keeps the double finite.
inline double approximate(const Number& a, int& shift) {
  const int low = std::max(0, a.size - 3);
  double v = 0;
  for (int i = a.size - 1; i >= low; --i) v = v * 0x1p32 + static_cast<double>(a.limb[i]);
  shift = low;
  return a.negative ? -v : v;
}

// The quotient a / b (b nonzero) times 2^base, as a double: relative error below 2^-50.
inline double quotient(const Number& a, const Number& b, int base) {
  int shiftA, shiftB;
  const double x = approximate(a, shiftA), y = approximate(b, shiftB);
  return std::ldexp(x / y, 32 * (shiftA - shiftB) + base);
}

}  // namespace geocdt::fixed
