#include "voronoi/lloyd.h"

#include <algorithm>
#include <cmath>

namespace geocdt {

// Area-weighted centroids of the rings (holes wind the other way and subtract), from
// coordinates relative to the site, so that nothing cancels at large coordinates.
double moveToCentroids(const VoronoiCells& cells, std::vector<double>& sites) {
  double longest = 0;
  const std::size_t count = sites.size() / 2;
  const double* xy = cells.coords.data();
  for (std::size_t i = 0; i < count; ++i) {
    const double ox = sites[2 * i], oy = sites[2 * i + 1];
    double twiceArea = 0, sx = 0, sy = 0;
    for (std::uint32_t p = cells.siteOffsets[i]; p < cells.siteOffsets[i + 1]; ++p)
      for (std::uint32_t r = cells.polygonOffsets[p]; r < cells.polygonOffsets[p + 1]; ++r)
        for (std::uint32_t k = cells.ringOffsets[r]; k + 1 < cells.ringOffsets[r + 1]; ++k) {
          const double ax = xy[2 * k] - ox, ay = xy[2 * k + 1] - oy;
          const double bx = xy[2 * k + 2] - ox, by = xy[2 * k + 3] - oy;
          const double cross = ax * by - ay * bx;
          twiceArea += cross;
          sx += (ax + bx) * cross;
          sy += (ay + by) * cross;
        }
    if (!(twiceArea > 0)) continue;
    const double dx = sx / (3 * twiceArea), dy = sy / (3 * twiceArea);
    sites[2 * i] = ox + dx;
    sites[2 * i + 1] = oy + dy;
    longest = std::max(longest, std::hypot(dx, dy));
  }
  return longest;
}

}  // namespace geocdt
