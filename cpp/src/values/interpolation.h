#pragma once
// Values anywhere in the triangulation, from the values of its vertices.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "geocdt/triangulation.h"

namespace geocdt {

// Values at count points (see Triangulation::interpolate), from values (perPoint per vertex).
void interpolateValues(Delaunay& d, const std::vector<double>& values, std::uint32_t perPoint,
                       const double* xy, std::size_t count, Interpolation method, double* out);

}  // namespace geocdt
