#include "terrain/triangle_scan.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

// An edge stepped a row at a time from its first row (ceil of its lower end's y, its ends
// ordered by (y, x)): the same additions in both triangles that share it, so that they
// agree on every row's crossing to the last bit.
struct Edge {
  double x, slope;
};

Edge edge(const Corner& p, const Corner& q) {
  if (!(p.y < q.y)) return {p.x, 0.0};  // horizontal: only its row, where it ends at p
  const double slope = (q.x - p.x) / (q.y - p.y);
  return {p.x + (static_cast<double>(ceilOf(p.y)) - p.y) * slope, slope};
}

// The pixels of rows first..last between two edges, `left` of `right` all the way (their
// crossings with a row, rounded inwards: ceil and floor); both edges are moved on past them.
// The triangle lies inside the raster, so no span leaves it.
struct Rows {
  const double* heights;
  const std::uint8_t* skip;
  std::size_t width;
  double base, gx, gy;  // the plane: z = base + gx x + gy y
};

void scanRows(const Rows& r, Edge& left, Edge& right, std::int64_t first, std::int64_t last,
              ScanResult& out) {
  double best = out.error;
  std::int64_t bestPixel = out.pixel;
  std::uint64_t scanned = 0;
  double xl = left.x, xr = right.x;
  for (std::int64_t j = first; j <= last; ++j, xl += left.slope, xr += right.slope) {
    const std::int64_t i0 = ceilOf(xl), i1 = floorOf(xr);
    if (i1 < i0) continue;
    scanned += static_cast<std::uint64_t>(i1 - i0 + 1);
    const std::size_t rowStart = static_cast<std::size_t>(j) * r.width;
    const double* row = r.heights + rowStart;
    const double rowBase = r.base + r.gy * static_cast<double>(j);
    double x = static_cast<double>(i0);
    for (std::int64_t i = i0; i <= i1; ++i, x += 1) {
      const double e = std::fabs(row[i] - (rowBase + r.gx * x));
      if (e > best && !r.skip[rowStart + static_cast<std::size_t>(i)]) {
        best = e;
        bestPixel = static_cast<std::int64_t>(rowStart) + i;
      }
    }
  }
  left.x = xl;
  right.x = xr;
  out.error = best;
  out.pixel = bestPixel;
  out.scanned += scanned;
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
  const double inverse = 1 / det;
  const double gx = (uz * vy - vz * uy) * inverse, gy = (ux * vz - vx * uz) * inverse;
  const Rows rows{raster.heights(), skip, raster.width(), a.z - gx * a.x - gy * a.y, gx, gy};
  // Rows below b lie between edges ac and ab, rows from b on between ac and bc; b is right
  // of ac when det > 0.
  Edge ac = edge(a, c);
  const std::int64_t first = ceilOf(a.y), middle = ceilOf(b.y), last = floorOf(c.y);
  const bool bRight = det > 0;
  if (middle > first) {
    Edge ab = edge(a, b);
    const std::int64_t end = std::min(middle - 1, last);
    if (bRight) {
      scanRows(rows, ac, ab, first, end, r);
    } else {
      scanRows(rows, ab, ac, first, end, r);
    }
  }
  if (last >= middle) {
    Edge bc = edge(b, c);
    if (bRight) {
      scanRows(rows, ac, bc, middle, last, r);
    } else {
      scanRows(rows, bc, ac, middle, last, r);
    }
  }
  return r;
}

}  // namespace geocdt::terrain
