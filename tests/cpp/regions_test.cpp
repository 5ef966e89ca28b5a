// Region labels: each triangle names the smallest input polygon that holds it (the innermost
// where polygons nest), or -1. The expected labels come from point-in-polygon tests of each
// triangle's centroid against the input rings, with exact predicates, and from areas counted
// on the integer grid, independently of the mesh's own windings.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "geocdt/predicates.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

using Ring = std::vector<double>;

struct Polygon {
  std::vector<Ring> rings;
};

// Polylines: the polygons' rings in order, then the extra polylines (of no polygon).
struct Input {
  std::vector<double> points;
  std::vector<Polygon> polygons;  // polygon i has id ids[i]
  std::vector<std::int32_t> ids;
  std::vector<Ring> extra;

  std::vector<Ring> polylines() const {
    std::vector<Ring> all;
    for (const Polygon& p : polygons) all.insert(all.end(), p.rings.begin(), p.rings.end());
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  }
  std::vector<std::int32_t> polylinePolygons() const {
    std::vector<std::int32_t> map;
    for (std::size_t i = 0; i < polygons.size(); ++i)
      map.insert(map.end(), polygons[i].rings.size(), ids[i]);
    return map;
  }
};

Ring rectangle(double x0, double y0, double x1, double y1, bool counterClockwise = true) {
  if (counterClockwise) return {x0, y0, x1, y0, x1, y1, x0, y1, x0, y0};
  return {x0, y0, x0, y1, x1, y1, x1, y0, x0, y0};
}

Mesh run(const Input& in, MeshOptions mo) {
  const std::vector<Ring> lines = in.polylines();
  std::vector<PolylineView> views;
  for (const Ring& l : lines) views.push_back({l.data(), l.size() / 2});
  mo.regions = true;
  mo.polylinePolygons = in.polylinePolygons();
  Mesh m;
  const Status s =
      triangulate(in.points.data(), in.points.size() / 2, views.data(), views.size(), {}, mo, m);
  EXPECT_TRUE(s.ok()) << s.message;
  return m;
}

// Winding number of (x, y) about a closed ring, exactly; (x, y) must not lie on the ring.
int winding(const Ring& ring, double x, double y) {
  int w = 0;
  for (std::size_t k = 0; k + 3 < ring.size(); k += 2) {
    const double ax = ring[k], ay = ring[k + 1], bx = ring[k + 2], by = ring[k + 3];
    const Sign side = orient2d(ax, ay, bx, by, x, y);
    if (ay <= y && by > y && side == Sign::Positive) ++w;
    if (by <= y && ay > y && side == Sign::Negative) --w;
  }
  return w;
}

bool inside(const Polygon& p, FillRule fill, double x, double y) {
  int w = 0;
  for (const Ring& r : p.rings) w += winding(r, x, y);
  return fill == FillRule::EvenOdd ? w % 2 != 0 : w != 0;
}

// The centroid of triangle t, when it lies strictly inside the triangle (rounding may put the
// centroid of a sliver on or beyond an edge).
bool centroid(const Mesh& m, std::size_t t, double& x, double& y) {
  const double* p = m.points.data();
  const std::uint32_t a = m.triangles[3 * t], b = m.triangles[3 * t + 1],
                      c = m.triangles[3 * t + 2];
  x = (p[2 * a] + p[2 * b] + p[2 * c]) / 3;
  y = (p[2 * a + 1] + p[2 * b + 1] + p[2 * c + 1]) / 3;
  return orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y) == Sign::Positive &&
         orient2d(p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], x, y) == Sign::Positive &&
         orient2d(p[2 * c], p[2 * c + 1], p[2 * a], p[2 * a + 1], x, y) == Sign::Positive;
}

// The label the rule gives, from the polygons holding (x, y) and their areas and triangle
// counts as the test measured them.
std::int32_t expectedLabel(const Input& in, FillRule fill, double x, double y,
                           const std::vector<double>& area,
                           const std::vector<std::size_t>& triangles) {
  std::int32_t best = -1;
  std::size_t bestIndex = 0;
  for (std::size_t i = 0; i < in.polygons.size(); ++i) {
    if (!inside(in.polygons[i], fill, x, y)) continue;
    if (best < 0 || std::tie(area[i], triangles[i], in.ids[i]) <
                        std::tie(area[bestIndex], triangles[bestIndex], best)) {
      best = in.ids[i];
      bestIndex = i;
    }
  }
  return best;
}

// Checks every triangle whose centroid is usable; areas are given (exact), triangle counts
// are measured here from the centroids. Returns the number of triangles checked.
std::size_t expectLabels(const Input& in, FillRule fill, const Mesh& m,
                         const std::vector<double>& area) {
  const std::size_t n = m.triangles.size() / 3;
  EXPECT_EQ(m.regions.size(), n);
  std::vector<std::size_t> triangles(in.polygons.size(), 0);
  std::vector<std::pair<double, double>> at(n);
  std::vector<bool> usable(n);
  for (std::size_t t = 0; t < n; ++t) {
    usable[t] = centroid(m, t, at[t].first, at[t].second);
    EXPECT_TRUE(usable[t]) << "a sliver in a test that has none";
    for (std::size_t i = 0; i < in.polygons.size(); ++i)
      triangles[i] += inside(in.polygons[i], fill, at[t].first, at[t].second);
  }
  std::size_t checked = 0;
  for (std::size_t t = 0; t < n && t < m.regions.size(); ++t) {
    if (!usable[t]) continue;
    const auto [x, y] = at[t];
    EXPECT_EQ(m.regions[t], expectedLabel(in, fill, x, y, area, triangles))
        << "triangle " << t << " at " << x << ", " << y;
    ++checked;
  }
  return checked;
}

// Exact areas of integer-cornered rectangle polygons: unit cells counted by their centers.
std::vector<double> cellAreas(const Input& in, FillRule fill, int lo, int hi) {
  std::vector<double> area(in.polygons.size(), 0);
  for (int cx = lo; cx < hi; ++cx)
    for (int cy = lo; cy < hi; ++cy)
      for (std::size_t i = 0; i < in.polygons.size(); ++i)
        area[i] += inside(in.polygons[i], fill, cx + 0.5, cy + 0.5);
  return area;
}

Input islandInLakeInIsland() {
  Input in;
  in.points = {-20, -20, 120, -20, 120, 120, -20, 120, 50, 50, 10, 90};
  // Ids out of nesting order, so that no order of ids gives the innermost by accident.
  in.polygons = {{{rectangle(0, 0, 100, 100)}},
                 {{rectangle(20, 20, 80, 80, false)}},
                 {{rectangle(40, 40, 60, 60)}}};
  in.ids = {1, 2, 0};
  return in;
}

TEST(Regions, NestedPolygonsGiveTheInnermost) {
  const Input in = islandInLakeInIsland();
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    MeshOptions mo;
    mo.fill = fill;
    const Mesh m = run(in, mo);
    std::map<std::int32_t, int> count;
    for (const std::int32_t r : m.regions) ++count[r];
    EXPECT_EQ(count.size(), 4u);  // -1 around, then 1, 2 and 0 inward
    EXPECT_GT(expectLabels(in, fill, m, cellAreas(in, fill, -20, 120)), 20u);
  }
}

TEST(Regions, AHoleBelongsToNoRegionButAnIslandInItDoes) {
  Input in;
  in.polygons = {{{rectangle(0, 0, 100, 100), rectangle(20, 20, 80, 80, false)}},
                 {{rectangle(40, 40, 60, 60)}}};
  in.ids = {0, 1};
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    MeshOptions mo;
    mo.fill = fill;
    const Mesh m = run(in, mo);
    EXPECT_GT(expectLabels(in, fill, m, cellAreas(in, fill, 0, 100)), 10u);
    EXPECT_NE(std::find(m.regions.begin(), m.regions.end(), -1), m.regions.end());
  }
}

// Countries on a 4 x 4 grid of unit squares, some wound each way, so that every shared
// border carries two rings (running opposite ways or the same way), corners touch, and two
// countries have two parts: one with parts side by side (its inner border carries its own two
// rings), one with parts apart.
TEST(Regions, SharedBordersAndTouchingCorners) {
  Input in;
  std::vector<int> owner(16);
  for (int i = 0; i < 16; ++i) owner[i] = i;
  owner[5] = 4;   // country 4: squares 4 and 5, side by side
  owner[15] = 0;  // country 0: squares 0 and 15, apart
  std::map<int, Polygon> byOwner;
  testing::Random r(3);
  for (int i = 0; i < 16; ++i) {
    const double x = i % 4, y = i / 4;
    byOwner[owner[i]].rings.push_back(rectangle(x, y, x + 1, y + 1, r.next() % 2 == 0));
  }
  for (const auto& [id, polygon] : byOwner) {
    in.polygons.push_back(polygon);
    in.ids.push_back(id);
  }
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    MeshOptions mo;
    mo.fill = fill;
    const Mesh m = run(in, mo);
    // Nonzero counts the two parts of country 4 wound opposite ways as they are: still inside.
    const std::size_t checked = expectLabels(in, fill, m, cellAreas(in, fill, 0, 4));
    EXPECT_EQ(checked, m.triangles.size() / 3);
    for (const std::int32_t label : m.regions) EXPECT_GE(label, 0);  // the grid is the hull
  }
}

// Rings that cross: the overlap goes to the smaller polygon, whatever the ids.
TEST(Regions, OverlapGoesToTheSmallerPolygon) {
  Input in;
  in.points = {-5, -5, 20, -5, 20, 20, -5, 20};
  in.polygons = {{{rectangle(5, 5, 13, 13)}}, {{rectangle(0, 0, 10, 10, false)}}};
  in.ids = {7, 3};
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    MeshOptions mo;
    mo.fill = fill;
    const Mesh m = run(in, mo);
    EXPECT_GT(expectLabels(in, fill, m, cellAreas(in, fill, -5, 20)), 10u);
    std::set<std::int32_t> seen(m.regions.begin(), m.regions.end());
    EXPECT_EQ(seen, (std::set<std::int32_t>{-1, 3, 7}));
  }
}

// The same ring given twice: equal area, equal triangles, so the lower id.
TEST(Regions, EqualPolygonsGoToTheLowerId) {
  Input in;
  in.points = {-5, -5, 15, 15};
  in.polygons = {{{rectangle(0, 0, 10, 10)}}, {{rectangle(0, 0, 10, 10, false)}}};
  in.ids = {4, 1};
  const Mesh m = run(in, {});
  std::set<std::int32_t> seen(m.regions.begin(), m.regions.end());
  EXPECT_EQ(seen, (std::set<std::int32_t>{-1, 1}));
}

// Polylines of no polygon, open or closed, constrain but change no label.
TEST(Regions, PolylinesOfNoPolygonChangeNothing) {
  Input in = islandInLakeInIsland();
  const Mesh plain = run(in, {});
  in.extra = {rectangle(10, 10, 90, 30), {-10, 50, 110, 55, 50, 110}, rectangle(45, 45, 55, 55)};
  const Mesh m = run(in, {});
  EXPECT_GT(m.triangles.size(), plain.triangles.size());
  EXPECT_GT(expectLabels(in, FillRule::EvenOdd, m, cellAreas(in, FillRule::EvenOdd, -20, 120)),
            30u);
  // A polyline id past the end of polylinePolygons is of no polygon too.
  MeshOptions mo;
  mo.regions = true;
  mo.polylinePolygons = {0};
  const std::vector<Ring> lines = in.polylines();
  std::vector<PolylineView> views;
  for (const Ring& l : lines) views.push_back({l.data(), l.size() / 2});
  Mesh first;
  ASSERT_TRUE(triangulate(nullptr, 0, views.data(), views.size(), {}, mo, first).ok());
  Input outer;
  outer.polygons = {in.polygons[0]};
  outer.ids = {0};
  outer.extra = {lines.begin() + 1, lines.end()};
  EXPECT_GT(
      expectLabels(outer, FillRule::EvenOdd, first, cellAreas(outer, FillRule::EvenOdd, -20, 120)),
      30u);
}

TEST(Regions, KeepInsideKeepsTheLabelsOfTheKeptTriangles) {
  const Input in = islandInLakeInIsland();
  MeshOptions all, kept;
  kept.keep = Keep::Inside;
  const Mesh a = run(in, all), b = run(in, kept);
  // Even-odd over all rings drops the lake: inside are the outer ring and the island.
  std::map<std::vector<std::uint32_t>, std::int32_t> labelOf;
  for (std::size_t t = 0; t < a.triangles.size() / 3; ++t) {
    std::vector<std::uint32_t> key(a.triangles.begin() + 3 * t, a.triangles.begin() + 3 * t + 3);
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    labelOf[key] = a.regions[t];
  }
  ASSERT_EQ(b.regions.size(), b.triangles.size() / 3);
  std::set<std::int32_t> seen;
  for (std::size_t t = 0; t < b.triangles.size() / 3; ++t) {
    std::vector<std::uint32_t> key(b.triangles.begin() + 3 * t, b.triangles.begin() + 3 * t + 3);
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    ASSERT_EQ(labelOf.count(key), 1u);
    EXPECT_EQ(b.regions[t], labelOf[key]);
    seen.insert(b.regions[t]);
  }
  EXPECT_EQ(seen, (std::set<std::int32_t>{0, 1}));
}

// Random integer rectangles, wound either way, grouped into polygons of one to three rings:
// crossings, collinear overlaps, shared corners, nesting and overlaps of every kind. The
// crossings of axis-parallel segments are exact, so the mesh follows the rings exactly.
TEST(Regions, RandomRectanglePolygons) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    testing::Random r(seed);
    Input in;
    const auto coordinate = [&r] { return static_cast<double>(r.next() % 25); };
    const int polygons = 3 + static_cast<int>(r.next() % 8);
    for (int i = 0; i < polygons; ++i) {
      Polygon p;
      const int rings = 1 + static_cast<int>(r.next() % 3);
      for (int k = 0; k < rings; ++k) {
        double x0 = coordinate(), x1 = coordinate(), y0 = coordinate(), y1 = coordinate();
        if (x0 == x1) x1 += 1;
        if (y0 == y1) y1 += 1;
        p.rings.push_back(rectangle(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1),
                                    std::max(y0, y1), r.next() % 2 == 0));
      }
      in.polygons.push_back(p);
      in.ids.push_back(i);
    }
    for (std::size_t i = in.ids.size() - 1; i > 0; --i)  // shuffled ids
      std::swap(in.ids[i], in.ids[r.next() % (i + 1)]);
    if (seed % 3 == 0) in.extra.push_back(rectangle(2, 3, 20, 21));  // of no polygon
    for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      MeshOptions mo;
      mo.fill = fill;
      const Mesh m = run(in, mo);
      EXPECT_EQ(testing::checkTriangulation(m), "");
      EXPECT_GT(expectLabels(in, fill, m, cellAreas(in, fill, 0, 26)), 10u) << "seed " << seed;
    }
  }
}

// The incremental path: rings inserted one call at a time, then points landing exactly on
// their edges (which splits constrained edges inside a batch), then a ring overlapping
// another one's edges and crossing the rest.
TEST(Regions, IncrementalInsertionsKeepEachRingsShare) {
  Triangulation t;
  Input in;
  in.polygons = {{{rectangle(0, 0, 10, 10)}},
                 {{rectangle(10, 0, 20, 10, false)}},
                 {{rectangle(5, 5, 15, 15)}}};
  in.ids = {0, 1, 2};
  const std::vector<double> frame = {-5, -5, 25, -5, 25, 25, -5, 25};
  ASSERT_TRUE(t.insertPoints(frame.data(), 4).ok());
  ASSERT_TRUE(t.insertPolyline(in.polygons[0].rings[0].data(), 5).ok());
  ASSERT_TRUE(t.insertPolyline(in.polygons[1].rings[0].data(), 5).ok());
  const std::vector<double> onEdges = {10, 3, 10, 7, 4, 0, 16, 10, 10, 5};
  ASSERT_TRUE(t.insertPoints(onEdges.data(), 5).ok());
  ASSERT_TRUE(t.insertPolyline(in.polygons[2].rings[0].data(), 5).ok());
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    MeshOptions mo;
    mo.fill = fill;
    mo.regions = true;
    mo.polylinePolygons = {0, 1, 2};
    const Mesh m = t.mesh(mo);
    EXPECT_GT(expectLabels(in, fill, m, cellAreas(in, fill, -5, 25)), 20u);
  }
}

TEST(Regions, OnlyWhenAskedFor) {
  const Input in = islandInLakeInIsland();
  const std::vector<Ring> lines = in.polylines();
  std::vector<PolylineView> views;
  for (const Ring& l : lines) views.push_back({l.data(), l.size() / 2});
  Mesh m;
  ASSERT_TRUE(triangulate(nullptr, 0, views.data(), views.size(), {}, {}, m).ok());
  EXPECT_TRUE(m.regions.empty());
  EXPECT_TRUE(m.values.empty());
  MeshOptions mo;
  mo.regions = true;  // no polygons: every triangle outside all of them
  ASSERT_TRUE(triangulate(nullptr, 0, views.data(), views.size(), {}, mo, m).ok());
  ASSERT_EQ(m.regions.size(), m.triangles.size() / 3);
  EXPECT_TRUE(std::all_of(m.regions.begin(), m.regions.end(), [](int r) { return r == -1; }));
}

// Every vertex added where constraints cross derives its values from the ends of the input
// segments through it; crossings lie on them exactly here (axis-parallel and diagonal lines
// through integer points).
TEST(Regions, CrossingsDeriveValuesFromTheSegmentsThroughThem) {
  const std::vector<Ring> lines = {{0, 0, 8, 0, 8, 8}, {4, -2, 4, 10}, {-1, -1, 9, 9}};
  std::vector<PolylineView> views;
  for (const Ring& l : lines) views.push_back({l.data(), l.size() / 2});
  const std::vector<double> free = {20, 20, -20, 5};
  std::vector<double> values = {0, 0};
  for (const Ring& l : lines)
    for (std::size_t i = 0; i < l.size(); i += 2) values.push_back(l[i] + 2 * l[i + 1]);
  Mesh m;
  std::vector<std::uint32_t> ids;
  ASSERT_TRUE(
      triangulate(free.data(), 2, views.data(), views.size(), {}, {}, m, &ids, values.data()).ok());
  ASSERT_EQ(m.values.size(), m.points.size() / 2);
  // (4, 0) and (4, 4); the diagonal meets the first line at its points.
  ASSERT_EQ(m.derivedVertices.size(), 2u);
  for (std::size_t i = 0; i < m.derivedVertices.size(); ++i) {
    const std::uint32_t v = m.derivedVertices[i];
    EXPECT_EQ(std::find(ids.begin(), ids.end(), v), ids.end());
    const double x = m.points[2 * v], y = m.points[2 * v + 1];
    EXPECT_EQ(m.values[v], x + 2 * y);
    const std::uint32_t from = m.derivedOffsets[i], to = m.derivedOffsets[i + 1];
    ASSERT_EQ(to - from, 4u) << "two segments through vertex " << v;
    for (std::uint32_t j = from; j < to; j += 2) {
      const std::uint32_t a = m.derivedParents[j], b = m.derivedParents[j + 1];
      const double* pa = &m.points[2 * a];
      const double* pb = &m.points[2 * b];
      EXPECT_EQ(orient2d(pa[0], pa[1], pb[0], pb[1], x, y), Sign::Zero) << "vertex " << v;
      EXPECT_EQ(m.derivedWeights[j] + m.derivedWeights[j + 1], 0.5);
    }
  }
}

}  // namespace
}  // namespace geocdt
