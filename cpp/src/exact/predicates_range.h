#pragma once
// Decides where the exact path of a predicate evaluates: the expansion code is exact only
// while every product it forms is a multiple of a normal power of two and nothing
// overflows. For a predicate of degree k over coordinate differences, that holds when
// every coordinate's lowest set bit is at least 2^lsb_floor with k * lsb_floor well above
// -1022, and every |coordinate| is below 2^(exponent_ceiling + 1) with the degree-k terms,
// summed, well below 2^1023.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace geocdt::detail {

// The windows of the two predicates. orient2d is of degree 2: its products are multiples
// of 2^-900 and its sums stay below 2^1007. incircle is of degree 4: multiples of 2^-900,
// sums below 2^1013. The spare bits at the bottom keep even the smallest error bounds of
// the adaptive stages (about 2^-106 times a product) normal numbers; the Dekker splits
// stay below 2^790.
constexpr int kOrient2dLsbFloor = -450;
constexpr int kOrient2dExponentCeiling = 500;
constexpr int kIncircleLsbFloor = -225;
constexpr int kIncircleExponentCeiling = 250;

enum class Range {
  Inside,     // evaluate as is
  Shiftable,  // multiply every coordinate by 2^shift first (exact, keeps the sign)
  TooWide,    // the exponent span exceeds the window: use big integers
  AllZero,    // every coordinate is zero: the points coincide
  NotFinite,  // NaN or infinity among the inputs
};

struct RangeCheck {
  Range range;
  int shift;
};

constexpr double power_of_two(int exponent) {
  double p = 1.0;
  for (; exponent > 0; --exponent) p *= 2.0;
  for (; exponent < 0; ++exponent) p *= 0.5;
  return p;
}

template <int lsb_floor, int exponent_ceiling>
RangeCheck check_range(const double* v, int n) {
  static_assert(lsb_floor + 52 >= -1022 && exponent_ceiling < 1023, "window must be normal");
  double max_abs = 0.0;
  double min_abs = HUGE_VAL;  // smallest nonzero magnitude
  for (int i = 0; i < n; ++i) {
    const double a = std::fabs(v[i]);
    if (!(a <= 1.7976931348623157e308)) return {Range::NotFinite, 0};
    if (a > max_abs) max_abs = a;
    if (a != 0.0 && a < min_abs) min_abs = a;
  }
  if (max_abs == 0.0) return {Range::AllZero, 0};
  // A double of exponent e has its lowest set bit at or above 2^(e - 52).
  constexpr double inside_low = power_of_two(lsb_floor + 52);
  constexpr double inside_high = power_of_two(exponent_ceiling + 1);
  if (min_abs >= inside_low && max_abs < inside_high) return {Range::Inside, 0};
  const int top_exponent = std::ilogb(max_abs);
  int lowest_bit = std::ilogb(min_abs) - 52;
  if (lowest_bit < -1074) lowest_bit = -1074;
  if (top_exponent - lowest_bit > exponent_ceiling - lsb_floor) return {Range::TooWide, 0};
  return {Range::Shiftable, exponent_ceiling - top_exponent};
}

// Multiplies v by 2^shift, exactly when check_range said Shiftable: in two steps, each by a
// normal power of two, and neither step can overflow or drop a bit that the final result
// keeps. Cheaper than std::ldexp.
inline void shift_exponents(double* v, int n, int shift) {
  const int first = shift / 2, second = shift - first;  // each within [-1022, 1023]
  auto power = [](int e) {
    const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
    double p;
    std::memcpy(&p, &bits, sizeof p);
    return p;
  };
  const double f1 = power(first), f2 = power(second);
  for (int i = 0; i < n; ++i) v[i] = v[i] * f1 * f2;
}

}  // namespace geocdt::detail
