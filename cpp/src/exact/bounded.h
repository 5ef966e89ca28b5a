#pragma once
// A double with a bound on its distance to the exact value it stands for: the floating-point
// filters of the bisector predicates and circumcentres evaluate their polynomials with these,
// so that each filter's error bound follows from its formula instead of an analysis by hand.
// Every operation adds its own rounding (half an ulp, bounded by u = 2^-53 of the result) and
// what underflow can take (a few 2^-1075). Overflow and NaN make the value or bound non-finite,
// which decides() refuses, so the exact path runs.
#include <cmath>

#include "geocdt/predicates.h"

namespace geocdt {

struct Bounded {
  double value = 0;
  double error = 0;  // |value - exact| <= error
};

namespace bounded {

inline constexpr double kUnit = detail::kUnitRoundoff;
// Rounding of the bounds themselves (each a few operations): a relative 2^-40 is far more.
inline constexpr double kSafety = 1.0 + 0x1p-40;
inline constexpr double kTiny = 0x1p-1070;

inline Bounded exact(double v) { return {v, 0}; }

}  // namespace bounded

// Found by argument-dependent lookup, next to Bounded.
inline Bounded operator+(Bounded a, Bounded b) {
  const double v = a.value + b.value;
  return {v,
          (a.error + b.error + bounded::kUnit * std::fabs(v) + bounded::kTiny) * bounded::kSafety};
}

inline Bounded operator-(Bounded a, Bounded b) {
  const double v = a.value - b.value;
  return {v,
          (a.error + b.error + bounded::kUnit * std::fabs(v) + bounded::kTiny) * bounded::kSafety};
}

inline Bounded operator*(Bounded a, Bounded b) {
  const double v = a.value * b.value;
  const double spread =
      std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error;
  return {v, (spread + bounded::kUnit * std::fabs(v) + bounded::kTiny) * bounded::kSafety};
}

inline Bounded twice(Bounded a) { return {2 * a.value, 2 * a.error}; }

namespace bounded {

// The sign of the exact value when the bound decides it; Zero when it does not.
inline Sign decided(Bounded a) {
  if (!(std::isfinite(a.value) && std::isfinite(a.error))) return Sign::Zero;
  if (a.value > a.error) return Sign::Positive;
  if (-a.value > a.error) return Sign::Negative;
  return Sign::Zero;
}

}  // namespace bounded
}  // namespace geocdt
