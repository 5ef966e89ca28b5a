#include "voronoi_checks.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

#include "geocdt/predicates.h"
#include "point_generators.h"

namespace geocdt::testing {
namespace {

struct Key {
  std::uint64_t a, b, c, d;
  bool operator==(const Key& o) const { return a == o.a && b == o.b && c == o.c && d == o.d; }
};
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    return k.a * 0x9E3779B97F4A7C15ull ^ (k.b + 0x632BE59BD9B4E019ull) * 31 ^ k.c * 131 ^ k.d;
  }
};
// %.17g: enough digits to tell ulps apart, and tiny values are not 0.000000.
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return v == 0 ? 0 : b;  // -0 and 0 are one point
}

// Nearest sites by a static k-d tree (any distribution, clustered ones too); among equal sites
// the first index wins.
class SiteGrid {
 public:
  explicit SiteGrid(const std::vector<double>& xy) : xy_(xy), order_(xy.size() / 2) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
    build(0, order_.size(), 0);
  }

  // The k nearest sites to (x, y), nearest first (ties: lower index first).
  std::vector<std::size_t> nearest(double x, double y, std::size_t k) const {
    std::vector<std::pair<double, std::size_t>> best;
    search(0, order_.size(), 0, x, y, k, best);
    std::vector<std::size_t> out;
    for (const auto& b : best) out.push_back(b.second);
    return out;
  }

  double distance(std::size_t site, double x, double y) const {
    return std::hypot(x - xy_[2 * site], y - xy_[2 * site + 1]);
  }

 private:
  void build(std::size_t lo, std::size_t hi, int axis) {
    if (hi - lo <= 1) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        order_.begin() + lo, order_.begin() + mid, order_.begin() + hi,
        [&](std::size_t a, std::size_t b) { return xy_[2 * a + axis] < xy_[2 * b + axis]; });
    build(lo, mid, 1 - axis);
    build(mid + 1, hi, 1 - axis);
  }

  void search(std::size_t lo, std::size_t hi, int axis, double x, double y, std::size_t k,
              std::vector<std::pair<double, std::size_t>>& best) const {
    if (lo >= hi) return;
    const std::size_t mid = lo + (hi - lo) / 2, site = order_[mid];
    const std::pair<double, std::size_t> candidate{distance(site, x, y), site};
    if (best.size() < k || candidate < best.back()) {
      best.insert(std::upper_bound(best.begin(), best.end(), candidate), candidate);
      if (best.size() > k) best.pop_back();
    }
    const double split = xy_[2 * site + axis], q = axis == 0 ? x : y;
    const bool left = q < split;
    search(left ? lo : mid + 1, left ? mid : hi, 1 - axis, x, y, k, best);
    if (best.size() < k || std::fabs(q - split) <= best.back().first)
      search(left ? mid + 1 : lo, left ? hi : mid, 1 - axis, x, y, k, best);
  }

  const std::vector<double>& xy_;
  std::vector<std::size_t> order_;
};

// q in a long double, whose exponent reaches where a double's underflows.
long double toLongDouble(mpq_class q) {
  if (q == 0) return 0;
  const long e = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                 static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (e > 0) mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(e));
  if (e < 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(-e));
  return std::ldexp(static_cast<long double>(q.get_d()), static_cast<int>(e));
}

// Exactly: |v - s|^2 <= |v - t|^2.
bool notFartherExactly(double vx, double vy, double sx, double sy, double tx, double ty) {
  const mpq_class ax = mpq_class(vx) - sx, ay = mpq_class(vy) - sy;
  const mpq_class bx = mpq_class(vx) - tx, by = mpq_class(vy) - ty;
  return ax * ax + ay * ay <= bx * bx + by * by;
}

double distanceToSegment(double x, double y, const std::array<double, 4>& s) {
  const long double dx = s[2] - s[0], dy = s[3] - s[1];
  const long double len2 = dx * dx + dy * dy;
  long double t = len2 > 0 ? ((x - s[0]) * dx + (y - s[1]) * dy) / len2 : 0;
  t = std::clamp(t, 0.0L, 1.0L);
  return static_cast<double>(std::hypot(x - (s[0] + t * dx), y - (s[1] + t * dy)));
}

// Boundary segments by a bucket grid, for "which segment is this point on".
class SegmentGrid {
 public:
  explicit SegmentGrid(const CheckDomain& d) : d_(d) {
    side_ = std::max<long>(1, static_cast<long>(std::sqrt(d.segments.size() / 4.0)));
    w_ = std::max(d.maxX - d.minX, 1e-300) / side_;
    h_ = std::max(d.maxY - d.minY, 1e-300) / side_;
    cells_.resize(side_ * side_);
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
      const auto& s = d.segments[k];
      for (long j = row(std::min(s[1], s[3])); j <= row(std::max(s[1], s[3])); ++j)
        for (long i = column(std::min(s[0], s[2])); i <= column(std::max(s[0], s[2])); ++i)
          cells_[j * side_ + i].push_back(k);
    }
  }
  // The length of the shortest (or the longest) segment within tolerance(length) of (x, y), or
  // -1.
  template <typename Tolerance>
  double segmentAt(double x, double y, Tolerance tolerance, bool longest = false) const {
    double best = -1;
    for (long j = row(y) - 1; j <= row(y) + 1; ++j)
      for (long i = column(x) - 1; i <= column(x) + 1; ++i) {
        if (i < 0 || j < 0 || i >= side_ || j >= side_) continue;
        for (const std::size_t k : cells_[j * side_ + i]) {
          const auto& s = d_.segments[k];
          const double length = std::hypot(s[2] - s[0], s[3] - s[1]);
          if (distanceToSegment(x, y, s) <= tolerance(length) &&
              (best < 0 || (longest ? length > best : length < best)))
            best = length;
        }
      }
    return best;
  }

 private:
  // Clamped as doubles: a point far off a thin domain is more cells away than a long holds.
  long bucket(double offset, double size) const {
    const double at = std::floor(offset / size);
    return static_cast<long>(std::clamp(at, 0.0, static_cast<double>(side_ - 1)));
  }
  long column(double x) const { return bucket(x - d_.minX, w_); }
  long row(double y) const { return bucket(y - d_.minY, h_); }
  const CheckDomain& d_;
  long side_;
  double w_, h_;
  std::vector<std::vector<std::size_t>> cells_;
};

// Where (x, y) lies against the closed ring p[0 .. n): 1 inside, 0 outside, -1 on it.
int inRing(const double* p, std::size_t n, double x, double y) {
  int winding = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double ax = p[2 * i], ay = p[2 * i + 1], bx = p[2 * i + 2], by = p[2 * i + 3];
    const Sign o = orient2d(ax, ay, bx, by, x, y);
    if (o == Sign::Zero && std::min(ax, bx) <= x && x <= std::max(ax, bx) &&
        std::min(ay, by) <= y && y <= std::max(ay, by))
      return -1;
    if (ay <= y) {
      if (by > y && o == Sign::Positive) ++winding;
    } else if (by <= y && o == Sign::Negative) {
      --winding;
    }
  }
  return winding != 0;
}

// Where (x, y) lies against site i's cell: 1 inside, 0 outside, -1 on a ring.
int inCell(const VoronoiCells& c, std::size_t i, double x, double y) {
  for (std::uint32_t p = c.siteOffsets[i]; p < c.siteOffsets[i + 1]; ++p) {
    int where = 0;
    for (std::uint32_t r = c.polygonOffsets[p]; r < c.polygonOffsets[p + 1]; ++r) {
      const std::uint32_t b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
      const int in = inRing(c.coords.data() + 2 * b, e - b, x, y);
      if (in < 0) return -1;
      if (r == c.polygonOffsets[p])
        where = in;
      else if (in)
        where = 0;
    }
    if (where) return 1;
  }
  return 0;
}

long double ringArea(const VoronoiCells& c, std::uint32_t r) {
  const double* p = c.coords.data();
  const std::uint32_t b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
  long double twice = 0;
  for (std::uint32_t k = b + 1; k + 1 < e; ++k)
    twice += static_cast<long double>(p[2 * k] - p[2 * b]) * (p[2 * k + 3] - p[2 * b + 1]) -
             static_cast<long double>(p[2 * k + 1] - p[2 * b + 1]) * (p[2 * k + 2] - p[2 * b]);
  return twice / 2;
}

std::string checkLayout(const VoronoiCells& c, std::size_t sites, VoronoiReport& report) {
  if (c.siteOffsets.size() != sites + 1 || c.siteOffsets[0] != 0) return "siteOffsets' size";
  if (c.polygonOffsets.size() != c.siteOffsets.back() + 1u) return "polygonOffsets' size";
  if (c.ringOffsets.size() != c.polygonOffsets.back() + 1u) return "ringOffsets' size";
  if (c.coords.size() != 2u * c.ringOffsets.back()) return "coords' size";
  for (std::size_t i = 0; i < sites; ++i)
    if (c.siteOffsets[i + 1] < c.siteOffsets[i]) return "siteOffsets decrease";
  for (std::size_t p = 0; p + 1 < c.polygonOffsets.size(); ++p)
    if (c.polygonOffsets[p + 1] <= c.polygonOffsets[p]) return "a polygon without rings";
  for (std::size_t r = 0; r + 1 < c.ringOffsets.size(); ++r) {
    const std::uint32_t b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
    if (e < b + 4) return "ring " + std::to_string(r) + " has fewer than 4 points";
    if (c.coords[2 * b] != c.coords[2 * e - 2] || c.coords[2 * b + 1] != c.coords[2 * e - 1])
      return "ring " + std::to_string(r) + " is not closed";
    for (std::uint32_t k = b; k + 1 < e; ++k)
      if (c.coords[2 * k] == c.coords[2 * k + 2] && c.coords[2 * k + 1] == c.coords[2 * k + 3])
        return "ring " + std::to_string(r) + " repeats a point";
  }
  report.polygons = c.polygonOffsets.size() - 1;
  report.rings = c.ringOffsets.size() - 1;
  report.points = c.ringOffsets.back();
  return "";
}

// How far rounding may move vertex (x, y) of the cell of the site at (sx, sy) (web/API.md,
// Exactness): a Voronoi vertex within 2^-48 (M + R) <= 2^-48 (|v| + 2 |v - s|), a crossing
// within rounding of its boundary segment and 2^-50 of its length along it; the slack covers
// both. The longest segment through v, as the checks cannot tell which one v came from.
double vertexMove(double x, double y, double sx, double sy, const SegmentGrid& grid) {
  const double size = std::max(std::fabs(x), std::fabs(y));
  const double own = std::hypot(x - sx, y - sy);
  const auto tolerance = [&](double length) {
    return kVertexSlack * (size + own + length) + kSubnormalSlack;
  };
  return tolerance(std::max(0.0, grid.segmentAt(x, y, tolerance, true)));
}

// Outer rings counter-clockwise, holes clockwise, unless the ring is so small that moving its
// vertices by vertexMove could turn it over: a vertex k moved by d_k changes the area by at
// most the sum over edges k -> k+1 of (|e_k| (d_k + d_k+1) + d_k d_k+1) / 2.
std::string checkWinding(const VoronoiCells& c, const std::vector<double>& sites,
                         const CheckDomain& d, VoronoiReport& report) {
  const SegmentGrid grid(d);
  const double* p = c.coords.data();
  for (std::size_t i = 0; i + 1 < c.siteOffsets.size(); ++i)
    for (std::uint32_t g = c.siteOffsets[i]; g < c.siteOffsets[i + 1]; ++g)
      for (std::uint32_t r = c.polygonOffsets[g]; r < c.polygonOffsets[g + 1]; ++r) {
        const long double a = ringArea(c, r);
        report.cellArea += a;
        if (r == c.polygonOffsets[g] ? a > 0 : a < 0) continue;
        const std::uint32_t b = c.ringOffsets[r], e = c.ringOffsets[r + 1];
        const auto move = [&](std::uint32_t k) {
          return d.segments.empty()
                     ? kSubnormalSlack
                     : vertexMove(p[2 * k], p[2 * k + 1], sites[2 * i], sites[2 * i + 1], grid);
        };
        long double turn = 0;
        for (std::uint32_t k = b; k + 1 < e; ++k) {
          const long double edge = std::hypot(p[2 * k + 2] - p[2 * k], p[2 * k + 3] - p[2 * k + 1]);
          const long double from = move(k), to = move(k + 1);
          turn += (edge * (from + to) + from * to) / 2;
        }
        if (std::fabs(a) > turn) return "ring " + std::to_string(r) + " winds the wrong way";
      }
  return "";
}

// Every cell edge is shared by another cell, reversed, or lies on the domain's boundary.
std::string checkEdges(const VoronoiCells& c, const CheckDomain& d, VoronoiReport& report) {
  std::unordered_map<Key, std::int64_t, KeyHash> edges;
  const double* p = c.coords.data();
  for (std::size_t r = 0; r + 1 < c.ringOffsets.size(); ++r)
    for (std::uint32_t k = c.ringOffsets[r]; k + 1 < c.ringOffsets[r + 1]; ++k) {
      const Key forward{bits(p[2 * k]), bits(p[2 * k + 1]), bits(p[2 * k + 2]), bits(p[2 * k + 3])};
      const Key backward{forward.c, forward.d, forward.a, forward.b};
      const auto twin = edges.find(backward);
      if (twin != edges.end() && twin->second > 0) {
        if (--twin->second == 0) edges.erase(twin);
      } else {
        ++edges[forward];
      }
    }
  const SegmentGrid grid(d);
  for (const auto& [edge, count] : edges) {
    double x[2], y[2];
    std::memcpy(&x[0], &edge.a, 8);
    std::memcpy(&y[0], &edge.b, 8);
    std::memcpy(&x[1], &edge.c, 8);
    std::memcpy(&y[1], &edge.d, 8);
    for (int e = 0; e < 2; ++e) {
      const double size = std::max(std::fabs(x[e]), std::fabs(y[e]));
      const auto tolerance = [&](double length) {
        return kVertexSlack * (size + length) + kSubnormalSlack;
      };
      if (grid.segmentAt(x[e], y[e], tolerance) < 0)
        return "an edge from (" + number(x[0]) + ", " + number(y[0]) + ") to (" + number(x[1]) +
               ", " + number(y[1]) + ") is neither shared nor on the domain's boundary";
    }
    report.boundaryEdges += count;
  }
  return "";
}

std::string checkVertices(const VoronoiCells& c, const std::vector<double>& sites,
                          const SiteGrid& near, const CheckDomain& d) {
  std::unordered_set<Key, KeyHash> boundary;
  for (const auto& s : d.segments) boundary.insert({bits(s[0]), bits(s[1]), 0, 0});
  const SegmentGrid grid(d);
  const double* p = c.coords.data();
  for (std::size_t i = 0; i + 1 < c.siteOffsets.size(); ++i) {
    const double sx = sites[2 * i], sy = sites[2 * i + 1];
    for (std::uint32_t k = c.ringOffsets[c.polygonOffsets[c.siteOffsets[i]]];
         k < c.ringOffsets[c.polygonOffsets[c.siteOffsets[i + 1]]]; ++k) {
      const double x = p[2 * k], y = p[2 * k + 1];
      const std::size_t j = near.nearest(x, y, 1)[0];
      const double tx = sites[2 * j], ty = sites[2 * j + 1];
      // A boundary vertex is in the cell of a site nearest it, exactly; a crossing that
      // rounded onto a boundary vertex (the midpoint of a one-ulp boundary segment is no
      // double) is a rounded point, held to the documented bound below.
      if (boundary.count({bits(x), bits(y), 0, 0}) && notFartherExactly(x, y, sx, sy, tx, ty))
        continue;
      const double size = std::max(std::fabs(x), std::fabs(y));
      const double own = std::hypot(x - sx, y - sy);
      // The longest segment through v (as in vertexMove): near a domain vertex a crossing
      // of a long segment, rounded by its length, also lies within rounding of a short one.
      const double along = std::max(
          0.0,
          grid.segmentAt(
              x, y,
              [&](double length) { return kVertexSlack * (size + own + length) + kSubnormalSlack; },
              true));
      const double excess = own - std::hypot(x - tx, y - ty);
      if (excess > kVertexSlack * (size + own + along) + kSubnormalSlack)
        return "vertex (" + number(x) + ", " + number(y) + ") of site " + std::to_string(i) + " (" +
               number(sx) + ", " + number(sy) + ") is " + number(excess) + " nearer site " +
               std::to_string(j) + " (" + number(tx) + ", " + number(ty) + ")";
    }
  }
  return "";
}

std::string checkSamples(const VoronoiCells& c, const std::vector<double>& sites,
                         const SiteGrid& near, const CheckDomain& d, std::size_t samples,
                         VoronoiReport& report) {
  Random random(samples * 7919 + sites.size());
  const SegmentGrid grid(d);
  for (std::size_t s = 0; s < samples; ++s) {
    const double x = d.minX + (d.maxX - d.minX) * random.uniform();
    const double y = d.minY + (d.maxY - d.minY) * random.uniform();
    const int in = d.inside(x, y);
    if (in < 0) continue;
    // Too near the boundary for the rounded cells to say: a cell's boundary edge ends at
    // crossings only within rounding of the boundary (web/API.md, Exactness).
    const double size = std::max(std::fabs(x), std::fabs(y));
    if (grid.segmentAt(x, y, [&](double length) {
          return kVertexSlack * (size + length) + kSubnormalSlack;
        }) >= 0)
      continue;
    const std::vector<std::size_t> order = near.nearest(x, y, 6);
    const double first = near.distance(order[0], x, y);
    // Too near a bisector: cell vertices are rounded (the documented slack, and "a few
    // 2^-1074 where coordinates are subnormal", where hypot's distances are off as much).
    if (order.size() > 1 &&
        near.distance(order[1], x, y) - first <= 1e-9 * (first + size) + 4 * kSubnormalSlack)
      continue;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int where = inCell(c, order[k], x, y);
      const int expected = k == 0 ? in : 0;
      if (where != expected)
        return "sample (" + number(x) + ", " + number(y) + "), " + (in ? "inside" : "outside") +
               " the domain, is " + (where ? "in" : "not in") + " the cell of site " +
               std::to_string(order[k]) + (k == 0 ? ", its nearest" : "");
    }
    ++report.samples;
  }
  return "";
}

void boundsOfSegments(CheckDomain& d) {
  d.minX = d.minY = INFINITY;
  d.maxX = d.maxY = -INFINITY;
  for (const auto& s : d.segments) {
    d.minX = std::min({d.minX, s[0], s[2]});
    d.maxX = std::max({d.maxX, s[0], s[2]});
    d.minY = std::min({d.minY, s[1], s[3]});
    d.maxY = std::max({d.maxY, s[1], s[3]});
  }
}

}  // namespace

int CheckDomain::inside(double x, double y) const {
  if (isBox) {
    if (x == minX || x == maxX || y == minY || y == maxY) return -1;
    return x > minX && x < maxX && y > minY && y < maxY;
  }
  if (rings) {
    const Location l = rings->locate(x, y);
    if (l.kind == Location::Kind::Outside || l.kind == Location::Kind::Empty) return 0;
    if (l.kind != Location::Kind::Face) return -1;
    return mesh.inside[l.triangle];
  }
  int where = 1;  // convex: inside every edge
  for (const auto& s : segments) {
    const Sign o = orient2d(s[0], s[1], s[2], s[3], x, y);
    if (o == Sign::Zero) return -1;
    if (o == Sign::Negative) where = 0;
  }
  return segments.empty() ? 0 : where;
}

CheckDomain boxCheckDomain(const double box[4]) {
  CheckDomain d;
  d.segments = {{box[0], box[1], box[2], box[1]},
                {box[2], box[1], box[2], box[3]},
                {box[2], box[3], box[0], box[3]},
                {box[0], box[3], box[0], box[1]}};
  d.area = static_cast<long double>(box[2] - box[0]) * (box[3] - box[1]);
  d.isBox = true;
  boundsOfSegments(d);
  return d;
}

CheckDomain ringCheckDomain(const std::vector<PolylineView>& rings, FillRule fill) {
  CheckDomain d;
  d.rings = std::make_shared<Triangulation>();
  d.rings->insertPolylines(rings.data(), rings.size());
  MeshOptions o;
  o.insideFlags = true;
  o.fill = fill;
  d.mesh = d.rings->mesh(o);
  const Mesh& m = d.mesh;
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const std::size_t next = e % 3 == 2 ? e - 2 : e + 1;
    const std::uint32_t a = m.triangles[e], b = m.triangles[next];
    if (e % 3 == 0 && m.inside[e / 3]) {
      const std::uint32_t c = m.triangles[e + 2];
      // Differences in long double: a sliver ulps wide has no area in double differences.
      const auto at = [&](std::uint32_t v, int k) {
        return static_cast<long double>(m.points[2 * v + k]);
      };
      const long double ux = at(b, 0) - at(a, 0), uy = at(b, 1) - at(a, 1);
      d.area += (ux * (at(c, 1) - at(a, 1)) - uy * (at(c, 0) - at(a, 0))) / 2;
    }
    const std::int32_t twin = m.halfedges[e];
    if (m.inside[e / 3] && (twin < 0 || !m.inside[twin / 3]))
      d.segments.push_back(
          {m.points[2 * a], m.points[2 * a + 1], m.points[2 * b], m.points[2 * b + 1]});
  }
  boundsOfSegments(d);
  return d;
}

// Andrew's monotone chain with exact orientation.
CheckDomain hullCheckDomain(const std::vector<double>& sites) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < sites.size() / 2; ++i) p.push_back({sites[2 * i], sites[2 * i + 1]});
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  std::vector<std::pair<double, double>> hull;
  const auto turnsLeft = [&](const std::pair<double, double>& c) {
    const auto& a = hull[hull.size() - 2];
    const auto& b = hull.back();
    return orient2d(a.first, a.second, b.first, b.second, c.first, c.second) == Sign::Positive;
  };
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (std::size_t k = 0; k < p.size(); ++k) {
      const auto& c = pass == 0 ? p[k] : p[p.size() - 1 - k];
      while (hull.size() >= base + 2 && !turnsLeft(c)) hull.pop_back();
      hull.push_back(c);
    }
    hull.pop_back();
  }
  CheckDomain d;
  mpq_class twice = 0;  // exactly: a sliver's area can hide under its coordinates' rounding
  if (hull.size() >= 3)
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const auto& a = hull[i];
      const auto& b = hull[(i + 1) % hull.size()];
      d.segments.push_back({a.first, a.second, b.first, b.second});
      twice += mpq_class(a.first) * b.second - mpq_class(a.second) * b.first;
    }
  d.area = toLongDouble(twice / 2);
  boundsOfSegments(d);
  return d;
}

std::string checkVoronoi(const VoronoiCells& cells, const std::vector<double>& sites,
                         const CheckDomain& domain, std::size_t samples, double areaTolerance,
                         VoronoiReport* out) {
  VoronoiReport report;
  std::string error = checkLayout(cells, sites.size() / 2, report);
  if (error.empty()) error = checkWinding(cells, sites, domain, report);
  // Boundary vertices off by the slack move the area by up to that times the boundary's length.
  long double perimeter = 0, longest = 0;
  for (const auto& s : domain.segments) {
    const long double length = std::hypot(s[2] - s[0], s[3] - s[1]);
    perimeter += length;
    longest = std::max(longest, length);
  }
  const double size = std::max({std::fabs(domain.minX), std::fabs(domain.maxX),
                                std::fabs(domain.minY), std::fabs(domain.maxY)});
  const long double areaSlack =
      areaTolerance * domain.area + perimeter * (kVertexSlack * (size + longest) + kSubnormalSlack);
  if (error.empty() && std::fabs(report.cellArea - domain.area) > areaSlack)
    error = "the cells' area " + number(static_cast<double>(report.cellArea)) +
            " is not the domain's " + number(static_cast<double>(domain.area));
  // Empty: no boundary (an area can round to 0 where the domain is a sliver).
  if (error.empty() && domain.segments.empty() && report.polygons > 0)
    error = "cells in an empty domain";
  if (error.empty() && !domain.segments.empty()) error = checkEdges(cells, domain, report);
  const SiteGrid near(sites);
  if (error.empty() && !domain.segments.empty()) error = checkVertices(cells, sites, near, domain);
  if (error.empty() && !domain.segments.empty())
    error = checkSamples(cells, sites, near, domain, samples, report);
  if (out) *out = report;
  return error;
}

}  // namespace geocdt::testing
