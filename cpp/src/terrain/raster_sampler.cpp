#include "terrain/raster_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt::terrain {

double RasterSampler::sample(double x, double y) const {
  const double maxX = width_ - 1.0, maxY = height_ - 1.0;
  x = std::clamp(x, 0.0, maxX);
  y = std::clamp(y, 0.0, maxY);
  const double fx = std::floor(x), fy = std::floor(y);
  const auto i = static_cast<std::uint32_t>(fx), j = static_cast<std::uint32_t>(fy);
  const double tx = x - fx, ty = y - fy;
  // The four pixels around (x, y) with their weights; those past the last row or column have
  // weight 0 (x or y is then exactly on that last line).
  const double weight[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  const std::uint32_t di[4] = {0, 1, 0, 1}, dj[4] = {0, 0, 1, 1};
  double sum = 0, total = 0;
  for (int k = 0; k < 4; ++k) {
    if (weight[k] == 0) continue;
    const std::size_t p = pixel(i + di[k], j + dj[k]);
    if (!valid(p)) continue;
    sum += weight[k] * heights_[p];
    total += weight[k];
  }
  if (total == 0) return std::numeric_limits<double>::quiet_NaN();
  return total == 1 ? sum : sum / total;
}

}  // namespace geocdt::terrain
