#pragma once
// Exact scaling by powers of two, read from and built into the bits of doubles: refinement
// measures triangles in a frame scaled to their size, at any coordinate magnitude.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace geocdt {

// The power of two 2^-e that scales the largest of the differences to magnitude ~1: scaled
// by it (exactly), their products neither underflow nor overflow. e stays within the normal
// exponents, so that 2^-e is a double and scaling is one multiplication (the same correctly
// rounded result as ldexp, without a library call per value); beyond, the largest
// difference scales to within [2^-52, 2), which is as good. The exponent is read from the
// bits and 2^-e built from them: ilogb and ldexp are library calls too (bench/EXPERIMENTS.md,
// R3 and R4).
inline int scaleExponent(std::initializer_list<double> differences) {
  double size = 0;
  for (const double d : differences) size = std::max(size, std::fabs(d));
  if (!(size > 0)) return 0;
  std::uint64_t bits;
  std::memcpy(&bits, &size, sizeof bits);
  // A subnormal size reads as -1023 and a non-finite one as 1024: both clamped, as ilogb's.
  return std::clamp(static_cast<int>(bits >> 52 & 0x7FF) - 1023, -1022, 1022);
}

// The exponent of x > 0 in half powers of two: k with sqrt(2)^k <= x < sqrt(2)^(k + 1), from
// the bits (a subnormal or zero reads as 2^-1023, an infinity as 2^1024).
inline int halfExponent(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int exponent = static_cast<int>(bits >> 52 & 0x7FF) - 1023;
  const std::uint64_t sqrt2Fraction = 0x6A09E667F3BCDull;  // the fraction bits of sqrt(2)
  return 2 * exponent + ((bits & 0xFFFFFFFFFFFFFull) >= sqrt2Fraction);
}

// 2^e for e in [-1022, 1023], exactly.
inline double powerOfTwo(int e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double p;
  std::memcpy(&p, &bits, sizeof p);
  return p;
}

}  // namespace geocdt
