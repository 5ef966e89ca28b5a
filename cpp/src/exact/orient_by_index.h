#pragma once
// orient2d of three points given by their indices into interleaved x, y coordinates.
#include <cstdint>

#include "geocdt/predicates.h"

namespace geocdt {

inline Sign orientByIndex(const double* xy, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * c], xy[2 * c + 1]);
}

inline bool counterClockwise(const double* xy, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return orientByIndex(xy, a, b, c) == Sign::Positive;
}

}  // namespace geocdt
