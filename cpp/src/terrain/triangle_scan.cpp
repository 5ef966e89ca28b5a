#include "terrain/triangle_scan.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "terrain/height_blocks.h"

namespace geocdt::terrain {

namespace {

bool below(const Corner& p, const Corner& q) { return p.y < q.y || (p.y == q.y && p.x < q.x); }

// ceil and floor of x >= -1 (a pixel position, give or take rounding) as integers: a
// conversion and a compare, where std::ceil is a library call on x86-64's baseline.
std::int32_t ceilOf(double x) {
  const auto i = static_cast<std::int32_t>(x);
  return i + (x > static_cast<double>(i));
}
std::int32_t floorOf(double x) {
  const auto i = static_cast<std::int32_t>(x);
  return i - (x < static_cast<double>(i));
}

// Where an edge crosses row y: p.x + (y - p.y) * slope, from its end p lower in (y, x) order.
struct Edge {
  double px, py, slope;
  double at(double y) const { return px + (y - py) * slope; }
};

Edge edge(const Corner& p, const Corner& q) {
  return {p.x, p.y, p.y < q.y ? (q.x - p.x) / (q.y - p.y) : 0.0};
}

// The pixels of rows first..last between two edges, `left` of `right` all the way (their
// crossings with a row, widened by kEdgeReach and rounded inwards). The triangle lies inside the
// raster, but a widened span may reach past its first or last column: clamped.
struct Rows {
  const double* heights;
  const std::uint8_t* skip;
  std::size_t width;
  Plane plane;
};

// Row y's first and last column between left and right, as every scan takes them (empty when
// i1 < i0).
void spanOf(const Edge& left, const Edge& right, double y, std::int64_t lastColumn,
            std::int64_t& i0, std::int64_t& i1) {
  i0 = std::max<std::int64_t>(0, ceilOf(left.at(y) - kEdgeReach));
  i1 = std::min(lastColumn, std::int64_t{floorOf(right.at(y) + kEdgeReach)});
}

void scanRows(const Rows& r, const Edge& left, const Edge& right, std::int64_t first,
              std::int64_t last, ScanResult& out) {
  double best = out.error;
  std::int64_t bestPixel = out.pixel;
  std::uint64_t scanned = 0;
  const auto lastColumn = static_cast<std::int64_t>(r.width) - 1;
  for (std::int64_t j = first; j <= last; ++j) {
    const auto y = static_cast<double>(j);
    std::int64_t i0, i1;
    spanOf(left, right, y, lastColumn, i0, i1);
    if (i1 < i0) continue;
    scanned += static_cast<std::uint64_t>(i1 - i0 + 1);
    const std::size_t rowStart = static_cast<std::size_t>(j) * r.width;
    const double* row = r.heights + rowStart;
    const double rowBase = r.plane.base + r.plane.gy * y;
    double x = static_cast<double>(i0);
    for (std::int64_t i = i0; i <= i1; ++i, x += 1) {
      const double e = std::fabs(row[i] - (rowBase + r.plane.gx * x));
      if (e > best && !r.skip[rowStart + static_cast<std::size_t>(i)]) {
        best = e;
        bestPixel = static_cast<std::int64_t>(rowStart) + i;
      }
    }
  }
  out.error = best;
  out.pixel = bestPixel;
  out.scanned += scanned;
}

// A triangle's rows first..last: rows before middle lie between edges lowLeft and lowRight,
// the others between highLeft and highRight.
struct RowSpans {
  Edge lowLeft, lowRight, highLeft, highRight;
  std::int64_t first, middle, last, lastColumn;
  // Row j's first and last column, as scanRows finds them (empty when i1 < i0).
  void of(std::int64_t j, std::int64_t& i0, std::int64_t& i1) const {
    spanOf(j < middle ? lowLeft : highLeft, j < middle ? lowRight : highRight,
           static_cast<double>(j), lastColumn, i0, i1);
  }
};

// The pixels of rows.first..rows.last, block by block: first the block whose heights may lie
// farthest from the plane, then the others in order, each passed over when its bound is below
// the largest error found. Ties go to the first pixel in row order, as in scanRows.
void scanByBlocks(const Rows& r, const RowSpans& rows, const HeightBlocks& blocks,
                  ScanScratch& scratch, ScanResult& out) {
  constexpr std::uint32_t kShift = HeightBlocks::kShift;
  constexpr std::int64_t kSide = HeightBlocks::kSide;
  const std::int64_t first = rows.first, last = rows.last;
  if (last < first) return;
  const Plane& p = r.plane;
  const double planeSize = std::fabs(p.base) + std::fabs(p.gx) * static_cast<double>(r.width) +
                           std::fabs(p.gy) * static_cast<double>(last + 1);
  // Each block's bound: its heights against the plane's lowest and highest over the columns
  // the block row's rows reach. Those columns come from the block row's first and last rows
  // and the rows beside the middle corner (where the sides bend), widened by one against
  // rounding.
  std::vector<ScanScratch::Block>& todo = scratch.blocks;
  std::vector<std::int32_t>& spans = scratch.spans;
  todo.clear();
  std::size_t largest = 0;
  const std::int64_t middle = rows.middle;
  for (std::int64_t row = first >> kShift; row <= last >> kShift; ++row) {
    const std::int64_t r0 = std::max(first, row << kShift);
    const std::int64_t r1 = std::min(last, (row << kShift) + kSide - 1);
    std::int64_t lo = rows.lastColumn + 1, hi = -1;
    for (const std::int64_t j : {r0, r1, middle - 1, middle}) {
      if (j < r0 || j > r1) continue;
      std::int64_t i0, i1;
      rows.of(j, i0, i1);
      lo = std::min(lo, i0);
      hi = std::max(hi, i1);
    }
    lo = std::max<std::int64_t>(0, lo - 1);
    hi = std::min(rows.lastColumn, hi + 1);
    if (hi < lo) continue;
    const double y0 = p.gy * static_cast<double>(r0), y1 = p.gy * static_cast<double>(r1);
    const double yLow = p.base + std::min(y0, y1), yHigh = p.base + std::max(y0, y1);
    for (std::int64_t column = lo >> kShift; column <= hi >> kShift; ++column) {
      const float* range =
          blocks.range(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row));
      const double low = range[0], high = range[1];
      if (!(low <= high)) continue;  // no height but NaN
      const double x0 = p.gx * static_cast<double>(std::max(lo, column << kShift));
      const double x1 = p.gx * static_cast<double>(std::min(hi, (column << kShift) + kSide - 1));
      const double planeLow = yLow + std::min(x0, x1), planeHigh = yHigh + std::max(x0, x1);
      // The scan evaluates the plane in another order: a margin far above its rounding.
      const double margin = 0x1p-40 * (planeSize + std::max(std::fabs(low), std::fabs(high)));
      const double bound = std::max(high - planeLow, planeHigh - low) + margin;
      if (!todo.empty() && bound > todo[largest].bound) largest = todo.size();
      todo.push_back({bound, static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row)});
    }
  }
  // Each block row's spans, found when one of its blocks is first scanned.
  const std::int64_t firstBlockRow = first >> kShift;
  std::vector<std::uint8_t>& found = scratch.found;
  found.assign(static_cast<std::size_t>((last >> kShift) - firstBlockRow + 1), 0);
  spans.resize(2 * found.size() * kSide);
  double best = out.error;
  std::int64_t bestPixel = out.pixel;
  std::uint64_t scanned = 0;
  if (todo.empty()) return;
  std::swap(todo[0], todo[largest]);
  for (const ScanScratch::Block& block : todo) {
    if (block.bound < best) continue;  // (a tie may hold an earlier pixel: scanned)
    const std::int64_t row = block.row, c0 = std::int64_t{block.column} << kShift;
    const std::int64_t r0 = std::max(first, row << kShift);
    const std::int64_t r1 = std::min(last, (row << kShift) + kSide - 1);
    std::int32_t* span = &spans[static_cast<std::size_t>(2 * ((row - firstBlockRow) << kShift))];
    if (!found[static_cast<std::size_t>(row - firstBlockRow)]) {
      found[static_cast<std::size_t>(row - firstBlockRow)] = 1;
      for (std::int64_t j = r0; j <= r1; ++j) {
        std::int64_t i0, i1;
        rows.of(j, i0, i1);
        span[2 * (j - (row << kShift))] = static_cast<std::int32_t>(i0);
        span[2 * (j - (row << kShift)) + 1] = static_cast<std::int32_t>(i1);
      }
    }
    for (std::int64_t j = r0; j <= r1; ++j) {
      const std::int64_t k = 2 * (j - (row << kShift));
      const std::int64_t i0 = std::max<std::int64_t>(span[k], c0);
      const std::int64_t i1 = std::min<std::int64_t>(span[k + 1], c0 + kSide - 1);
      if (i1 < i0) continue;
      scanned += static_cast<std::uint64_t>(i1 - i0 + 1);
      const std::size_t rowStart = static_cast<std::size_t>(j) * r.width;
      const double* line = r.heights + rowStart;
      const double rowBase = p.base + p.gy * static_cast<double>(j);
      double x = static_cast<double>(i0);
      for (std::int64_t i = i0; i <= i1; ++i, x += 1) {
        const double e = std::fabs(line[i] - (rowBase + p.gx * x));
        const auto pixel = static_cast<std::int64_t>(rowStart) + i;
        if (e >= best && (e > best || pixel < bestPixel) && !r.skip[pixel]) {
          best = e;
          bestPixel = pixel;
        }
      }
    }
  }
  out.error = best;
  out.pixel = bestPixel;
  out.scanned += scanned;
}

// Whether p is a pixel of the raster (whole coordinates inside it), and which.
bool pixelAt(const Corner& p, const RasterSampler& raster, std::size_t& pixel) {
  // Below 2^26, so that det is exact.
  if (!(p.x >= 0 && p.y >= 0 && p.x < raster.width() && p.y < raster.height() && p.x < 0x1p26 &&
        p.y < 0x1p26))
    return false;
  const auto i = static_cast<std::uint32_t>(p.x), j = static_cast<std::uint32_t>(p.y);
  if (static_cast<double>(i) != p.x || static_cast<double>(j) != p.y) return false;
  pixel = raster.pixel(i, j);
  return true;
}

// Whether abc is a lattice triangle of area 1/2 or 1 (|det| 1 or 2, exact for pixel
// positions) whose corners are skipped: it then holds no other pixel, or exactly one more, at
// the middle of the edge whose ends differ by even numbers (Pick's theorem), and its rows need
// not be walked. Most triangles are such at fine error bounds.
bool smallLatticeTriangle(const Corner& a, const Corner& b, const Corner& c, double det,
                          const RasterSampler& raster, const std::uint8_t* skip) {
  const double size = std::fabs(det);
  if (size != 1 && size != 2) return false;
  std::size_t pa, pb, pc;
  return pixelAt(a, raster, pa) && pixelAt(b, raster, pb) && pixelAt(c, raster, pc) && skip[pa] &&
         skip[pb] && skip[pc];
}

// The pixel in the middle of the lattice edge pq whose ends differ by even numbers, if pq is it.
bool middlePixel(const Corner& p, const Corner& q, double& x, double& y) {
  const auto dx = static_cast<std::int64_t>(q.x - p.x), dy = static_cast<std::int64_t>(q.y - p.y);
  if ((dx & 1) != 0 || (dy & 1) != 0) return false;
  x = p.x + static_cast<double>(dx / 2);
  y = p.y + static_cast<double>(dy / 2);
  return true;
}

// Sorted by (y, x): every edge then runs from its lower end, as the neighbour sees it too.
void sortCorners(Corner& a, Corner& b, Corner& c) {
  if (below(b, a)) std::swap(a, b);
  if (below(c, b)) std::swap(b, c);
  if (below(b, a)) std::swap(a, b);
}

double determinant(const Corner& a, const Corner& b, const Corner& c) {
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// The plane z = a.z + gx (x - a.x) + gy (y - a.y) of sorted corners whose determinant is det.
Plane sortedPlane(const Corner& a, const Corner& b, const Corner& c, double det) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double inverse = 1 / det;
  const double gx = (uz * vy - vz * uy) * inverse, gy = (ux * vz - vx * uz) * inverse;
  return {a.z - gx * a.x - gy * a.y, gx, gy};
}

}  // namespace

bool planeOf(Corner a, Corner b, Corner c, Plane& plane) {
  sortCorners(a, b, c);
  const double det = determinant(a, b, c);
  if (!(det != 0)) return false;
  plane = sortedPlane(a, b, c, det);
  return true;
}

ScanResult scanTriangle(Corner a, Corner b, Corner c, const RasterSampler& raster,
                        const std::uint8_t* skip, const HeightBlocks* blocks,
                        ScanScratch* scratch) {
  sortCorners(a, b, c);
  ScanResult r;
  const double det = determinant(a, b, c);
  if (!(det != 0)) return r;
  const bool small = smallLatticeTriangle(a, b, c, det, raster, skip);
  if (small && std::fabs(det) == 1) return r;
  const Rows rows{raster.heights(), skip, raster.width(), sortedPlane(a, b, c, det)};
  if (small) {
    // One pixel besides the corners, measured as scanRows would.
    double x = 0, y = 0;
    if (!middlePixel(a, b, x, y) && !middlePixel(b, c, x, y)) middlePixel(a, c, x, y);
    const std::size_t pixel =
        raster.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
    const double e = std::fabs(rows.heights[pixel] - rows.plane.at(x, y));
    r.scanned = 1;
    if (e > 0 && !skip[pixel]) {
      r.error = e;
      r.pixel = static_cast<std::int64_t>(pixel);
    }
    return r;
  }
  // Rows below b lie between edges ac and ab, rows from b on between ac and bc; b is right
  // of ac when det > 0. Rows within kEdgeReach of a corner's row count (rounding aside, a corner's
  // row is an integer only when it is a pixel's).
  const Edge ac = edge(a, c);
  const auto lastRow = static_cast<std::int64_t>(raster.height()) - 1;
  const std::int64_t first = std::max<std::int64_t>(0, ceilOf(a.y - kEdgeReach));
  const std::int64_t middle = ceilOf(b.y);
  const std::int64_t last = std::min(lastRow, std::int64_t{floorOf(c.y + kEdgeReach)});
  const bool bRight = det > 0;
  if (blocks && scratch && std::fabs(det) >= 2 * scratch->fromArea) {
    const Edge ab = edge(a, b);
    const Edge bc = b.y < c.y ? edge(b, c) : Edge{b.x, b.y, 0.0};
    const RowSpans spans{bRight ? ac : ab,
                         bRight ? ab : ac,
                         bRight ? ac : bc,
                         bRight ? bc : ac,
                         first,
                         middle,
                         last,
                         static_cast<std::int64_t>(raster.width()) - 1};
    scanByBlocks(rows, spans, *blocks, *scratch, r);
    return r;
  }
  if (middle > first) {
    const Edge ab = edge(a, b);
    const std::int64_t end = std::min(middle - 1, last);
    scanRows(rows, bRight ? ac : ab, bRight ? ab : ac, first, end, r);
  }
  if (last >= middle) {
    // A horizontal bc (b.y == c.y) is only row c.y, whose span ends at b: a zero slope does.
    const Edge bc = b.y < c.y ? edge(b, c) : Edge{b.x, b.y, 0.0};
    scanRows(rows, bRight ? ac : bc, bRight ? bc : ac, std::max(middle, first), last, r);
  }
  return r;
}

}  // namespace geocdt::terrain
