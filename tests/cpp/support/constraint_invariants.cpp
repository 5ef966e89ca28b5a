#include "constraint_invariants.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "geocdt/predicates.h"

namespace geocdt::testing {

namespace {

struct Segment {
  double ax, ay, bx, by;
};

template <typename... Args>
std::string describe(Args&&... args) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << args);
  return out.str();
}

// In long double: its exponent range keeps squares of subnormal lengths from underflowing,
// and its 64-bit significand keeps the error far below the bound (2^-51 of the magnitude).
long double distanceToSegment(const Segment& s, double x, double y) {
  const long double dx = (long double)s.bx - s.ax, dy = (long double)s.by - s.ay;
  const long double len2 = dx * dx + dy * dy;
  long double t =
      len2 > 0 ? (((long double)x - s.ax) * dx + ((long double)y - s.ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0L, 1.0L);
  const long double ex = s.ax + t * dx - x, ey = s.ay + t * dy - y;
  return std::sqrt(ex * ex + ey * ey);
}

// The spacing of doubles at |v|.
double spacing(double v) { return std::nextafter(std::fabs(v), INFINITY) - std::fabs(v); }

// The length of (x, y) by the core's formula (IEEE operations only, unlike std::hypot, whose
// last bit differs between C libraries): a chain's cost must be computed as the core does.
double norm(double x, double y) {
  double a = std::fabs(x), b = std::fabs(y);
  if (a < b) std::swap(a, b);
  if (a == 0 || std::isinf(a)) return a;
  const double r = b / a;
  return a * std::sqrt(1 + r * r);
}

// Whether (x, y) lies within `bound` of the closed segment, in rationals.
bool withinExactly(const Segment& s, double x, double y, double bound) {
  const mpq_class ax(s.ax), ay(s.ay), bx(s.bx), by(s.by), px(x), py(y);
  const mpq_class dx = bx - ax, dy = by - ay, wx = px - ax, wy = py - ay;
  const mpq_class dot = wx * dx + wy * dy, length2 = dx * dx + dy * dy;
  mpq_class distance2;
  if (dot <= 0) {
    distance2 = wx * wx + wy * wy;
  } else if (dot >= length2) {
    const mpq_class ex = px - bx, ey = py - by;
    distance2 = ex * ex + ey * ey;
  } else {
    const mpq_class cross = dx * wy - dy * wx;
    distance2 = cross * cross / length2;
  }
  const mpq_class b(bound);
  return distance2 <= b * b;
}

bool within(const Segment& s, double x, double y, double bound) {
  const long double d = distanceToSegment(s, x, y);
  if (d <= 0.9L * bound) return true;
  if (d >= 1.1L * bound) return false;
  return withinExactly(s, x, y, bound);
}

// Whether segment s meets the rounding cell of (x, y), the box of the points that round to
// it (closed here, and in long double: it only ranks chains, it decides nothing).
bool meetsCell(const Segment& s, double x, double y) {
  long double lo = 0, hi = 1;
  const auto clip = [&](double a, double b, double c) {
    const long double below = (c - std::nextafter(c, -INFINITY)) / 2.0L;
    const long double above = (std::nextafter(c, INFINITY) - c) / 2.0L;
    const long double w = (long double)a - c, d = (long double)b - a;
    if (d == 0) return -below <= w && w <= above;
    const long double t0 = (-below - w) / d, t1 = (above - w) / d;
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
    return true;
  };
  return clip(s.ax, s.bx, x) && clip(s.ay, s.by, y) && lo <= hi;
}

// The sign of (q - p) . (b - a): whether q lies beyond p along the segment's direction.
int alongSign(const Segment& s, double px, double py, double qx, double qy) {
  const long double ux = (long double)qx - px, uy = (long double)qy - py;
  const long double dx = (long double)s.bx - s.ax, dy = (long double)s.by - s.ay;
  const long double v = ux * dx + uy * dy;
  const long double error = 0x1p-58L * (std::fabs(ux * dx) + std::fabs(uy * dy));
  if (v > error) return 1;
  if (-v > error) return -1;
  const mpq_class exact = (mpq_class(qx) - mpq_class(px)) * (mpq_class(s.bx) - mpq_class(s.ax)) +
                          (mpq_class(qy) - mpq_class(py)) * (mpq_class(s.by) - mpq_class(s.ay));
  return sgn(exact);
}

// Whether (x, y) lies on the closed segment s, exactly.
bool exactlyOn(const Segment& s, double x, double y) {
  if (x < std::min(s.ax, s.bx) || x > std::max(s.ax, s.bx) || y < std::min(s.ay, s.by) ||
      y > std::max(s.ay, s.by))
    return false;
  return orient2d(s.ax, s.ay, s.bx, s.by, x, y) == Sign::Zero;
}

// Segments bucketed on a uniform grid by their bounding boxes, widened by their bounds.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Segment>& segments, const std::vector<double>& bounds)
      : segments_(segments), bounds_(bounds) {
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
      const double t = bounds[i];
      const std::size_t x0 = column(std::min(s.ax, s.bx) - t),
                        x1 = column(std::max(s.ax, s.bx) + t);
      const std::size_t y0 = row(std::min(s.ay, s.by) - t), y1 = row(std::max(s.ay, s.by) + t);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) cells_[y * side_ + x].push_back(i);
    }
  }
  // Whether some segment has both points within its bound.
  bool covers(double x0, double y0, double x1, double y1) const {
    const double mx = 0.5 * x0 + 0.5 * x1, my = 0.5 * y0 + 0.5 * y1;
    for (const std::size_t i : cells_[row(my) * side_ + column(mx)]) {
      const Segment& s = segments_[i];
      if (within(s, x0, y0, bounds_[i]) && within(s, x1, y1, bounds_[i])) return true;
    }
    return false;
  }
  // The segments whose widened boxes hold the cell of (x, y).
  const std::vector<std::size_t>& near(double x, double y) const {
    return cells_[row(y) * side_ + column(x)];
  }

 private:
  std::size_t column(double x) const { return clampCell((x - minX_) / cellX_); }
  std::size_t row(double y) const { return clampCell((y - minY_) / cellY_); }
  std::size_t clampCell(double c) const {
    if (!(c > 0)) return 0;
    return c >= double(side_) ? side_ - 1 : static_cast<std::size_t>(c);
  }
  const std::vector<Segment>& segments_;
  const std::vector<double>& bounds_;
  double minX_, minY_, cellX_, cellY_;
  std::size_t side_;
  std::vector<std::vector<std::size_t>> cells_;
};

// How two input segments meet: not at all, in one point interior to both, or otherwise
// (at an end, or overlapping), where a crossing of their chains is not defined.
enum class Meeting { Apart, Crossing, Touching };

Meeting meeting(const Segment& s, const Segment& t) {
  const int o1 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.ax, t.ay));
  const int o2 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.bx, t.by));
  const int o3 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.ax, s.ay));
  const int o4 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.bx, s.by));
  if (o1 * o2 < 0 && o3 * o4 < 0) return Meeting::Crossing;
  if (o1 * o2 > 0 || o3 * o4 > 0) return Meeting::Apart;
  // A zero: an end on the other's line. It meets the other segment when it lies within
  // that segment's box (then it is on the segment).
  const auto inBox = [](const Segment& g, double x, double y) {
    return std::min(g.ax, g.bx) <= x && x <= std::max(g.ax, g.bx) && std::min(g.ay, g.by) <= y &&
           y <= std::max(g.ay, g.by);
  };
  if ((o1 == 0 && inBox(s, t.ax, t.ay)) || (o2 == 0 && inBox(s, t.bx, t.by)) ||
      (o3 == 0 && inBox(t, s.ax, s.ay)) || (o4 == 0 && inBox(t, s.bx, s.by)))
    return Meeting::Touching;
  return Meeting::Apart;
}

// Whether ray a->w lies strictly inside the counter-clockwise sector from ray a->u to a->v.
bool inSector(const std::vector<double>& p, std::uint32_t a, std::uint32_t u, std::uint32_t v,
              std::uint32_t w) {
  const auto turn = [&](std::uint32_t from, std::uint32_t to) {
    return int(
        orient2d(p[2 * a], p[2 * a + 1], p[2 * from], p[2 * from + 1], p[2 * to], p[2 * to + 1]));
  };
  const int uv = turn(u, v);
  if (uv > 0) return turn(u, w) > 0 && turn(w, v) > 0;
  if (uv < 0) return !(turn(v, w) >= 0 && turn(w, u) >= 0);
  return turn(u, w) > 0;  // u and v opposite: a half-plane
}

// How often chain q crosses chain p, counted over the stretches they share; `undefined`
// tells whether a stretch holds an end of either chain (where a crossing is not defined).
using Positions = std::vector<std::pair<std::uint32_t, std::size_t>>;  // (vertex, index)

// A chain's vertices with their indices, sorted for lookup.
Positions positionsOf(const std::vector<std::uint32_t>& chain) {
  Positions out;
  for (std::size_t k = 0; k < chain.size(); ++k) out.push_back({chain[k], k});
  std::sort(out.begin(), out.end());
  return out;
}

int crossings(const std::vector<double>& p, const std::vector<std::uint32_t>& P,
              const std::vector<std::uint32_t>& Q, const Positions& inQ, bool& undefined) {
  const std::size_t m = P.size(), n = Q.size();
  int count = 0;
  undefined = false;
  for (std::size_t i = 0; i < m; ++i) {
    const auto found =
        std::lower_bound(inQ.begin(), inQ.end(), std::pair<std::uint32_t, std::size_t>{P[i], 0});
    if (found == inQ.end() || found->first != P[i]) continue;
    const std::size_t k = found->second;
    // The shared stretch P[i..j] = Q[k..l], with Q running forward or backward along it.
    int step = 0;
    if (i + 1 < m && k + 1 < n && P[i + 1] == Q[k + 1]) step = 1;
    if (i + 1 < m && k >= 1 && P[i + 1] == Q[k - 1]) step = -1;
    std::size_t j = i, l = k;
    while (step != 0 && j + 1 < m && l + step < n && P[j + 1] == Q[l + step]) {
      ++j;
      l += step;
    }
    if (i == 0 || j + 1 == m || std::min(k, l) == 0 || std::max(k, l) + 1 == n) {
      undefined = true;
    } else {
      // Q's neighbours off the stretch at its two ends, each on the left or the right of P.
      const std::uint32_t qi = step >= 0 ? Q[k - 1] : Q[k + 1];
      const std::uint32_t qj = step >= 0 ? Q[l + 1] : Q[l - 1];
      const bool leftAtI = inSector(p, P[i], P[i + 1], P[i - 1], qi);
      const bool leftAtJ = inSector(p, P[j], P[j + 1], P[j - 1], qj);
      count += leftAtI != leftAtJ;
    }
    i = j;
  }
  return count;
}

}  // namespace

double chainBound(double ax, double ay, double bx, double by) {
  const double m = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by)});
  return 2 * (std::nextafter(m, INFINITY) - m);
}

std::string checkConstraints(const Mesh& mesh, const Polylines& polylines,
                             const std::vector<std::uint32_t>& inputToVertex, bool overlaps) {
  const std::vector<double>& p = mesh.points;
  std::vector<Segment> segments;
  std::vector<double> bounds;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  std::vector<std::uint32_t> polylineOf;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < polylines.size(); ++i) {
    const std::vector<double>& line = polylines[i];
    const std::size_t n = line.size() / 2;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const std::uint32_t u = inputToVertex[offset + k], v = inputToVertex[offset + k + 1];
      if (u == v) continue;
      segments.push_back({line[2 * k], line[2 * k + 1], line[2 * k + 2], line[2 * k + 3]});
      bounds.push_back(chainBound(line[2 * k], line[2 * k + 1], line[2 * k + 2], line[2 * k + 3]));
      ends.push_back({u, v});
      polylineOf.push_back(static_cast<std::uint32_t>(i));
    }
    offset += n;
  }
  if (segments.empty()) return "";
  const SegmentGrid grid(segments, bounds);

  // Constrained neighbours of each vertex.
  std::vector<std::vector<std::uint32_t>> next(p.size() / 2);
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    if (!mesh.constrained[e]) continue;
    const std::uint32_t u = mesh.triangles[e], v = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
    next[u].push_back(v);
    if (mesh.halfedges[e] < 0) next[v].push_back(u);  // a hull edge has no twin to list it
    if (!grid.covers(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]))
      return describe("constrained edge ", u, "-", v, " (", p[2 * u], ", ", p[2 * u + 1], ")-(",
                      p[2 * v], ", ", p[2 * v + 1], ") lies within the bound of no input segment");
  }

  // The polylines each constrained edge names, when the mesh has provenance: a chain only
  // uses edges that name its polyline (with coordinates of very different sizes the bound is
  // wide across the smaller axis, and other segments' edges would fit it too). Where the mesh
  // names the input segments too (MeshOptions::segmentSources), a chain only uses edges that
  // name its segment: then each segment has one chain, the one the core routed, and the
  // checks below need not guess it among the many a tangle allows.
  const bool bySegment = !mesh.segmentOffsets.empty();
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> named;
  for (std::size_t i = 0; i < mesh.constraintEdges.size(); ++i) {
    const std::uint32_t e = mesh.constraintEdges[i];
    const std::uint32_t u = mesh.triangles[e], v = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
    const std::uint64_t key = std::uint64_t{std::min(u, v)} << 32 | std::max(u, v);
    if (bySegment)
      named[key].assign(mesh.segmentSources.begin() + mesh.segmentOffsets[i],
                        mesh.segmentSources.begin() + mesh.segmentOffsets[i + 1]);
    else
      named[key].assign(mesh.sources.begin() + mesh.sourceOffsets[i],
                        mesh.sources.begin() + mesh.sourceOffsets[i + 1]);
  }
  // Where segments overlap, the edges they share list each of them (API.md): an edge routed
  // for a segment it lies exactly on names the polyline of every other segment it lies
  // exactly on. (Not every edge exactly on a segment: in a snap-rounded tangle a segment's
  // chain may pass through a vertex an ulp beside another segment's link along it.) Checked
  // where asked and the mesh names each edge's segments.
  for (std::size_t i = 0; i < mesh.constraintEdges.size() && overlaps && bySegment; ++i) {
    const std::uint32_t e = mesh.constraintEdges[i];
    const std::uint32_t u = mesh.triangles[e], v = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
    const double ux = p[2 * u], uy = p[2 * u + 1], vx = p[2 * v], vy = p[2 * v + 1];
    const auto onSegment = [&](std::size_t j) {
      return exactlyOn(segments[j], ux, uy) && exactlyOn(segments[j], vx, vy);
    };
    const auto routed = mesh.segmentSources.begin() + mesh.segmentOffsets[i];
    const auto routedEnd = mesh.segmentSources.begin() + mesh.segmentOffsets[i + 1];
    const auto along = std::find_if(
        routed, routedEnd, [&](std::uint32_t t) { return t < segments.size() && onSegment(t); });
    if (along == routedEnd) continue;
    const auto first = mesh.sources.begin() + mesh.sourceOffsets[i];
    const auto last = mesh.sources.begin() + mesh.sourceOffsets[i + 1];
    for (const std::size_t j : grid.near(0.5 * ux + 0.5 * vx, 0.5 * uy + 0.5 * vy)) {
      if (std::find(first, last, polylineOf[j]) != last || !onSegment(j)) continue;
      return describe("constrained edge ", u, "-", v, " (", ux, ", ", uy, ")-(", vx, ", ", vy,
                      ") lies on input segments ", *along, " and ", j, " but does not name ",
                      "polyline ", polylineOf[j]);
    }
  }

  // Whether edge u-v may be on segment i's chain.
  const auto names = [&](std::uint32_t u, std::uint32_t v, std::size_t i) {
    if (named.empty()) return true;
    const auto it = named.find(std::uint64_t{std::min(u, v)} << 32 | std::max(u, v));
    const std::uint32_t name = bySegment ? static_cast<std::uint32_t>(i) : polylineOf[i];
    return it != named.end() &&
           std::find(it->second.begin(), it->second.end(), name) != it->second.end();
  };

  // How far v strays from segment i in units of the spacing of doubles on each axis there
  // (snap rounding keeps a chain within one such unit). In double, exactly as the core's
  // chain check computes it, so that both pick the same chain where several stray equally
  // (in a tangle, the choice decides whether two chains seem to cross).
  const auto stray = [&](std::size_t i, std::uint32_t v) {
    const Segment& s = segments[i];
    const double gx = spacing(std::max(std::fabs(s.ax), std::fabs(s.bx)));
    const double gy = spacing(std::max(std::fabs(s.ay), std::fabs(s.by)));
    const double dx = (s.bx - s.ax) / gx, dy = (s.by - s.ay) / gy;
    const double wx = (p[2 * v] - s.ax) / gx, wy = (p[2 * v + 1] - s.ay) / gy;
    const double t = std::clamp((wx * dx + wy * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return norm(wx - t * dx, wy - t * dy);
  };
  // From each segment's start, constrained edges to vertices within the bound and further
  // along lead to its end (a graph without cycles: positions increase). Where several chains
  // would do, the one that strays least is the segment's: the chain snap rounding gives.
  // Ties go to the lower vertex ids, as in the core.
  std::vector<std::uint32_t> seenAt(p.size() / 2, 0xFFFFFFFFu), from(p.size() / 2);
  struct Step {
    double cost;  // the most a chain to here strays
    std::uint32_t at, before;
  };
  std::vector<Step> queue;
  std::vector<std::vector<std::uint32_t>> chains(segments.size());
  std::uint32_t searches = 0;
  const auto search = [&](std::size_t i, double bound, bool ordered) {
    const Segment& s = segments[i];
    const std::uint32_t goal = ends[i].second, mark = searches++;
    queue.assign(1, {0.0, ends[i].first, ends[i].first});
    const auto later = [](const Step& a, const Step& b) {
      return std::tie(a.cost, a.at, a.before) > std::tie(b.cost, b.at, b.before);
    };
    while (!queue.empty()) {
      std::pop_heap(queue.begin(), queue.end(), later);
      const Step step = queue.back();
      queue.pop_back();
      const std::uint32_t at = step.at;
      if (seenAt[at] == mark) continue;
      seenAt[at] = mark;
      from[at] = step.before;
      if (at == goal) return true;
      for (const std::uint32_t n : next[at]) {
        if (seenAt[n] == mark || !names(at, n, i) || !within(s, p[2 * n], p[2 * n + 1], bound))
          continue;
        if (ordered && alongSign(s, p[2 * at], p[2 * at + 1], p[2 * n], p[2 * n + 1]) <= 0)
          continue;
        queue.push_back({std::max(step.cost, stray(i, n)), n, at});
        std::push_heap(queue.begin(), queue.end(), later);
      }
    }
    return false;
  };
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (search(i, bounds[i], true)) {
      std::vector<std::uint32_t>& chain = chains[i];
      for (std::uint32_t v = ends[i].second; v != ends[i].first; v = from[v]) chain.push_back(v);
      chain.push_back(ends[i].first);
      std::reverse(chain.begin(), chain.end());
      continue;
    }
    const std::string what = describe("input segment ", i, " (", s.ax, ", ", s.ay, ")-(", s.bx,
                                      ", ", s.by, ") is not covered by a chain of constrained ");
    if (search(i, bounds[i], false))
      return what + "edges in order along it (within the bound, it goes back and forth)";
    const double loose = 1e-6 * std::hypot(s.bx - s.ax, s.by - s.ay) + 1e6 * bounds[i];
    if (search(i, loose, false))
      return what + "edges within " + describe(bounds[i]) + " of it (only farther away)";
    return what + "edges lying near it";
  }

  // The output names polylines, not segments: in a tangle a few ulps wide, a segment's chain
  // can borrow edges of a neighbouring segment of its polyline, or pass one of its own
  // vertices by, and still keep the bound. So a pair of chains that seems to cross is checked
  // again with other chains of the two segments: first the one snap rounding would route
  // (through the most vertices whose rounding cells the segment meets, then through the
  // fewest others), where the least-straying chain may take a shortcut along a neighbouring
  // segment; then every chain (up to 64 each): it fails only when every choice crosses.
  // Positions along the segment increase along a chain: in that order, one pass finds the
  // best chain.
  const auto snappedChain = [&](std::size_t i) {
    const Segment& s = segments[i];
    const std::uint32_t a = ends[i].first, b = ends[i].second;
    const auto forward = [&](std::uint32_t u, std::uint32_t n) {
      return names(u, n, i) && within(s, p[2 * n], p[2 * n + 1], bounds[i]) &&
             alongSign(s, p[2 * u], p[2 * u + 1], p[2 * n], p[2 * n + 1]) > 0;
    };
    struct Best {
      long cells = 0, others = 0;  // vertices on the best chain to here, in s's cells or not
      std::uint32_t before = 0;
      bool reached = false;
    };
    std::unordered_map<std::uint32_t, Best> best{{a, {0, 0, a, true}}};
    std::vector<std::uint32_t> order(1, a);  // the vertices reached from a
    for (std::size_t k = 0; k < order.size(); ++k)
      for (const std::uint32_t n : next[order[k]])
        if (!best.count(n) && forward(order[k], n)) {
          best[n] = {};
          order.push_back(n);
        }
    std::sort(order.begin(), order.end(), [&](std::uint32_t u, std::uint32_t v) {
      return alongSign(s, p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]) > 0;
    });
    for (const std::uint32_t u : order) {
      const Best from = best[u];
      for (const std::uint32_t n : next[u]) {
        if (!best.count(n) || !forward(u, n)) continue;
        const bool cell = meetsCell(s, p[2 * n], p[2 * n + 1]);
        const Best to{from.cells + cell, from.others + !cell, u, true};
        Best& at = best[n];
        if (!at.reached ||
            std::make_pair(to.cells, -to.others) > std::make_pair(at.cells, -at.others))
          at = to;
      }
    }
    std::vector<std::uint32_t> chain;
    if (!best.count(b)) return chain;
    for (std::uint32_t v = b; v != a; v = best[v].before) chain.push_back(v);
    chain.push_back(a);
    std::reverse(chain.begin(), chain.end());
    return chain;
  };
  // Up to 4096 chains a segment when the first two seem to cross: two long segments ulps
  // apart through a tangle can have more than a thousand chains each within the bound, and
  // only some pairs keep apart as snap rounding routes them (fuzz: 64 were too few). Each
  // segment's list is built once, with each vertex tested against the bound once, and a
  // vertex from which the end proved unreachable is not entered again: a tangle's chains
  // share most of their vertices (fuzz: 25 s for one small input without this).
  std::unordered_map<std::size_t, std::vector<std::vector<std::uint32_t>>> chainsOf;
  const auto everyChain = [&](std::size_t i) -> const std::vector<std::vector<std::uint32_t>>& {
    const auto cached = chainsOf.find(i);
    if (cached != chainsOf.end()) return cached->second;
    const Segment& s = segments[i];
    const std::uint32_t a = ends[i].first, b = ends[i].second;
    std::unordered_map<std::uint32_t, bool> near, dead;
    const auto forward = [&](std::uint32_t u, std::uint32_t n) {
      if (!names(u, n, i)) return false;
      const auto known = near.find(n);
      const bool inside = known != near.end()
                              ? known->second
                              : (near[n] = within(s, p[2 * n], p[2 * n + 1], bounds[i]));
      return inside && alongSign(s, p[2 * u], p[2 * u + 1], p[2 * n], p[2 * n + 1]) > 0;
    };
    std::vector<std::vector<std::uint32_t>> found(1, snappedChain(i));
    std::vector<std::uint32_t> path(1, a);
    std::vector<std::size_t> choice(1, 0), foundBefore(1, 1);
    while (!path.empty() && found.size() < 4096) {
      const std::uint32_t at = path.back();
      std::size_t& k = choice.back();
      while (at != b && k < next[at].size() &&
             (dead.count(next[at][k]) || !forward(at, next[at][k])))
        ++k;
      if (at == b || k == next[at].size()) {
        if (at == b)
          found.push_back(path);
        else if (found.size() == foundBefore.back())
          dead[at] = true;
        path.pop_back();
        choice.pop_back();
        foundBefore.pop_back();
        continue;
      }
      path.push_back(next[at][k++]);
      choice.push_back(0);
      foundBefore.push_back(found.size());
    }
    return chainsOf[i] = std::move(found);
  };

  // No new crossings: pairs of chains that share a vertex, and, for inputs small enough to
  // compare every pair, pairs of crossing segments whose chains share none.
  std::vector<std::vector<std::uint32_t>> through(p.size() / 2);
  for (std::size_t i = 0; i < chains.size(); ++i)
    for (const std::uint32_t v : chains[i]) through[v].push_back(static_cast<std::uint32_t>(i));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& list : through)
    for (std::size_t a = 0; a < list.size(); ++a)
      for (std::size_t b = a + 1; b < list.size(); ++b)
        pairs.push_back({std::min(list[a], list[b]), std::max(list[a], list[b])});
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  // A crossing within the bound of an end may be kept as a touch at that end.
  const auto crossingNearAnEnd = [&](std::size_t i, std::size_t j) {
    const Segment &s = segments[i], &t = segments[j];
    return within(t, s.ax, s.ay, bounds[j]) || within(t, s.bx, s.by, bounds[j]) ||
           within(s, t.ax, t.ay, bounds[i]) || within(s, t.bx, t.by, bounds[i]);
  };
  std::vector<Positions> positions(chains.size());
  for (std::size_t i = 0; i < chains.size(); ++i) positions[i] = positionsOf(chains[i]);
  for (const auto& [i, j] : pairs) {
    const Meeting how = meeting(segments[i], segments[j]);
    if (how == Meeting::Touching || (how == Meeting::Crossing && crossingNearAnEnd(i, j))) continue;
    int count = 0;
    const auto wrong = [&](const std::vector<std::uint32_t>& P, const std::vector<std::uint32_t>& Q,
                           const Positions& inQ) {
      if (P.empty() || Q.empty()) return true;
      bool undefined = false;
      count = crossings(p, P, Q, inQ, undefined);
      return how == Meeting::Apart ? count > 0 : count > 1 || (!undefined && count != 1);
    };
    if (wrong(chains[i], chains[j], positions[j])) {
      const auto &is = everyChain(i), &js = everyChain(j);
      bool some = false;
      for (std::size_t q = 0; q < js.size() && !some; ++q) {
        const Positions inQ = positionsOf(js[q]);
        for (std::size_t r = 0; r < is.size() && !some; ++r) some = !wrong(is[r], js[q], inQ);
      }
      if (some) continue;
      wrong(chains[i], chains[j], positions[j]);
      return describe("the chains of input segments ", i, " and ", j, " cross ", count,
                      " times, but the segments ",
                      how == Meeting::Apart ? "do not meet" : "cross once");
    }
  }
  if (segments.size() <= 2000) {
    for (std::size_t i = 0; i < segments.size(); ++i)
      for (std::size_t j = i + 1; j < segments.size(); ++j)
        if (meeting(segments[i], segments[j]) == Meeting::Crossing && !crossingNearAnEnd(i, j) &&
            !std::binary_search(pairs.begin(), pairs.end(),
                                std::pair<std::uint32_t, std::uint32_t>(i, j)))
          return describe("input segments ", i, " and ", j,
                          " cross but their chains share no vertex");
  }
  return "";
}

bool withinBoundOfPolyline(const std::vector<double>& line, double x0, double y0, double x1,
                           double y1) {
  for (std::size_t k = 0; k + 3 < line.size(); k += 2) {
    const Segment s{line[k], line[k + 1], line[k + 2], line[k + 3]};
    if (s.ax == s.bx && s.ay == s.by) continue;
    const double bound = chainBound(s.ax, s.ay, s.bx, s.by);
    if (within(s, x0, y0, bound) && within(s, x1, y1, bound)) return true;
  }
  return false;
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
      best = std::min(best, static_cast<double>(distanceToSegment(
                                {line[k], line[k + 1], line[k + 2], line[k + 3]}, x, y)));
  return best;
}

}  // namespace geocdt::testing
