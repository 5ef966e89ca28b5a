#pragma once
// Pixel positions (x the column, y the row) and the map coordinates a bbox gives them: pixel
// (0, 0) at (minX, maxY), pixel (width - 1, height - 1) at (maxX, minY). The map is affine
// and flips y, so a triangle counter-clockwise in pixels is clockwise on the map.
#include <cstdint>

namespace geocdt::terrain {

class PixelFrame {
 public:
  PixelFrame() = default;
  PixelFrame(double minX, double minY, double maxX, double maxY, std::uint32_t width,
             std::uint32_t height)
      : mapped_(true),
        minX_(minX),
        maxX_(maxX),
        minY_(minY),
        maxY_(maxY),
        lastX_(width - 1.0),
        lastY_(height - 1.0) {}

  bool mapped() const { return mapped_; }  // false: pixel positions are the map's
  // The ends of the range are given as they are, so that tiles sharing a border agree on it.
  // A single column lies at minX (the west edge), a single row at maxY (the north edge).
  double mapX(double x) const {
    if (!mapped_) return x;
    if (lastX_ == 0) return minX_;
    if (x == lastX_) return maxX_;
    return minX_ + (maxX_ - minX_) * (x / lastX_);
  }
  double mapY(double y) const {
    if (!mapped_) return y;
    if (lastY_ == 0) return maxY_;
    if (y == lastY_) return minY_;
    return maxY_ - (maxY_ - minY_) * (y / lastY_);
  }
  double pixelX(double x) const {
    if (!mapped_) return x;
    if (lastX_ == 0)
      return maxX_ > minX_ ? (x - minX_) / (maxX_ - minX_) : (x > minX_) - (x < minX_);
    if (x == maxX_) return lastX_;
    return lastX_ * ((x - minX_) / (maxX_ - minX_));
  }
  double pixelY(double y) const {
    if (!mapped_) return y;
    if (lastY_ == 0)
      return maxY_ > minY_ ? (maxY_ - y) / (maxY_ - minY_) : (y < maxY_) - (y > maxY_);
    if (y == minY_) return lastY_;
    return lastY_ * ((maxY_ - y) / (maxY_ - minY_));
  }

 private:
  bool mapped_ = false;
  double minX_ = 0, maxX_ = 0, minY_ = 0, maxY_ = 0, lastX_ = 0, lastY_ = 0;
};

}  // namespace geocdt::terrain
