#include "terrain/height_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt::terrain {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The float nearest z on the side of it given.
float below(double z) {
  const auto f = static_cast<float>(z);
  return static_cast<double>(f) <= z ? f : std::nextafter(f, -kInfinity);
}
float above(double z) {
  const auto f = static_cast<float>(z);
  return static_cast<double>(f) >= z ? f : std::nextafter(f, kInfinity);
}

}  // namespace

HeightBlocks::HeightBlocks(const RasterSampler& raster)
    : columns_((raster.width() + kSide - 1) >> kShift) {
  const std::uint32_t width = raster.width(), height = raster.height();
  const std::uint32_t rows = (height + kSide - 1) >> kShift;
  range_.resize(2 * static_cast<std::size_t>(columns_) * rows);
  std::vector<double> low(columns_), high(columns_);
  for (std::uint32_t row = 0; row < rows; ++row) {
    std::fill(low.begin(), low.end(), std::numeric_limits<double>::infinity());
    std::fill(high.begin(), high.end(), -std::numeric_limits<double>::infinity());
    for (std::uint32_t j = row << kShift; j < std::min(height, (row + 1) << kShift); ++j) {
      const double* line = raster.heights() + raster.pixel(0, j);
      for (std::uint32_t column = 0; column < columns_; ++column) {
        // (A NaN compares false: min and max, in this order, pass over it.)
        double lo = low[column], hi = high[column];
        const std::uint32_t end = std::min(width, (column + 1) << kShift);
        for (std::uint32_t i = column << kShift; i < end; ++i) {
          lo = std::min(lo, line[i]);
          hi = std::max(hi, line[i]);
        }
        low[column] = lo;
        high[column] = hi;
      }
    }
    for (std::uint32_t column = 0; column < columns_; ++column) {
      float* r = &range_[2 * (static_cast<std::size_t>(row) * columns_ + column)];
      const bool empty = !(low[column] <= high[column]);
      r[0] = empty ? kInfinity : below(low[column]);
      r[1] = empty ? -kInfinity : above(high[column]);
    }
  }
}

}  // namespace geocdt::terrain
