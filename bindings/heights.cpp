#include "heights.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt::wasm {

std::vector<double> vertexHeights(const Mesh& mesh, const std::vector<std::uint32_t>& inputToVertex,
                                  const std::vector<double>& z, std::size_t pointCount) {
  const std::size_t vertices = mesh.points.size() / 2;
  std::vector<double> out(vertices, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint8_t> fromInput(vertices, 0);
  for (std::size_t i = 0; i < inputToVertex.size(); ++i) {
    const std::uint32_t v = inputToVertex[i];
    fromInput[v] = 1;
    if (std::isnan(out[v])) out[v] = z[i];
  }
  const double* p = mesh.points.data();
  for (std::size_t v = 0; v < vertices; ++v) {
    const std::uint32_t s = mesh.vertexSegments.empty() ? kNoSegment : mesh.vertexSegments[v];
    if (fromInput[v] || s == kNoSegment || pointCount + s + 1 >= inputToVertex.size()) continue;
    const std::size_t i = pointCount + s;
    const std::uint32_t a = inputToVertex[i], b = inputToVertex[i + 1];
    const double dx = p[2 * b] - p[2 * a], dy = p[2 * b + 1] - p[2 * a + 1];
    const double length2 = dx * dx + dy * dy;
    double t = length2 > 0
                   ? ((p[2 * v] - p[2 * a]) * dx + (p[2 * v + 1] - p[2 * a + 1]) * dy) / length2
                   : 0;
    t = std::min(1.0, std::max(0.0, t));
    out[v] = z[i] + t * (z[i + 1] - z[i]);
  }
  return out;
}

}  // namespace geocdt::wasm
