#pragma once
// The order in which a batch of points is inserted. Spatially coherent orders keep the
// walk short and the memory traffic local.
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt {

// Returns the indices 0..count-1 of the points xy in the order to insert them.
std::vector<std::uint32_t> insertionOrder(const double* xy, std::uint32_t count,
                                          InsertionOrder order);
// The same for the points subset[0..count) of xy: returns them (their indices in xy) in the
// order to insert them.
std::vector<std::uint32_t> insertionOrder(const double* xy, const std::uint32_t* subset,
                                          std::uint32_t count, InsertionOrder order);

// The bounding box of count >= 1 points xy.
struct Bounds {
  double minX, minY, maxX, maxY;
};
Bounds boundsOf(const double* xy, std::uint32_t count);

// Position along a Hilbert curve of 2^bits x 2^bits cells, x and y in [0, 2^bits).
std::uint32_t hilbertIndex(std::uint32_t x, std::uint32_t y, int bits);

}  // namespace geocdt
