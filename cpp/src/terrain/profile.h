#pragma once
// A raster of one row or one column has no triangles: its mesh is its simplified profile, the
// ends of each run of pixels with data and, greedily, the pixels farthest from the line
// between their neighbours until every pixel is within the bound.
#include <cstdint>
#include <vector>

#include "terrain/greedy_mesher.h"
#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

struct Profile {
  std::vector<double> xy;  // pixel positions, in order along the line
  std::vector<double> z;
  double maxError = 0;
  std::uint64_t scannedPixels = 0;
};

// raster has one row or one column.
Profile simplifyProfile(const RasterSampler& raster, const MesherLimits& limits);

}  // namespace geocdt::terrain
