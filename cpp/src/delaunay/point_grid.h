#pragma once
// Skvortsov's dynamic uniform grid: m x m cells over a bounding box, each remembering a
// triangle near it. It starts at m = 1 and doubles per axis when the points inserted exceed
// density * m * m, each old cell handing its triangle to its four children.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace geocdt {

class PointGrid {
 public:
  void reset(double minX, double minY, double maxX, double maxY, double density) {
    minX_ = minX;
    minY_ = minY;
    const double w = maxX - minX, h = maxY - minY;
    // A degenerate box maps every point to one column or row: the walk does the rest.
    scaleX_ = w > 0 ? 1.0 / w : 0.0;
    scaleY_ = h > 0 ? 1.0 / h : 0.0;
    density_ = density > 0 ? density : 1.0;
    m_ = 1;
    cells_.assign(1, -1);
  }

  bool empty() const { return cells_.empty(); }
  std::uint32_t size() const { return m_; }

  std::int32_t& cellAt(double x, double y) {
    return cells_[static_cast<std::size_t>(row(y)) * m_ + column(x)];
  }

  // Whether (ax, ay) lies within two cells of (bx, by) along both axes.
  bool near(double ax, double ay, double bx, double by) const {
    const std::uint32_t i = column(ax), j = row(ay), k = column(bx), l = row(by);
    return (i > k ? i - k : k - i) <= 2 && (j > l ? j - l : l - j) <= 2;
  }
  // The hint of the cell di columns and dj rows from (x, y)'s, or -1 beyond the grid.
  std::int32_t neighbour(double x, double y, int di, int dj) const {
    const std::int64_t i = std::int64_t{column(x)} + di, j = std::int64_t{row(y)} + dj;
    if (i < 0 || j < 0 || i >= m_ || j >= m_) return -1;
    return cells_[static_cast<std::size_t>(j) * m_ + static_cast<std::size_t>(i)];
  }

  // Called after each insertion with the number of points inserted so far.
  void grow(std::uint64_t inserted) {
    if (static_cast<double>(inserted) <= density_ * m_ * m_ || m_ >= kMaxSize) return;
    const std::uint32_t m = m_ * 2;
    std::vector<std::int32_t> cells(static_cast<std::size_t>(m) * m);
    for (std::uint32_t j = 0; j < m; ++j)
      for (std::uint32_t i = 0; i < m; ++i)
        cells[static_cast<std::size_t>(j) * m + i] =
            cells_[static_cast<std::size_t>(j / 2) * m_ + i / 2];
    cells_.swap(cells);
    m_ = m;
  }

  // The size grow() would have reached after `inserted` insertions, with every cell empty
  // (-1): for rebuild() after a batch that did not keep the grid up to date.
  void resizeFor(std::uint64_t inserted) {
    m_ = sizeFor(inserted);
    cells_.assign(static_cast<std::size_t>(m_) * m_, -1);
  }
  std::uint32_t sizeFor(std::uint64_t inserted) const {
    std::uint32_t m = m_;
    while (static_cast<double>(inserted) > density_ * m * m && m < kMaxSize) m *= 2;
    return m;
  }

  void fill(std::int32_t triangle) { std::fill(cells_.begin(), cells_.end(), triangle); }

  // Fresh hints after a large batch: for each cell, a triangle with a vertex in it; a cell
  // with none takes its left (or upper) neighbour's. A spatially sorted batch leaves stale
  // hints in the cells it never visited, which this replaces. at(k, x, y) gives the k-th of
  // count places and a triangle there, or -1 for none.
  template <typename PlaceOf>
  void rebuild(std::uint32_t count, PlaceOf at, std::int32_t fallback) {
    std::fill(cells_.begin(), cells_.end(), -1);
    for (std::uint32_t k = 0; k < count; ++k) {
      double x, y;
      const std::int32_t t = at(k, x, y);
      if (t >= 0) cellAt(x, y) = t;
    }
    for (std::uint32_t j = 0; j < m_; ++j)
      for (std::uint32_t i = 0; i < m_; ++i) {
        std::int32_t& c = cells_[static_cast<std::size_t>(j) * m_ + i];
        if (c >= 0) continue;
        c = i > 0 ? cells_[static_cast<std::size_t>(j) * m_ + i - 1]
                  : (j > 0 ? cells_[static_cast<std::size_t>(j - 1) * m_] : -1);
        if (c < 0) c = fallback;
      }
  }

 private:
  static constexpr std::uint32_t kMaxSize = 1u << 13;

  std::uint32_t column(double x) const { return clampCell((x - minX_) * scaleX_); }
  std::uint32_t row(double y) const { return clampCell((y - minY_) * scaleY_); }
  std::uint32_t clampCell(double unit) const {
    const double c = unit * m_;
    if (!(c > 0)) return 0;  // also catches NaN from out-of-range arithmetic
    return c >= m_ ? m_ - 1 : static_cast<std::uint32_t>(c);
  }

  double minX_ = 0, minY_ = 0, scaleX_ = 0, scaleY_ = 0, density_ = 2;
  std::uint32_t m_ = 0;
  std::vector<std::int32_t> cells_;
};

}  // namespace geocdt
