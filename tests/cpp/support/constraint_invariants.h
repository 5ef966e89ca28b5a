#pragma once
// The constraint half of the checker: input segments and constrained edges must match within
// the documented bound, in order, without new crossings.
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

using Polylines = std::vector<std::vector<double>>;

// The bound every output chain keeps from its input segment (ax, ay)-(bx, by): two ulps of
// the largest |coordinate| of the segment's ends (the spacing of doubles there; among
// subnormals the smallest double).
double chainBound(double ax, double ay, double bx, double by);

// Checks, exactly:
//  - every constrained edge lies within the bound of some input segment;
//  - every input segment is covered by a chain of constrained edges from its first vertex to
//    its last whose vertices all lie within the bound of it, in strictly increasing order
//    along it;
//  - no new crossings: the chains of two input segments that do not meet never cross (they
//    may touch), and the chains of two segments that cross properly cross once, where each
//    shared stretch of the two chains lies away from their ends (at an end, touching and
//    crossing are the same thing);
//  - with `overlaps`, where the mesh names each edge's segments (MeshOptions::segmentSources):
//    an edge routed for a segment it lies exactly on names every polyline with a segment it
//    lies exactly on (overlapping segments share their edges). Real data keeps it; in ulp
//    tangles overlapping segments can part at rounded crossings (README, "Known
//    limitations"), so the fuzzers do not ask for it.
// inputToVertex holds the polylines' vertex ids in order (all points of polyline 0, then
// polyline 1, ...). Returns "" when everything holds, else the first failure.
std::string checkConstraints(const Mesh& mesh, const Polylines& polylines,
                             const std::vector<std::uint32_t>& inputToVertex,
                             bool overlaps = false);

// Whether both points lie within the bound of one segment of the polyline (exactly).
bool withinBoundOfPolyline(const std::vector<double>& line, double x0, double y0, double x1,
                           double y1);

// Even-odd inside test of a point against the rings among the polylines, by ray casting.
bool insideEvenOdd(const Polylines& polylines, double x, double y);

// Distance from (x, y) to the nearest segment of the polylines.
double distanceToPolylines(const Polylines& polylines, double x, double y);

}  // namespace geocdt::testing
