#pragma once
// The constraint half of the checker: input segments and constrained edges must match,
// up to the rounding of crossing points.
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

using Polylines = std::vector<std::vector<double>>;

// Every constrained edge lies on some input segment, and every input segment is covered
// by a chain of constrained edges lying on it. inputToVertex holds the polylines' vertex ids
// in order (all points of polyline 0, then polyline 1, ...).
std::string checkConstraints(const Mesh& mesh, const Polylines& polylines,
                             const std::vector<std::uint32_t>& inputToVertex);

// Even-odd inside test of a point against the rings among the polylines, by ray casting.
bool insideEvenOdd(const Polylines& polylines, double x, double y);

// Distance from (x, y) to the nearest segment of the polylines.
double distanceToPolylines(const Polylines& polylines, double x, double y);

}  // namespace geocdt::testing
