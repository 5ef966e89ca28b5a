#include "polygon_checks.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "constraint_invariants.h"
#include "geocdt/predicates.h"

namespace geocdt::testing {

namespace {

template <typename... Args>
std::string describe(Args&&... args) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << args);
  return out.str();
}

struct Point {
  double x, y;
  bool operator<(const Point& o) const { return x < o.x || (x == o.x && y < o.y); }
  bool operator==(const Point& o) const { return x == o.x && y == o.y; }
};

// The ring segments of a polygon in a uniform grid over their bounding box, so that the
// segments near an edge are found without a scan of all of them (Natural Earth's large
// countries have 100,000 segments).
class SegmentGrid {
 public:
  void build(const std::vector<std::array<double, 4>>& segments) {
    segments_ = &segments;
    if (segments.empty()) return;
    minX_ = minY_ = INFINITY;
    double maxX = -INFINITY, maxY = -INFINITY;
    for (const auto& s : segments) {
      minX_ = std::min({minX_, s[0], s[2]});
      minY_ = std::min({minY_, s[1], s[3]});
      maxX = std::max({maxX, s[0], s[2]});
      maxY = std::max({maxY, s[1], s[3]});
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(segments.size() / 4.0)));
    scaleX_ = maxX > minX_ ? side_ / (maxX - minX_) : 0;
    scaleY_ = maxY > minY_ ? side_ / (maxY - minY_) : 0;
    cells_.assign(side_ * side_, {});
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const auto& s = segments[i];
      forCells(
          std::min(s[0], s[2]), std::min(s[1], s[3]), std::max(s[0], s[2]), std::max(s[1], s[3]),
          [&](std::vector<std::uint32_t>& cell) { cell.push_back(static_cast<std::uint32_t>(i)); });
    }
  }

  // f(segment) for each segment whose box may meet the box (x0, y0)-(x1, y1); a segment may
  // come more than once.
  template <typename F>
  void near(double x0, double y0, double x1, double y1, F&& f) const {
    if (cells_.empty()) return;
    forCells(x0, y0, x1, y1, [&](const std::vector<std::uint32_t>& cell) {
      for (const std::uint32_t i : cell) f((*segments_)[i]);
    });
  }

 private:
  std::size_t cell(double v, double min, double scale) const {
    const double c = (v - min) * scale;
    if (!(c > 0)) return 0;
    return c >= static_cast<double>(side_) ? side_ - 1 : static_cast<std::size_t>(c);
  }
  template <typename F>
  void forCells(double x0, double y0, double x1, double y1, F&& f) const {
    for (std::size_t j = cell(y0, minY_, scaleY_); j <= cell(y1, minY_, scaleY_); ++j)
      for (std::size_t i = cell(x0, minX_, scaleX_); i <= cell(x1, minX_, scaleX_); ++i)
        f(const_cast<std::vector<std::uint32_t>&>(cells_[j * side_ + i]));
  }

  const std::vector<std::array<double, 4>>* segments_ = nullptr;
  double minX_ = 0, minY_ = 0, scaleX_ = 0, scaleY_ = 0;
  std::size_t side_ = 0;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// One polygon's rings (each closed) and triangles, with the positions of its indices.
class PolygonView {
 public:
  PolygonView(const PolygonBatch& b, const PolygonTriangles& out, std::size_t p)
      : b_(b), out_(out) {
    for (std::uint32_t r = b.polygonOffsets[p]; r < b.polygonOffsets[p + 1]; ++r) {
      std::vector<double> ring;
      for (std::uint32_t k = b.ringOffsets[r]; k < b.ringOffsets[r + 1]; ++k) {
        ring.push_back(b.xy[2 * k]);
        ring.push_back(b.xy[2 * k + 1]);
      }
      const std::size_t n = ring.size();
      if (n >= 4 && (ring[0] != ring[n - 2] || ring[1] != ring[n - 1]))
        ring.insert(ring.end(), {ring[0], ring[1]});
      for (std::size_t k = 0; k + 3 < ring.size(); k += 2)
        if (ring[k] != ring[k + 2] || ring[k + 1] != ring[k + 3])
          segments.push_back({ring[k], ring[k + 1], ring[k + 2], ring[k + 3]});
      rings.push_back(std::move(ring));
    }
    grid_.build(segments);
    first = out.triangleOffsets[p];
    last = out.triangleOffsets[p + 1];
  }

  Point at(std::uint32_t i) const {
    if (i < b_.pointCount) return {b_.xy[2 * i], b_.xy[2 * i + 1]};
    const std::size_t e = i - b_.pointCount;
    return {out_.extraPoints[2 * e], out_.extraPoints[2 * e + 1]};
  }
  bool extra(std::uint32_t i) const { return i >= b_.pointCount; }
  std::uint32_t corner(std::size_t t, int k) const { return out_.triangles[3 * t + k]; }

  // Whether the edge p-q lies on a ring segment: exactly, or within the bound that crossings
  // keep (README, known limitations: where rings cross, the general engine's chains bend
  // through rounded crossings, or through a vertex within ulps of a segment; decided in
  // rationals by withinBoundOfPolyline).
  enum class OnRing { No, Exactly, WithinBound };
  OnRing onRing(Point p, Point q) const {
    bool exact = false, bent = false;
    // The bound is two ulps of the largest coordinate: a box that much wider around the edge.
    const double slack =
        4 * spacing(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)}));
    const double x0 = std::min(p.x, q.x), y0 = std::min(p.y, q.y);
    const double x1 = std::max(p.x, q.x), y1 = std::max(p.y, q.y);
    grid_.near(x0, y0, x1, y1, [&](const std::array<double, 4>& s) {
      exact = exact || (onSegment(s.data(), p) && onSegment(s.data(), q));
    });
    if (exact) return OnRing::Exactly;
    grid_.near(x0 - slack, y0 - slack, x1 + slack, y1 + slack, [&](const std::array<double, 4>& s) {
      bent = bent || withinBoundOfPolyline({s[0], s[1], s[2], s[3]}, p.x, p.y, q.x, q.y);
    });
    return bent ? OnRing::WithinBound : OnRing::No;
  }

  // Whether two ring segments near the box (x0, y0)-(x1, y1) cross. There the general
  // engine's chains bend through the rounded crossing, within the bound above, and the
  // crossing may round onto an input vertex and leave no extra point behind.
  bool crossingNear(double x0, double y0, double x1, double y1) const {
    std::vector<const std::array<double, 4>*> near;
    grid_.near(x0, y0, x1, y1, [&](const std::array<double, 4>& s) { near.push_back(&s); });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    const auto side = [](const std::array<double, 4>& s, double x, double y) {
      return static_cast<int>(orient2d(s[0], s[1], s[2], s[3], x, y));
    };
    for (std::size_t i = 0; i < near.size(); ++i)
      for (std::size_t j = i + 1; j < near.size(); ++j) {
        const std::array<double, 4>&a = *near[i], &b = *near[j];
        if (side(a, b[0], b[1]) * side(a, b[2], b[3]) < 0 &&
            side(b, a[0], a[1]) * side(b, a[2], a[3]) < 0)
          return true;
      }
    return false;
  }

  // Whether q lies on the closed segment s[0], s[1] - s[2], s[3], exactly.
  static bool onSegment(const double* s, Point q) {
    return orient2d(s[0], s[1], s[2], s[3], q.x, q.y) == Sign::Zero &&
           std::min(s[0], s[2]) <= q.x && q.x <= std::max(s[0], s[2]) &&
           std::min(s[1], s[3]) <= q.y && q.y <= std::max(s[1], s[3]);
  }

  static double spacing(double v) { return std::nextafter(v, INFINITY) - v; }

  // The winding number of q against the rings (exactly: the crossings of a ray to +x decided
  // by orientation), or false when q lies on a ring segment.
  bool winding(Point q, int& w) const {
    w = 0;
    for (const auto& s : segments) {
      const double ux = s[0], uy = s[1], vx = s[2], vy = s[3];
      const Sign o = orient2d(ux, uy, vx, vy, q.x, q.y);
      if (o == Sign::Zero && onSegment(s.data(), q)) return false;
      if (uy <= q.y) {
        if (vy > q.y && o == Sign::Positive) ++w;
      } else if (vy <= q.y && o == Sign::Negative) {
        --w;
      }
    }
    return true;
  }

  std::vector<std::vector<double>> rings;
  std::vector<std::array<double, 4>> segments;
  std::size_t first = 0, last = 0;

 private:
  const PolygonBatch& b_;
  const PolygonTriangles& out_;
  SegmentGrid grid_;
};

bool inside(int winding, FillRule fill) {
  return fill == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0;
}

mpq_class doubledArea(Point a, Point b, Point c) {
  const mpq_class ax(a.x), ay(a.y);
  return (mpq_class(b.x) - ax) * (mpq_class(c.y) - ay) -
         (mpq_class(b.y) - ay) * (mpq_class(c.x) - ax);
}

long double doubledAreaApprox(Point a, Point b, Point c) {
  return ((long double)b.x - a.x) * ((long double)c.y - a.y) -
         ((long double)b.y - a.y) * ((long double)c.x - a.x);
}

// The reference: the rings through geocdt::triangulate, keep inside.
Mesh reference(const PolygonView& v, FillRule fill) {
  std::vector<PolylineView> views;
  for (const std::vector<double>& ring : v.rings) views.push_back({ring.data(), ring.size() / 2});
  MeshOptions options;
  options.keep = Keep::Inside;
  options.fill = fill;
  Mesh m;
  const Status s = triangulate(nullptr, 0, views.data(), views.size(), {}, options, m);
  if (!s.ok()) m.triangles.assign(1, 0xFFFFFFFFu);  // marks the failure
  return m;
}

std::string compareArea(const PolygonView& v, FillRule fill, std::size_t p) {
  const Mesh m = reference(v, fill);
  if (m.triangles.size() == 1) return describe("polygon ", p, ": the reference failed");
  const auto point = [&](std::uint32_t i) { return Point{m.points[2 * i], m.points[2 * i + 1]}; };
  long double ours = 0, theirs = 0, magnitude = 0;
  for (std::size_t t = v.first; t < v.last; ++t) {
    const long double a =
        doubledAreaApprox(v.at(v.corner(t, 0)), v.at(v.corner(t, 1)), v.at(v.corner(t, 2)));
    ours += a;
    magnitude += std::fabs(a);
  }
  for (std::size_t i = 0; i < m.triangles.size(); i += 3)
    theirs += doubledAreaApprox(point(m.triangles[i]), point(m.triangles[i + 1]),
                                point(m.triangles[i + 2]));
  if (std::fabs(ours - theirs) <= 1e-15L * magnitude) return "";
  mpq_class exactOurs = 0, exactTheirs = 0;
  for (std::size_t t = v.first; t < v.last; ++t)
    exactOurs += doubledArea(v.at(v.corner(t, 0)), v.at(v.corner(t, 1)), v.at(v.corner(t, 2)));
  for (std::size_t i = 0; i < m.triangles.size(); i += 3)
    exactTheirs +=
        doubledArea(point(m.triangles[i]), point(m.triangles[i + 1]), point(m.triangles[i + 2]));
  if (exactOurs == exactTheirs) return "";
  return describe("polygon ", p, ": area ", exactOurs.get_d() / 2, " where triangulate(keep ",
                  "inside) gives ", exactTheirs.get_d() / 2);
}

using Edges = std::map<std::pair<Point, Point>, Point>;  // directed edge -> its apex

// Orientation, indices and edges used once; fills edges.
std::string checkTriangles(const PolygonView& v, std::size_t indices, std::size_t p, Edges& edges,
                           bool& extra) {
  for (std::size_t t = v.first; t < v.last; ++t) {
    Point corners[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = v.corner(t, k);
      if (c >= indices) return describe("polygon ", p, " triangle ", t, ": index ", c);
      extra = extra || v.extra(c);
      corners[k] = v.at(c);
    }
    const Point a = corners[0], bb = corners[1], cc = corners[2];
    if (orient2d(a.x, a.y, bb.x, bb.y, cc.x, cc.y) != Sign::Positive)
      return describe("polygon ", p, " triangle ", t, " is not strictly counter-clockwise");
    for (int k = 0; k < 3; ++k) {
      const auto key = std::make_pair(corners[k], corners[(k + 1) % 3]);
      if (!edges.emplace(key, corners[(k + 2) % 3]).second)
        return describe("polygon ", p, " triangle ", t, ": an edge used twice in one direction");
    }
  }
  return "";
}

// Border edges on ring segments, interior edges constrained Delaunay; bent: some border edge
// lies only within the crossings' bound of its segment (a chain bent at a crossing).
std::string checkEdges(const PolygonView& v, const Edges& edges, std::size_t p, bool& bent) {
  for (const auto& [key, apex] : edges) {
    const auto twin = edges.find(std::make_pair(key.second, key.first));
    if (twin == edges.end()) {
      const PolygonView::OnRing on = v.onRing(key.first, key.second);
      if (on == PolygonView::OnRing::No)
        return describe("polygon ", p, ": border edge (", key.first.x, ", ", key.first.y, ")-(",
                        key.second.x, ", ", key.second.y, ") lies on no ring segment");
      bent = bent || on == PolygonView::OnRing::WithinBound;
      continue;
    }
    // An interior edge, once: Delaunay, or constrained (on a ring segment).
    if (key.second < key.first) continue;
    const Point a = key.first, bb = key.second, c = apex, d = twin->second;
    if (incircle(a.x, a.y, bb.x, bb.y, c.x, c.y, d.x, d.y) == Sign::Positive &&
        v.onRing(a, bb) == PolygonView::OnRing::No)
      return describe("polygon ", p, ": edge (", a.x, ", ", a.y, ")-(", bb.x, ", ", bb.y,
                      ") is not constrained Delaunay");
  }
  return "";
}

// Inside by the fill rule: the winding at each triangle's centroid, where it lies strictly
// inside the triangle. Each test scans every segment: on large polygons a sample, so that a
// polygon costs at most about 4M orientation tests.
std::string checkInside(const PolygonView& v, FillRule fill, std::size_t p) {
  const std::size_t stride = 1 + (v.last - v.first) * v.segments.size() / 4000000;
  for (std::size_t t = v.first; t < v.last; t += stride) {
    const Point a = v.at(v.corner(t, 0)), bb = v.at(v.corner(t, 1)), cc = v.at(v.corner(t, 2));
    const Point corners[3] = {a, bb, cc};
    const Point q{(a.x + bb.x + cc.x) / 3, (a.y + bb.y + cc.y) / 3};
    bool strictlyInside = true;
    for (int k = 0; k < 3; ++k) {
      const Point u = corners[k], w = corners[(k + 1) % 3];
      strictlyInside = strictlyInside && orient2d(u.x, u.y, w.x, w.y, q.x, q.y) == Sign::Positive;
    }
    if (!strictlyInside) continue;
    // Within the crossings' bound of two segments that cross, the rings' chains bend (README,
    // known limitations): the exact segments say nothing there, neither the winding nor
    // whether one of them passes through the triangle.
    const double slack =
        4 * PolygonView::spacing(std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(bb.x),
                                           std::fabs(bb.y), std::fabs(cc.x), std::fabs(cc.y)}));
    const auto nearCrossing = [&] {
      return v.crossingNear(
          std::min({a.x, bb.x, cc.x}) - slack, std::min({a.y, bb.y, cc.y}) - slack,
          std::max({a.x, bb.x, cc.x}) + slack, std::max({a.y, bb.y, cc.y}) + slack);
    };
    int winding = 0;
    if (!v.winding(q, winding)) {
      if (nearCrossing()) continue;
      return describe("polygon ", p, " triangle ", t, ": a ring segment passes through it");
    }
    if (inside(winding, fill) || nearCrossing()) continue;
    return describe("polygon ", p, " triangle ", t, " is outside (winding ", winding, ")");
  }
  return "";
}

std::string checkPolygon(const PolygonBatch& b, const PolygonTriangles& out, std::size_t p,
                         const PolygonCheckOptions& options) {
  const PolygonView v(b, out, p);
  Edges edges;
  bool extra = false, bent = false;
  std::string failure =
      checkTriangles(v, b.pointCount + out.extraPoints.size() / 2, p, edges, extra);
  if (failure.empty()) failure = checkEdges(v, edges, p, bent);
  // Where rings cross, chains bend by up to two ulps of their largest coordinate (README,
  // known limitations): the unbent segments may cut through triangles beside them, so the
  // winding at a centroid says nothing there. Those polygons are the reference's own output.
  if (failure.empty() && !extra && !bent) failure = checkInside(v, options.fill, p);
  if (failure.empty() && options.compareArea) failure = compareArea(v, options.fill, p);
  return failure;
}

}  // namespace

std::string checkPolygonTriangles(const PolygonBatch& b, const PolygonTriangles& out,
                                  const PolygonCheckOptions& options) {
  if (out.triangleOffsets.size() != b.polygonCount + 1 || out.triangleOffsets[0] != 0)
    return describe("triangleOffsets has ", out.triangleOffsets.size(), " entries for ",
                    b.polygonCount, " polygons");
  for (std::size_t p = 0; p < b.polygonCount; ++p)
    if (out.triangleOffsets[p + 1] < out.triangleOffsets[p])
      return describe("triangleOffsets decreases at polygon ", p);
  if (3 * static_cast<std::size_t>(out.triangleOffsets.back()) != out.triangles.size())
    return describe("triangleOffsets ends at ", out.triangleOffsets.back(), " for ",
                    out.triangles.size() / 3, " triangles");
  if (out.extraPoints.size() % 2 != 0) return "extraPoints has an odd length";
  for (std::size_t p = 0; p < b.polygonCount; ++p) {
    const std::string failure = checkPolygon(b, out, p, options);
    if (!failure.empty()) return failure;
  }
  return "";
}

}  // namespace geocdt::testing
