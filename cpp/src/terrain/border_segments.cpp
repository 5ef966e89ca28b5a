#include "terrain/border_segments.h"

#include <algorithm>
#include <cmath>

namespace geocdt::terrain {

std::uint64_t BorderSegments::scan(std::uint32_t i, const double* xy, const double* z,
                                   const RasterSampler& raster) {
  BorderSegment& s = segments_[i];
  s.error = 0;
  s.pixel = -1;
  const double ax = xy[2 * s.a], ay = xy[2 * s.a + 1], bx = xy[2 * s.b], by = xy[2 * s.b + 1];
  const bool horizontal = ay == by && ay == std::floor(ay);
  const bool vertical = ax == bx && ax == std::floor(ax);
  if (horizontal == vertical) return 0;  // off the grid lines, or a point
  // Positions along the line, from the end with the lower coordinate: the same arithmetic
  // whichever way the segment was made, and in whichever tile.
  const double fixed = horizontal ? ay : ax;
  double lo = horizontal ? ax : ay, hi = horizontal ? bx : by;
  double zlo = z[s.a], zhi = z[s.b];
  if (hi < lo) {
    std::swap(lo, hi);
    std::swap(zlo, zhi);
  }
  const double limit = horizontal ? raster.width() - 1.0 : raster.height() - 1.0;
  const double across = horizontal ? raster.height() - 1.0 : raster.width() - 1.0;
  if (fixed < 0 || fixed > across) return 0;
  const double first = std::max(std::floor(lo) + 1, 0.0);
  const double last = std::min(std::ceil(hi) - 1, limit);
  const double length = hi - lo, rise = zhi - zlo;
  double best = 0;
  std::int64_t bestPixel = -1;
  for (double p = first; p <= last; ++p) {
    const std::size_t pixel =
        horizontal ? raster.pixel(static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(fixed))
                   : raster.pixel(static_cast<std::uint32_t>(fixed), static_cast<std::uint32_t>(p));
    const double e = std::fabs(raster.at(pixel) - (zlo + rise * ((p - lo) / length)));
    if (e > best) {
      best = e;
      bestPixel = static_cast<std::int64_t>(pixel);
    }
  }
  s.error = best;
  s.pixel = bestPixel;
  return last >= first ? static_cast<std::uint64_t>(last - first + 1) : 0;
}

}  // namespace geocdt::terrain
