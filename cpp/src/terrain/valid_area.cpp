#include "terrain/valid_area.h"

namespace geocdt::terrain {

namespace {

// Directions along grid lines, counter-clockwise from east (y up): east, north, west, south.
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

class Tracer {
 public:
  explicit Tracer(const RasterSampler& raster)
      : w_(raster.width()), h_(raster.height()), cells_((w_ - 1) * std::size_t{h_ - 1}, 0) {
    for (std::uint32_t j = 0; j + 1 < h_; ++j)
      for (std::uint32_t i = 0; i + 1 < w_; ++i)
        cells_[cell(i, j)] =
            raster.valid(raster.pixel(i, j)) && raster.valid(raster.pixel(i + 1, j)) &&
            raster.valid(raster.pixel(i, j + 1)) && raster.valid(raster.pixel(i + 1, j + 1));
    used_.assign(2 * std::size_t{w_} * h_, 0);
  }

  ValidArea trace() {
    ValidArea area;
    for (std::size_t c = 0; c < cells_.size(); ++c) area.cells += cells_[c];
    // Every boundary edge starts one ring at most once: scan the horizontal ones (every ring
    // has some) and follow each unused one round.
    for (std::uint32_t j = 0; j < h_; ++j)
      for (std::uint32_t i = 0; i + 1 < w_; ++i)
        for (int d : {0, 2}) {
          const std::int64_t x = d == 0 ? i : i + 1;
          if (boundary(x, j, d) && !used(x, j, d)) follow(x, j, d, area);
        }
    return area;
  }

 private:
  std::size_t cell(std::uint32_t i, std::uint32_t j) const {
    return static_cast<std::size_t>(j) * (w_ - 1) + i;
  }
  bool cellValid(std::int64_t i, std::int64_t j) const {
    if (i < 0 || j < 0 || i + 1 >= w_ || j + 1 >= h_) return false;
    return cells_[cell(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j))] != 0;
  }
  // Whether the grid edge from (x, y) in direction d has a cell with data on its left and
  // none on its right. Cell (i, j) spans [i, i + 1] x [j, j + 1].
  bool boundary(std::int64_t x, std::int64_t y, int d) const {
    const std::int64_t ex = x + kDx[d], ey = y + kDy[d];
    if (ex < 0 || ey < 0 || ex >= w_ || ey >= h_) return false;
    std::int64_t li, lj, ri, rj;  // the cells left and right of the edge
    switch (d) {
      case 0: li = x, lj = y, ri = x, rj = y - 1; break;
      case 1: li = x - 1, lj = y, ri = x, rj = y; break;
      case 2: li = x - 1, lj = y - 1, ri = x - 1, rj = y; break;
      default: li = x, lj = y - 1, ri = x - 1, rj = y - 1; break;
    }
    return cellValid(li, lj) && !cellValid(ri, rj);
  }
  // A grid edge's used flag, by its lower-left end and axis.
  std::uint8_t& usedFlag(std::int64_t x, std::int64_t y, int d) {
    const std::int64_t ex = x + kDx[d], ey = y + kDy[d];
    const std::int64_t lx = ex < x ? ex : x, ly = ey < y ? ey : y;
    return used_[2 * (static_cast<std::size_t>(ly) * w_ + static_cast<std::size_t>(lx)) + (d & 1)];
  }
  bool used(std::int64_t x, std::int64_t y, int d) { return usedFlag(x, y, d) != 0; }

  // Follows the ring through the boundary edge from (x, y) in direction d, appending its
  // corners. Each vertex pairs every boundary edge arriving with the first boundary edge
  // leaving it in the order left, straight on, right: where two cells with data touch
  // diagonally, that turns left, so that each ring goes round its own cells, and following
  // the pairs always leads back to the first edge.
  void follow(std::int64_t x, std::int64_t y, int d, ValidArea& area) {
    const std::int64_t startX = x, startY = y;
    const int startD = d;
    const std::size_t first = area.xy.size();
    for (;;) {
      usedFlag(x, y, d) = 1;
      x += kDx[d];
      y += kDy[d];
      int next = -1;
      for (int turn : {1, 0, 3}) {
        const int e = (d + turn) & 3;
        if (boundary(x, y, e)) {
          next = e;
          break;
        }
      }
      if (next < 0 || (x == startX && y == startY && next == startD)) break;
      if (next != d) {
        area.xy.push_back(static_cast<double>(x));
        area.xy.push_back(static_cast<double>(y));
      }
      d = next;
    }
    // The start is a corner unless the ring arrives there going straight on.
    if (d != startD) {
      area.xy.insert(area.xy.begin() + static_cast<std::ptrdiff_t>(first),
                     {static_cast<double>(startX), static_cast<double>(startY)});
    }
    area.xy.push_back(area.xy[first]);
    area.xy.push_back(area.xy[first + 1]);
    area.offsets.push_back(static_cast<std::uint32_t>(area.xy.size() / 2));
  }

  std::uint32_t w_, h_;
  std::vector<std::uint8_t> cells_;
  std::vector<std::uint8_t> used_;  // 2 per grid vertex: its east and north edges
};

}  // namespace

ValidArea traceValidArea(const RasterSampler& raster) { return Tracer(raster).trace(); }

}  // namespace geocdt::terrain
