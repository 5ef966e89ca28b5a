#pragma once
// Orientation and in-circle for points whose coordinates are integers spanning at most
// kSmallIntegerSpan on each axis, as map tiles have them (an extent of 4096 or 8192 and its
// buffer): exact with no filter. Every difference of two coordinates is then an integer of
// magnitude at most 2^14, so orientation's products (at most 2^28) and their difference are
// exact in doubles; in-circle's lifts and cross terms (at most 2^29 each) are exact in doubles
// too, and their products (at most 2^58, three summed below 2^60) in 64-bit integers. The same
// signs as orient2d() and incircle(), for a third to a half of their instructions.
#include <cmath>
#include <cstdint>

#include "geocdt/predicates.h"

namespace geocdt {

inline constexpr double kSmallIntegerSpan = 16384.0;  // 2^14

// Whether the count points xy (x, y pairs) are integers within a box of side at most
// kSmallIntegerSpan on each axis.
inline bool areSmallIntegers(const double* xy, std::size_t count) {
  // Integers first, stopping at the first that is not one (lon/lat fails at once); through a
  // 64-bit integer, which libm's trunc() would cost a call for where no instruction does it.
  for (std::size_t i = 0; i < 2 * count; ++i) {
    const double v = xy[i];
    if (!(std::fabs(v) < 0x1p52) || v != static_cast<double>(static_cast<std::int64_t>(v)))
      return false;
  }
  if (count == 0) return true;
  double minX = xy[0], maxX = xy[0], minY = xy[1], maxY = xy[1];
  for (std::size_t i = 1; i < count; ++i) {
    const double x = xy[2 * i], y = xy[2 * i + 1];
    minX = x < minX ? x : minX;
    maxX = x > maxX ? x : maxX;
    minY = y < minY ? y : minY;
    maxY = y > maxY ? y : maxY;
  }
  return maxX - minX <= kSmallIntegerSpan && maxY - minY <= kSmallIntegerSpan;
}

inline Sign signOf(double v) {
  return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero);
}

inline Sign orient2dSmallIntegers(double ax, double ay, double bx, double by, double cx,
                                  double cy) {
  return signOf((ax - cx) * (by - cy) - (ay - cy) * (bx - cx));
}

inline Sign incircleSmallIntegers(double ax, double ay, double bx, double by, double cx, double cy,
                                  double dx, double dy) {
  const double adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy;
  const double cdx = cx - dx, cdy = cy - dy;
  const auto alift = static_cast<std::int64_t>(adx * adx + ady * ady);
  const auto blift = static_cast<std::int64_t>(bdx * bdx + bdy * bdy);
  const auto clift = static_cast<std::int64_t>(cdx * cdx + cdy * cdy);
  const auto bc = static_cast<std::int64_t>(bdx * cdy - cdx * bdy);
  const auto ca = static_cast<std::int64_t>(cdx * ady - adx * cdy);
  const auto ab = static_cast<std::int64_t>(adx * bdy - bdx * ady);
  const std::int64_t det = alift * bc + blift * ca + clift * ab;
  return det > 0 ? Sign::Positive : (det < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace geocdt
