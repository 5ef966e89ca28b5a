#pragma once
// The check that decides whether computed crossings are kept or snap rounding takes over:
// after the usual insertion, the chains of the input segments that met a crossing (or passed
// through a vertex on them) must keep the documented guarantee. Each must lead from its segment's
// first vertex to its last through constrained edges naming its polyline, its vertices within two
// spacings of doubles of the segment (at the segment's largest coordinate) and in strictly
// increasing order along it; and it must not cross the chain of another segment, met at a shared
// vertex, that its segment does not cross (away from their ends). Chains are found as the test
// checker finds them (the one that strays least, ties to the lower vertex ids), so that whatever
// passes here passes there. Real data passes: Natural Earth, GSHHG and US counties keep their
// computed crossings.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "delaunay/vertex_edges.h"

namespace geocdt {

// Whether the chains of the given input segments (indices into the constraint store, in any
// order, repeats allowed) keep the guarantee. Chains start from ends' half-edges.
bool chainsKeepTheGuarantee(Delaunay& d, std::vector<std::uint32_t> segments, VertexEdges& ends);

}  // namespace geocdt
