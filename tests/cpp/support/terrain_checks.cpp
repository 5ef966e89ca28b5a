#include "terrain_checks.h"

#include <algorithm>
#include <cmath>

#include "geocdt/predicates.h"

namespace geocdt::testing {

namespace {

bool cellValid(const std::vector<std::uint8_t>& valid, std::uint32_t width, std::uint32_t height,
               std::int64_t i, std::int64_t j) {
  if (i < 0 || j < 0 || i + 1 >= width || j + 1 >= height) return false;
  if (valid.empty()) return true;
  const auto at = [&](std::int64_t x, std::int64_t y) {
    return valid[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)] != 0;
  };
  return at(i, j) && at(i + 1, j) && at(i, j + 1) && at(i + 1, j + 1);
}

}  // namespace

RasterErrors rasterErrors(const Mesh& mesh, const std::vector<double>& heights, std::uint32_t width,
                          std::uint32_t height, const std::vector<std::uint8_t>& valid,
                          const std::vector<std::uint8_t>& exempt) {
  RasterErrors r;
  std::vector<std::uint8_t> covered(heights.size(), 0);
  const std::vector<double>& p = mesh.points;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const std::uint32_t v[3] = {mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]};
    double x[3], y[3];
    long double z[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = p[2 * v[k]];
      y[k] = p[2 * v[k] + 1];
      z[k] = mesh.values[v[k]];
    }
    // (In long double: a triangle ulps wide at a cell's corner, where a breakline's rounded
    // crossings meet the boundary, has a double centroid that rounds into the next cell.)
    const long double cx = (static_cast<long double>(x[0]) + x[1] + x[2]) / 3,
                      cy = (static_cast<long double>(y[0]) + y[1] + y[2]) / 3;
    if (!valid.empty() &&
        !cellValid(valid, width, height, static_cast<std::int64_t>(std::floor(cx)),
                   static_cast<std::int64_t>(std::floor(cy))) &&
        r.problem.empty())
      r.problem = "triangle " + std::to_string(t / 3) + " lies outside the cells with data";
    const auto lo = [](double a, double b, double c) { return std::min({a, b, c}); };
    const auto hi = [](double a, double b, double c) { return std::max({a, b, c}); };
    const std::int64_t i0 = std::max<std::int64_t>(0, std::ceil(lo(x[0], x[1], x[2])));
    const std::int64_t i1 = std::min<std::int64_t>(width - 1, std::floor(hi(x[0], x[1], x[2])));
    const std::int64_t j0 = std::max<std::int64_t>(0, std::ceil(lo(y[0], y[1], y[2])));
    const std::int64_t j1 = std::min<std::int64_t>(height - 1, std::floor(hi(y[0], y[1], y[2])));
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) {
        const double px = static_cast<double>(i), py = static_cast<double>(j);
        bool in = true;
        int onEdge = -1;  // the edge k -> k + 1 the pixel lies on, exactly
        for (int k = 0; k < 3 && in; ++k) {
          const Sign side = orient2d(x[k], y[k], x[(k + 1) % 3], y[(k + 1) % 3], px, py);
          in = side != Sign::Negative;
          if (side == Sign::Zero) onEdge = k;
        }
        if (!in) continue;
        long double value;
        if (onEdge >= 0) {
          // On an edge the surface is the edge's own interpolation; barycentric weights would
          // have no digits there in a sliver (a crossing ulps off a breakline).
          const int a = onEdge, b = (onEdge + 1) % 3;
          const long double ex = static_cast<long double>(x[b]) - x[a];
          const long double ey = static_cast<long double>(y[b]) - y[a];
          const long double f = ((px - x[a]) * ex + (py - y[a]) * ey) / (ex * ex + ey * ey);
          value = (1 - f) * z[a] + f * z[b];
        } else {
          // Barycentric weights as sub-triangle areas, in long double.
          long double w[3], sum = 0, weighted = 0;
          for (int k = 0; k < 3; ++k) {
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            w[k] = (static_cast<long double>(x[b]) - x[a]) * (py - y[a]) -
                   (static_cast<long double>(y[b]) - y[a]) * (px - x[a]);
            sum += w[k];
          }
          for (int k = 0; k < 3; ++k) weighted += w[k] * z[k];
          value = weighted / sum;
        }
        const std::size_t pixel = static_cast<std::size_t>(j) * width + static_cast<std::size_t>(i);
        const double e = static_cast<double>(std::fabs(value - heights[pixel]));
        if (exempt.empty() || !exempt[pixel]) r.maxError = std::max(r.maxError, e);
        covered[pixel] = 1;
      }
  }
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i) {
      const std::size_t pixel = static_cast<std::size_t>(j) * width + i;
      // A pixel with data must be covered when a cell with data has it as a corner.
      bool inArea = false;
      for (int dj = -1; dj <= 0 && !inArea; ++dj)
        for (int di = -1; di <= 0 && !inArea; ++di)
          inArea = cellValid(valid, width, height, std::int64_t{i} + di, std::int64_t{j} + dj);
      if (!inArea) continue;
      ++r.pixels;
      if (covered[pixel]) continue;
      ++r.uncovered;
      if (r.problem.empty())
        r.problem =
            "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") is in no triangle";
    }
  return r;
}

double distanceToSegment(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, squared = dx * dx + dy * dy;
  const double t =
      squared > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / squared, 0.0, 1.0) : 0.0;
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

std::vector<std::uint8_t> underGivenHeights(const Mesh& mesh, const std::vector<double>& heights,
                                            std::uint32_t width, std::uint32_t height,
                                            const std::vector<std::vector<double>>& lines) {
  std::vector<std::uint8_t> exempt(heights.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size() / 2; ++v) {
    const double x = mesh.points[2 * v], y = mesh.points[2 * v + 1];
    if (x != std::floor(x) || y != std::floor(y) || x < 0 || y < 0 || x >= width || y >= height)
      continue;
    const std::size_t pixel = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
    bool onLine = false;
    for (const auto& l : lines)
      for (std::size_t k = 0; k + 3 < l.size(); k += 2)
        onLine |= distanceToSegment(x, y, l[k], l[k + 1], l[k + 2], l[k + 3]) < 1e-9;
    if (onLine && mesh.values[v] != heights[pixel]) exempt[pixel] = 1;
  }
  return exempt;
}

}  // namespace geocdt::testing
