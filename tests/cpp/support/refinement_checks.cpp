#include "refinement_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "invariants.h"

namespace geocdt::testing {

namespace {

constexpr double kPi = 3.14159265358979323846;

void corners(const Mesh& m, std::size_t t, double (&x)[3], double (&y)[3]) {
  for (int k = 0; k < 3; ++k) {
    x[k] = m.points[2 * m.triangles[3 * t + k]];
    y[k] = m.points[2 * m.triangles[3 * t + k] + 1];
  }
}

}  // namespace

double smallestAngle(const Mesh& m, std::size_t t) {
  double x[3], y[3];
  corners(m, t, x, y);
  // Differences scaled by a power of two to magnitude ~1: subnormal ones would underflow.
  double size = 0;
  for (int k = 1; k < 3; ++k)
    size = std::max({size, std::fabs(x[k] - x[0]), std::fabs(y[k] - y[0])});
  const int e = size > 0 ? std::ilogb(size) : 0;
  double smallest = 180;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double ux = std::ldexp(x[i] - x[k], -e), uy = std::ldexp(y[i] - y[k], -e);
    const double vx = std::ldexp(x[j] - x[k], -e), vy = std::ldexp(y[j] - y[k], -e);
    const double angle = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
    smallest = std::min(smallest, angle * 180 / kPi);
  }
  return smallest;
}

double triangleArea(const Mesh& m, std::size_t t) {
  double x[3], y[3];
  corners(m, t, x, y);
  return 0.5 * std::fabs((x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]));
}

std::size_t countBadTriangles(const Mesh& m, double minAngle, double maxArea, bool insideOnly) {
  std::size_t bad = 0;
  for (std::size_t t = 0; t < m.triangles.size() / 3; ++t) {
    if (insideOnly && !m.inside[t]) continue;
    const bool angle = smallestAngle(m, t) < minAngle * (1 - 1e-9);
    const bool area = maxArea > 0 && triangleArea(m, t) > maxArea * (1 + 1e-9);
    bad += angle || area;
  }
  return bad;
}

std::string checkSteinerRecords(const Mesh& m, std::size_t firstSteiner) {
  const std::size_t n = m.steiner.size(), vertices = m.points.size() / 2;
  if (m.steinerParents.size() != 3 * n || m.steinerWeights.size() != 3 * n)
    return "Steiner records of the wrong length";
  std::vector<std::uint8_t> seen(vertices, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::ostringstream where;
    where << "Steiner vertex " << i << " (" << m.steiner[i] << "): ";
    const std::uint32_t v = m.steiner[i];
    if (v < firstSteiner || v >= vertices || seen[v]) return where.str() + "not a new vertex";
    seen[v] = 1;
    double x = 0, y = 0, sum = 0, spread = 0;
    const double magnitude = std::max(std::fabs(m.points[2 * v]), std::fabs(m.points[2 * v + 1]));
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = m.steinerParents[3 * i + k];
      const double w = m.steinerWeights[3 * i + k];
      if (p == kNoVertex) {
        if (k != 2 || w != 0) return where.str() + "a missing parent with a weight";
        continue;
      }
      if (p >= v) return where.str() + "a parent added after it";
      x += w * m.points[2 * p];
      y += w * m.points[2 * p + 1];
      sum += w;
      spread = std::max({spread, std::fabs(m.points[2 * p] - m.points[2 * v]),
                         std::fabs(m.points[2 * p + 1] - m.points[2 * v + 1])});
    }
    if (std::fabs(sum - 1) > 1e-9) return where.str() + "weights do not sum to 1";
    if (m.steinerParents[3 * i + 2] == kNoVertex) {
      // On an edge: the weights project it on the edge. (It lies within the chains' bound of
      // its input segment, which checkConstraints checks, not necessarily near the edge's
      // line: with coordinates of very different magnitudes the bound can exceed the edge.)
      const std::uint32_t a = m.steinerParents[3 * i], b = m.steinerParents[3 * i + 1];
      const double ax = m.points[2 * a], ay = m.points[2 * a + 1];
      double ex = m.points[2 * b] - ax, ey = m.points[2 * b + 1] - ay;
      double px = m.points[2 * v] - ax, py = m.points[2 * v + 1] - ay;
      const int e = std::ilogb(
          std::max({std::fabs(ex), std::fabs(ey), std::fabs(px), std::fabs(py), 0x1p-1074}));
      ex = std::ldexp(ex, -e), ey = std::ldexp(ey, -e), px = std::ldexp(px, -e);
      py = std::ldexp(py, -e);
      const double w = std::clamp((px * ex + py * ey) / (ex * ex + ey * ey), 0.0, 1.0);
      if (std::fabs(w - m.steinerWeights[3 * i + 1]) > 1e-9)
        return where.str() + "weights are not its projection on its edge";
      continue;
    }
    const double error =
        std::max(std::fabs(x - m.points[2 * v]), std::fabs(y - m.points[2 * v + 1]));
    if (error > 1e-9 * spread + 0x1p-48 * magnitude) {
      where << "weights put it " << error << " away (spread " << spread << ")";
      return where.str();
    }
  }
  return "";
}

std::string checkRefined(const Mesh& m, const std::vector<double>& inputXY,
                         const Polylines& polylines, const std::vector<std::uint32_t>& ids,
                         double minAngle, double maxArea, bool insideOnly, std::size_t allowed) {
  std::vector<double> allXY(inputXY);
  for (const auto& line : polylines) allXY.insert(allXY.end(), line.begin(), line.end());
  CheckOptions c;
  c.inputXY = &allXY;
  c.inputToVertex = &ids;
  std::string error = checkTriangulation(m, c);
  if (!error.empty()) return "triangulation: " + error;
  const std::vector<std::uint32_t> lineIds(ids.begin() + inputXY.size() / 2, ids.end());
  error = checkConstraints(m, polylines, lineIds);
  if (!error.empty()) return "constraints: " + error;
  // Every constrained edge keeps a source.
  for (std::size_t i = 0; i + 1 < m.sourceOffsets.size(); ++i)
    if (m.sourceOffsets[i + 1] <= m.sourceOffsets[i]) return "a constrained edge with no source";
  std::uint32_t firstSteiner = 0;
  for (const std::uint32_t v : ids) firstSteiner = std::max(firstSteiner, v + 1);
  error = checkSteinerRecords(m, firstSteiner);
  if (!error.empty()) return error;
  const std::size_t bad = countBadTriangles(m, minAngle, maxArea, insideOnly);
  if (bad > allowed) {
    std::ostringstream out;
    out << bad << " triangles miss the bounds, " << allowed << " allowed";
    return out.str();
  }
  return "";
}

}  // namespace geocdt::testing
