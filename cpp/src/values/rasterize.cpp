// Rasters of the values: the linear surface scan-converted triangle by triangle.
#include "values/rasterize.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt {

void rasterizeLinear(const Delaunay& d, const std::vector<double>& values, std::uint32_t k,
                     const RasterGrid& grid, float* out) {
  const Topology& topo = d.topo;
  const double* p = d.xy.data();
  const std::size_t width = grid.width, height = grid.height;
  const double dx = (grid.maxX - grid.minX) / static_cast<double>(width);
  const double dy = (grid.maxY - grid.minY) / static_cast<double>(height);
  // Pixel centres within this fraction of a pixel outside a triangle still take its plane, so
  // that rounding leaves no gap along shared edges (a pixel on one is written twice, with
  // values equal up to rounding).
  constexpr double kSlack = 1e-9;
  std::vector<double> gradient(3 * k);
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (topo.isGhost(t)) continue;
    const std::uint32_t* v = &topo.tri[3 * t];
    // Pixel coordinates (column and row as continuous numbers; centres at + 0.5).
    double px[3], py[3];
    for (int c = 0; c < 3; ++c) {
      px[c] = (p[2 * v[c]] - grid.minX) / dx;
      py[c] = (grid.maxY - p[2 * v[c] + 1]) / dy;
    }
    const double rowLo = std::min({py[0], py[1], py[2]});
    const double rowHi = std::max({py[0], py[1], py[2]});
    const double first = std::max(0.0, std::ceil(rowLo - 0.5 - kSlack));
    const double last = std::min(static_cast<double>(height) - 1, std::floor(rowHi - 0.5 + kSlack));
    if (first > last) continue;
    // The plane of each value in pixel coordinates: f = f0 + gx (X - px0) + gy (Y - py0).
    const double ux = px[1] - px[0], uy = py[1] - py[0], wx = px[2] - px[0], wy = py[2] - py[0];
    const double det = ux * wy - uy * wx;
    if (det == 0) continue;
    for (std::uint32_t j = 0; j < k; ++j) {
      const double f0 = values[v[0] * k + j];
      const double fu = values[v[1] * k + j] - f0, fw = values[v[2] * k + j] - f0;
      gradient[3 * j] = f0;
      gradient[3 * j + 1] = (fu * wy - fw * uy) / det;
      gradient[3 * j + 2] = (fw * ux - fu * wx) / det;
    }
    for (double r = first; r <= last; ++r) {
      const double yc = r + 0.5;
      // The span of the row inside the triangle: intersect the three edges' lines.
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int c = 0; c < 3; ++c) {
        const int n = (c + 1) % 3;
        const double y0 = py[c], y1 = py[n];
        if ((yc < std::min(y0, y1) - kSlack) || (yc > std::max(y0, y1) + kSlack)) continue;
        if (y0 == y1) {
          lo = std::min({lo, px[c], px[n]});
          hi = std::max({hi, px[c], px[n]});
          continue;
        }
        const double s = std::min(1.0, std::max(0.0, (yc - y0) / (y1 - y0)));
        const double xe = px[c] + s * (px[n] - px[c]);
        lo = std::min(lo, xe);
        hi = std::max(hi, xe);
      }
      const double colFirst = std::max(0.0, std::ceil(lo - 0.5 - kSlack));
      const double colLast =
          std::min(static_cast<double>(width) - 1, std::floor(hi - 0.5 + kSlack));
      const std::size_t row = static_cast<std::size_t>(r) * width;
      for (double c = colFirst; c <= colLast; ++c) {
        float* o = out + (row + static_cast<std::size_t>(c)) * k;
        const double ex = c + 0.5 - px[0], ey = yc - py[0];
        for (std::uint32_t j = 0; j < k; ++j)
          o[j] = static_cast<float>(gradient[3 * j] + gradient[3 * j + 1] * ex +
                                    gradient[3 * j + 2] * ey);
      }
    }
  }
}

}  // namespace geocdt
