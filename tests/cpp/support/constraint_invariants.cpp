#include "constraint_invariants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace geocdt::testing {

namespace {

struct Segment {
  double ax, ay, bx, by;
};

// In long double: its exponent range keeps squares of subnormal lengths from underflowing.
double distanceToSegment(const Segment& s, double x, double y) {
  const long double dx = (long double)s.bx - s.ax, dy = (long double)s.by - s.ay;
  const long double len2 = dx * dx + dy * dy;
  long double t =
      len2 > 0 ? (((long double)x - s.ax) * dx + ((long double)y - s.ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0L, 1.0L);
  const long double ex = s.ax + t * dx - x, ey = s.ay + t * dy - y;
  return static_cast<double>(std::sqrt(ex * ex + ey * ey));
}

// Rounding of crossing points: a few ulps of the coordinates plus a tiny part of the length.
// Among subnormals an ulp is the smallest double, however small the coordinates.
double tolerance(const Segment& s) {
  const double magnitude =
      std::max({std::fabs(s.ax), std::fabs(s.ay), std::fabs(s.bx), std::fabs(s.by)});
  const double ulp = std::max(magnitude * std::numeric_limits<double>::epsilon(),
                              std::numeric_limits<double>::denorm_min());
  return 1e-9 * std::hypot(s.bx - s.ax, s.by - s.ay) + 64 * ulp;
}

// Segments bucketed on a uniform grid by their bounding boxes.
class SegmentGrid {
 public:
  explicit SegmentGrid(const std::vector<Segment>& segments) : segments_(segments) {
    minX_ = minY_ = std::numeric_limits<double>::infinity();
    double maxX = -minX_, maxY = -minY_;
    for (const Segment& s : segments) {
      minX_ = std::min({minX_, s.ax, s.bx});
      minY_ = std::min({minY_, s.ay, s.by});
      maxX = std::max({maxX, s.ax, s.bx});
      maxY = std::max({maxY, s.ay, s.by});
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(double(segments.size()))));
    cellX_ = std::max((maxX - minX_) / double(side_), 1e-300);
    cellY_ = std::max((maxY - minY_) / double(side_), 1e-300);
    cells_.resize(side_ * side_);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Segment& s = segments[i];
      const double t = tolerance(s);
      const std::size_t x0 = column(std::min(s.ax, s.bx) - t),
                        x1 = column(std::max(s.ax, s.bx) + t);
      const std::size_t y0 = row(std::min(s.ay, s.by) - t), y1 = row(std::max(s.ay, s.by) + t);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) cells_[y * side_ + x].push_back(i);
    }
  }
  // Index of a segment that both points lie on, or -1.
  long find(double x0, double y0, double x1, double y1) const {
    const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    for (const std::size_t i : cells_[row(my) * side_ + column(mx)]) {
      const Segment& s = segments_[i];
      const double t = tolerance(s);
      if (distanceToSegment(s, x0, y0) <= t && distanceToSegment(s, x1, y1) <= t) return long(i);
    }
    return -1;
  }

 private:
  std::size_t column(double x) const { return clampCell((x - minX_) / cellX_); }
  std::size_t row(double y) const { return clampCell((y - minY_) / cellY_); }
  std::size_t clampCell(double c) const {
    if (!(c > 0)) return 0;
    return c >= double(side_) ? side_ - 1 : static_cast<std::size_t>(c);
  }
  const std::vector<Segment>& segments_;
  double minX_, minY_, cellX_, cellY_;
  std::size_t side_;
  std::vector<std::vector<std::size_t>> cells_;
};

}  // namespace

std::string checkConstraints(const Mesh& mesh, const Polylines& polylines,
                             const std::vector<std::uint32_t>& inputToVertex) {
  const std::vector<double>& p = mesh.points;
  std::vector<Segment> segments;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  std::size_t offset = 0;
  for (const auto& line : polylines) {
    const std::size_t n = line.size() / 2;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const std::uint32_t u = inputToVertex[offset + k], v = inputToVertex[offset + k + 1];
      if (u == v) continue;
      segments.push_back({line[2 * k], line[2 * k + 1], line[2 * k + 2], line[2 * k + 3]});
      ends.push_back({u, v});
    }
    offset += n;
  }
  if (segments.empty()) return "";
  const SegmentGrid grid(segments);

  // Constrained neighbours of each vertex.
  std::vector<std::vector<std::uint32_t>> next(p.size() / 2);
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    if (!mesh.constrained[e]) continue;
    const std::uint32_t u = mesh.triangles[e], v = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
    next[u].push_back(v);
    if (mesh.halfedges[e] < 0) next[v].push_back(u);  // a hull edge has no twin to list it
    if (grid.find(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]) < 0) {
      std::ostringstream out;
      out << "constrained edge " << u << "-" << v << " (" << p[2 * u] << ", " << p[2 * u + 1]
          << ")-(" << p[2 * v] << ", " << p[2 * v + 1] << ") lies on no input segment";
      return out.str();
    }
  }

  // From each segment's start, constrained edges lying on it lead to its end: a search
  // over those edges (several vertices may lie on a segment within rounding).
  std::vector<std::uint32_t> seenAt(p.size() / 2, 0xFFFFFFFFu);
  std::vector<std::uint32_t> frontier;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    const double t = tolerance(s);
    const std::uint32_t goal = ends[i].second;
    frontier.assign(1, ends[i].first);
    seenAt[ends[i].first] = static_cast<std::uint32_t>(i);
    bool found = false;
    for (std::size_t k = 0; k < frontier.size() && !found; ++k) {
      for (const std::uint32_t n : next[frontier[k]]) {
        if (seenAt[n] == i || distanceToSegment(s, p[2 * n], p[2 * n + 1]) > t) continue;
        seenAt[n] = static_cast<std::uint32_t>(i);
        if (n == goal) found = true;
        frontier.push_back(n);
      }
    }
    if (!found) {
      std::ostringstream out;
      out << "input segment " << i << " (" << s.ax << ", " << s.ay << ")-(" << s.bx << ", " << s.by
          << ") is not covered by a chain of constrained edges lying on it";
      return out.str();
    }
  }
  return "";
}

bool insideEvenOdd(const Polylines& polylines, double x, double y) {
  bool inside = false;
  for (const auto& line : polylines) {
    const std::size_t n = line.size() / 2;
    if (n < 3 || line[0] != line[2 * n - 2] || line[1] != line[2 * n - 1]) continue;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double ax = line[2 * k], ay = line[2 * k + 1], bx = line[2 * k + 2],
                   by = line[2 * k + 3];
      if ((ay > y) != (by > y) && x < ax + (y - ay) / (by - ay) * (bx - ax)) inside = !inside;
    }
  }
  return inside;
}

double distanceToPolylines(const Polylines& polylines, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& line : polylines)
    for (std::size_t k = 0; k + 3 < line.size(); k += 2)
      best =
          std::min(best, distanceToSegment({line[k], line[k + 1], line[k + 2], line[k + 3]}, x, y));
  return best;
}

}  // namespace geocdt::testing
