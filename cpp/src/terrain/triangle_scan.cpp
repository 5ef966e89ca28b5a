#include "terrain/triangle_scan.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace geocdt::terrain {

namespace {

bool below(const Corner& p, const Corner& q) { return p.y < q.y || (p.y == q.y && p.x < q.x); }

// ceil and floor of x to an integer (|x| < 2^62): a conversion and a compare, where the
// library's calls cost more than a short row of pixels.
std::int64_t ceilToInt(double x) {
  const auto i = static_cast<std::int64_t>(x);
  return i + (x > static_cast<double>(i));
}
std::int64_t floorToInt(double x) {
  const auto i = static_cast<std::int64_t>(x);
  return i - (x < static_cast<double>(i));
}

// An edge from its end p lower in (y, x) order: its x at row y is p.x + (y - p.y) * slope, the
// same arithmetic in both triangles that share it.
struct Edge {
  double px, py, slope;
  double at(double y) const { return px + (y - py) * slope; }
};

Edge edge(const Corner& p, const Corner& q) {
  return {p.x, p.y, p.y < q.y ? (q.x - p.x) / (q.y - p.y) : 0.0};
}

}  // namespace

ScanResult scanTriangle(Corner a, Corner b, Corner c, const RasterSampler& raster,
                        const std::uint8_t* skip) {
  // Sorted by (y, x): every edge then runs from its lower end, as the neighbour sees it too.
  if (below(b, a)) std::swap(a, b);
  if (below(c, b)) std::swap(b, c);
  if (below(b, a)) std::swap(a, b);
  ScanResult r;
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double det = ux * vy - vx * uy;
  if (!(det != 0)) return r;
  // The plane z = a.z + gx (x - a.x) + gy (y - a.y).
  const double gx = (uz * vy - vz * uy) / det, gy = (ux * vz - vx * uz) / det;
  const std::int64_t lastRow = static_cast<std::int64_t>(raster.height()) - 1;
  const std::int64_t lastColumn = static_cast<std::int64_t>(raster.width()) - 1;
  const std::int64_t first = std::max<std::int64_t>(0, ceilToInt(a.y));
  const std::int64_t end = std::min<std::int64_t>(lastRow, floorToInt(c.y));
  const Edge across = edge(a, c), lower = edge(a, b), upper = edge(b, c);
  const double* heights = raster.heights();
  const std::size_t width = raster.width();
  double best = 0;
  std::int64_t bestPixel = -1;
  std::uint64_t scanned = 0;
  for (std::int64_t j = first; j <= end; ++j) {
    const auto y = static_cast<double>(j);
    const double x0 = across.at(y);
    const double x1 = y < b.y ? lower.at(y) : b.y == c.y ? b.x : upper.at(y);
    const std::int64_t i0 = std::max<std::int64_t>(0, ceilToInt(std::min(x0, x1)));
    const std::int64_t i1 = std::min<std::int64_t>(lastColumn, floorToInt(std::max(x0, x1)));
    if (i1 < i0) continue;
    scanned += static_cast<std::uint64_t>(i1 - i0 + 1);
    const std::size_t rowStart = static_cast<std::size_t>(j) * width;
    const double* row = heights + rowStart;
    // z at column i of this row: base + gx * i.
    const double base = a.z + gy * (y - a.y) - gx * a.x;
    double column = static_cast<double>(i0);
    for (std::int64_t i = i0; i <= i1; ++i, column += 1) {
      const double e = std::fabs(row[i] - (base + gx * column));
      if (e > best && !skip[rowStart + static_cast<std::size_t>(i)]) {
        best = e;
        bestPixel = static_cast<std::int64_t>(rowStart) + i;
      }
    }
  }
  r.error = best;
  r.pixel = bestPixel;
  r.scanned = scanned;
  return r;
}

}  // namespace geocdt::terrain
