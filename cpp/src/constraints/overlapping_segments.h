#pragma once
// Refinement's test for a subsegment that another input segment runs along, ulps from it but
// not on its line (overlapping segments rounded apart): a point placed on one may land on the
// far side of the other and make their chains cross, so such a subsegment is left whole.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"

namespace geocdt {

// Whether the constrained edge a-b, which stands for input segment `segment` (geometry s),
// lies within the bound of another input segment not on s's line. The segments looked at are
// those of the constrained edges at a and b; vertexEdge gives a half-edge out of each vertex.
// An end flagged in `splitEnds` (bit 0: a, bit 1: b) was made by splitting a constrained edge
// of this chain, so its two constrained edges carry what a-b carries: a-b's are looked at
// for it, with no turn round it.
bool runsAlongAnotherSegment(const Delaunay& d, const std::vector<std::int32_t>& vertexEdge,
                             std::uint32_t a, std::uint32_t b, std::uint64_t segment,
                             const InputSegment& s, unsigned splitEnds = 0);

}  // namespace geocdt
