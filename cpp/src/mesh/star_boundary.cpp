#include "mesh/star_boundary.h"

#include <utility>

#include "geocdt/predicates.h"

namespace geocdt {

bool orderStarBoundary(const Topology& topo, const std::vector<double>& xy, std::size_t slots,
                       double px, double py, std::vector<std::int32_t>& boundary) {
  const std::size_t n = boundary.size();
  if (n != slots + 2) return false;
  // Chain each edge to the one starting where it ends: a few edges, searched in place.
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t e = boundary[i];
    const std::uint32_t a = topo.tri[e], b = topo.tri[nextEdge(e)];
    if (orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], px, py) != Sign::Positive)
      return false;
    if (i + 1 == n) return b == topo.tri[boundary[0]];
    std::size_t j = i + 1;
    while (j < n && topo.tri[boundary[j]] != b) ++j;
    if (j == n) return false;
    std::swap(boundary[i + 1], boundary[j]);
  }
  return false;
}

}  // namespace geocdt
