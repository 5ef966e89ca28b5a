#pragma once
// Heights of a raster at pixel positions (x the column, y the row) and between them: the
// pixels' own heights, and bilinear samples for vertices that are not pixels (breakline
// points, crossings, Steiner points). Pixels without data never enter a sample.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace geocdt::terrain {

class RasterSampler {
 public:
  // valid: one byte per pixel, 1 where it has data; empty when every pixel has.
  RasterSampler(const double* heights, std::uint32_t width, std::uint32_t height,
                std::vector<std::uint8_t> valid)
      : heights_(heights), width_(width), height_(height), valid_(std::move(valid)) {}

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  const double* heights() const { return heights_; }
  std::size_t pixel(std::uint32_t i, std::uint32_t j) const {
    return static_cast<std::size_t>(j) * width_ + i;
  }
  double at(std::size_t pixel) const { return heights_[pixel]; }
  bool valid(std::size_t pixel) const { return valid_.empty() || valid_[pixel] != 0; }
  bool allValid() const { return valid_.empty(); }
  const std::vector<std::uint8_t>& validMask() const { return valid_; }

  // The bilinear sample at (x, y), clamped into the raster, weighted over the pixels with data
  // among the (up to) four around it that have a weight; NaN when none has. At a pixel
  // position it is that pixel's height exactly.
  double sample(double x, double y) const;

 private:
  const double* heights_;
  std::uint32_t width_, height_;
  std::vector<std::uint8_t> valid_;
};

}  // namespace geocdt::terrain
