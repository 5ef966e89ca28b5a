#include "voronoi/lloyd.h"

#include <algorithm>
#include <cmath>

namespace geocdt {

// Area-weighted centroids of the rings (holes wind the other way and subtract), from
// coordinates relative to the site, so that nothing cancels at large coordinates, and scaled by
// a power of two to the cell's extent, so that the cubes of a large cell's coordinates do not
// overflow (nor a tiny one's underflow). The centroid is kept in the cell's bounding box.
double moveToCentroids(const VoronoiCells& cells, std::vector<double>& sites) {
  double longest = 0;
  const std::size_t count = sites.size() / 2;
  const double* xy = cells.coords.data();
  for (std::size_t i = 0; i < count; ++i) {
    if (cells.siteOffsets[i] == cells.siteOffsets[i + 1]) continue;
    const double ox = sites[2 * i], oy = sites[2 * i + 1];
    const std::uint32_t first = cells.ringOffsets[cells.polygonOffsets[cells.siteOffsets[i]]];
    const std::uint32_t last = cells.ringOffsets[cells.polygonOffsets[cells.siteOffsets[i + 1]]];
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY, extent = 0;
    for (std::uint32_t k = first; k < last; ++k) {
      minX = std::min(minX, xy[2 * k]);
      maxX = std::max(maxX, xy[2 * k]);
      minY = std::min(minY, xy[2 * k + 1]);
      maxY = std::max(maxY, xy[2 * k + 1]);
      extent = std::max({extent, std::fabs(xy[2 * k] - ox), std::fabs(xy[2 * k + 1] - oy)});
    }
    if (!(extent > 0) || !std::isfinite(extent)) continue;
    const int shift = -std::ilogb(extent);
    double twiceArea = 0, sx = 0, sy = 0;
    for (std::uint32_t p = cells.siteOffsets[i]; p < cells.siteOffsets[i + 1]; ++p)
      for (std::uint32_t r = cells.polygonOffsets[p]; r < cells.polygonOffsets[p + 1]; ++r)
        for (std::uint32_t k = cells.ringOffsets[r]; k + 1 < cells.ringOffsets[r + 1]; ++k) {
          const double ax = std::ldexp(xy[2 * k] - ox, shift);
          const double ay = std::ldexp(xy[2 * k + 1] - oy, shift);
          const double bx = std::ldexp(xy[2 * k + 2] - ox, shift);
          const double by = std::ldexp(xy[2 * k + 3] - oy, shift);
          const double cross = ax * by - ay * bx;
          twiceArea += cross;
          sx += (ax + bx) * cross;
          sy += (ay + by) * cross;
        }
    if (!(twiceArea > 0)) continue;
    const double dx = std::ldexp(sx / (3 * twiceArea), -shift);
    const double dy = std::ldexp(sy / (3 * twiceArea), -shift);
    sites[2 * i] = std::clamp(ox + dx, minX, maxX);
    sites[2 * i + 1] = std::clamp(oy + dy, minY, maxY);
    longest = std::max(longest, std::hypot(dx, dy));
  }
  return longest;
}

}  // namespace geocdt
