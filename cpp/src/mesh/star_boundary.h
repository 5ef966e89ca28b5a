#pragma once
// The border of a cavity, for inserting a vertex by joining it to the border (Bowyer-Watson)
// instead of by flips: refinement finds the cavity with its own in-circle tests anyway.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/topology.h"

namespace geocdt {

// `boundary` holds, in any order, the half-edges of a cavity's triangles whose twins are
// outside it (or constrained); the cavity has `slots` triangles, none a ghost. Puts them in
// counter-clockwise order and returns true when joining (px, py) to them replaces the
// cavity: one closed chain of slots + 2 edges (no vertex inside the cavity), each strictly
// counter-clockwise around the point. The chain then winds once around the point, so the
// cavity is a disk star-shaped from it. Otherwise returns false, and the caller inserts by
// flips.
bool orderStarBoundary(const Topology& topo, const std::vector<double>& xy, std::size_t slots,
                       double px, double py, std::vector<std::int32_t>& boundary);

}  // namespace geocdt
