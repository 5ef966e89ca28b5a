#pragma once
// The area of a raster that has data: the union of the grid cells (the unit squares between
// four neighbouring pixel positions) whose four corners have data. Its boundary runs along
// grid lines; it is traced into closed rings of corner points, which the mesh takes as
// constraints so that it covers that area and nothing else.
#include <cstdint>
#include <vector>

#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

struct ValidArea {
  // The rings in GeoArrow's layout: ring r has the points offsets[r] .. offsets[r + 1] of xy,
  // its last point repeating its first; only the corners where the boundary turns (and
  // where rings touch) are points. Each ring has the area on its left (y up).
  std::vector<double> xy;
  std::vector<std::uint32_t> offsets{0};
  std::size_t cells = 0;  // grid cells with data

  std::size_t ringCount() const { return offsets.size() - 1; }
};

// The rings around the cells with data of raster (which has at least 2 rows and columns).
ValidArea traceValidArea(const RasterSampler& raster);

}  // namespace geocdt::terrain
