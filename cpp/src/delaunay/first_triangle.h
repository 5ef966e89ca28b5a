#pragma once
// The first triangle of a triangulation: the first point, the first one after it at another
// place, and the first one after that not on their line.
#include <cstddef>

#include "geocdt/predicates.h"

namespace geocdt {

// at(i) gives the vertex of the i-th of n candidates, p their coordinates. Sets i1 and i2 to
// the second and third corners' candidates (the first is candidate 0) and returns true, or
// returns false when all n lie on one line.
template <typename At>
bool findFirstTriangle(const double* p, At at, std::size_t n, std::size_t& i1, std::size_t& i2) {
  const auto same = [p](std::size_t u, std::size_t v) {
    return p[2 * u] == p[2 * v] && p[2 * u + 1] == p[2 * v + 1];
  };
  i1 = 1;
  while (i1 < n && same(at(0), at(i1))) ++i1;
  i2 = i1 + 1;
  if (i1 >= n) return false;
  const std::size_t a = at(0), b = at(i1);
  while (i2 < n && orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * at(i2)],
                            p[2 * at(i2) + 1]) == Sign::Zero)
    ++i2;
  return i2 < n;
}

}  // namespace geocdt
