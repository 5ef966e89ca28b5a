#pragma once
// The lowest and highest height of each 8 x 8 block of pixels. A block's pixels lie no farther
// from a plane than the larger of (its highest - the plane's lowest over it) and (the plane's
// highest - its lowest): a scan passes over the blocks that cannot beat the largest error it
// found already (triangle_scan.cpp). Most pixels of a large triangle lie near its plane.
#include <cstdint>
#include <vector>

#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

class HeightBlocks {
 public:
  static constexpr std::uint32_t kShift = 3;
  static constexpr std::uint32_t kSide = 1u << kShift;  // pixels a block's side

  explicit HeightBlocks(const RasterSampler& raster);

  // Block (column, row)'s lowest and highest height (rounded outwards to floats; NaN left
  // out, which no scan picks): low > high when there are none. Pixels without data count as
  // any other: a scan measures whatever pixel its triangle covers.
  const float* range(std::uint32_t column, std::uint32_t row) const {
    return &range_[2 * (static_cast<std::size_t>(row) * columns_ + column)];
  }

 private:
  std::uint32_t columns_;
  std::vector<float> range_;
};

}  // namespace geocdt::terrain
