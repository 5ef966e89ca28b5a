#pragma once
// Rasters of the values carried by the vertices.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "geocdt/triangulation.h"

namespace geocdt {

// Writes the linear surface of values (k per vertex) into the pixels of grid (width > 0,
// height > 0, finite bounds with min < max) whose centres lie in a triangle; other pixels are
// left as they are.
void rasterizeLinear(const Delaunay& d, const std::vector<double>& values, std::uint32_t k,
                     const RasterGrid& grid, float* out);

}  // namespace geocdt
