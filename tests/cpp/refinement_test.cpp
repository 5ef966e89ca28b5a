// Delaunay refinement: valid constrained Delaunay triangulations with their input intact,
// every triangle within the bounds except those the stats own up to, Steiner records that
// place their vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"
#include "refinement_checks.h"

namespace geocdt {
namespace {

using testing::Polylines;

constexpr double kPi = 3.14159265358979323846;

struct Refined {
  Status status;
  Mesh mesh;
  Stats stats;
  std::vector<std::uint32_t> ids;
};

// Points, then polylines, refined, exported with inside flags and all triangles.
Refined refine(const std::vector<double>& points, const Polylines& lines, RefineOptions ro,
               const Options& options = Options()) {
  Refined r;
  Triangulation t(options);
  r.ids.resize(points.size() / 2);
  r.status = t.insertPoints(points.data(), points.size() / 2, r.ids.data());
  std::vector<PolylineView> views;
  std::size_t count = 0;
  for (const auto& l : lines) {
    views.push_back({l.data(), l.size() / 2});
    count += l.size() / 2;
  }
  std::vector<std::uint32_t> lineIds(count);
  if (r.status.ok()) r.status = t.insertPolylines(views.data(), views.size(), lineIds.data());
  r.ids.insert(r.ids.end(), lineIds.begin(), lineIds.end());
  if (r.status.ok()) r.status = t.refine(ro);
  MeshOptions mo;
  mo.insideFlags = true;
  mo.fill = ro.fill;
  r.mesh = t.mesh(mo);
  r.stats = t.stats();
  return r;
}

std::vector<double> circle(double cx, double cy, double radius, int n) {
  std::vector<double> ring;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * kPi * (i % n) / n;
    ring.push_back(cx + radius * std::cos(a));
    ring.push_back(cy + radius * std::sin(a));
  }
  return ring;
}

const Polylines kSquareWithHole = {{0, 0, 10, 0, 10, 10, 0, 10, 0, 0}, circle(5, 5, 2, 24)};

TEST(Refinement, SquareWithAHoleInsideAtSeveralAngles) {
  for (const double angle : {0.0, 20.0, 25.0, 30.0, 33.0}) {
    RefineOptions ro;
    ro.minAngle = angle;
    ro.keep = Keep::Inside;
    const Refined r = refine({}, kSquareWithHole, ro);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_FALSE(r.stats.refineCapped) << angle;
    EXPECT_EQ(r.stats.refineSkipped, 0u) << angle;
    EXPECT_EQ(r.stats.steinerPoints, r.mesh.steiner.size());
    EXPECT_EQ(testing::checkRefined(r.mesh, {}, kSquareWithHole, r.ids, angle, 0, true, 0), "")
        << angle;
  }
}

TEST(Refinement, InsideOnlyLeavesTheOutsideAlone) {
  RefineOptions ro;
  ro.minAngle = 30;
  ro.keep = Keep::Inside;
  const Refined r = refine({}, kSquareWithHole, ro);
  ASSERT_TRUE(r.status.ok());
  // No Steiner vertex inside the hole (the outside): its triangles are those of its ring.
  for (const std::uint32_t v : r.mesh.steiner) {
    const double dx = r.mesh.points[2 * v] - 5, dy = r.mesh.points[2 * v + 1] - 5;
    EXPECT_GT(dx * dx + dy * dy, 2 * 2 * 0.98) << v;
  }
  EXPECT_GT(r.mesh.steiner.size(), 0u);
  // keep all refines the hole as well.
  ro.keep = Keep::All;
  const Refined all = refine({}, kSquareWithHole, ro);
  EXPECT_GT(all.mesh.steiner.size(), r.mesh.steiner.size());
  EXPECT_EQ(testing::checkRefined(all.mesh, {}, kSquareWithHole, all.ids, 30, 0, false, 0), "");
}

TEST(Refinement, MaximumArea) {
  RefineOptions ro;
  ro.minAngle = 20;
  ro.maxArea = 0.05;
  ro.keep = Keep::Inside;
  const Refined r = refine({}, kSquareWithHole, ro);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.stats.refineSkipped, 0u);
  EXPECT_EQ(testing::checkRefined(r.mesh, {}, kSquareWithHole, r.ids, 20, 0.05, true, 0), "");
  // Area alone, no angle bound.
  ro.minAngle = 0;
  const Refined a = refine({}, kSquareWithHole, ro);
  EXPECT_EQ(testing::checkRefined(a.mesh, {}, kSquareWithHole, a.ids, 0, 0.05, true, 0), "");
  EXPECT_GT(a.mesh.steiner.size(), 100u);
}

// maxArea holds on every triangle, in corners of small input angles too (as Triangle's -a):
// there a triangle keeps its small angle, but not its size. Fans of segments from one vertex
// at 2 to 15 degrees, and two segments crossing at 3 degrees, inside a square.
TEST(Refinement, MaximumAreaInSmallAngleCorners) {
  for (const double degrees : {2.0, 5.0, 10.0, 15.0}) {
    SCOPED_TRACE(degrees);
    Polylines lines = {{0, 0, 100, 0, 100, 100, 0, 100, 0, 0}};
    const double step = degrees * 3.14159265358979323846 / 180;
    for (int k = 1; k <= 3; ++k)
      lines.push_back({10, 10, 10 + 80 * std::cos(k * step), 10 + 80 * std::sin(k * step)});
    lines.push_back({5, 60, 95, 60 + 90 * std::tan(3 * 3.14159265358979323846 / 180)});
    for (const double angle : {20.0, 30.0}) {
      RefineOptions ro;
      ro.minAngle = angle;
      ro.maxArea = 2;
      ro.keep = Keep::Inside;
      const Refined r = refine({}, lines, ro);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      EXPECT_FALSE(r.stats.refineCapped);
      EXPECT_GT(r.stats.refineSkipped, 0u) << "the corners keep their small angles";
      EXPECT_EQ(testing::countBadTriangles(r.mesh, 0, ro.maxArea, true), 0u) << angle;
      EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, angle, ro.maxArea, true,
                                      r.stats.refineSkipped),
                "")
          << angle;
    }
  }
}

// A triangle too large whose circumcentre lies across a subsegment that may not be split (an
// input segment ulps away runs along it: overlapping_segments.h) is split at its centroid:
// before, such triangles stayed larger than maxArea (5 of them here; 2 on the Natural Earth
// 50m rings at 30 degrees and 0.05 square degrees).
TEST(Refinement, MaximumAreaWhereTheCircumcentreIsBlocked) {
  for (const double apart : {1e-15, 4e-15, 1e-14}) {
    SCOPED_TRACE(apart);
    const Polylines lines = {
        {-5, -5, 15, -5, 15, 5, -5, 5, -5, -5}, {0, 0, 10, 0}, {0, 0, 10, apart}};
    RefineOptions ro;
    ro.minAngle = 20;
    ro.maxArea = 0.5;
    ro.keep = Keep::Inside;
    const Refined r = refine({5, -0.5}, lines, ro);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(testing::countBadTriangles(r.mesh, 0, ro.maxArea, true), 0u);
    EXPECT_EQ(testing::countBadTriangles(r.mesh, ro.minAngle, 0, true), r.stats.refineSkipped);
  }
}

TEST(Refinement, LatticesAndRandomPoints) {
  const Polylines box = {{-1, -1, 64, -1, 64, 64, -1, 64, -1, -1}};
  for (const auto& points : {testing::latticePoints(24), testing::uniformPoints(2000, 3),
                             testing::gaussianClusters(2000, 4)}) {
    // Points in [0, 1)^2 or on the lattice: scale the random ones into the box.
    std::vector<double> p = points;
    if (p[2] < 1) p = testing::transformed(points, 32, 8, 8);
    RefineOptions ro;
    ro.minAngle = 28;
    const Refined r = refine(p, box, ro);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_FALSE(r.stats.refineCapped);
    EXPECT_EQ(testing::checkRefined(r.mesh, p, box, r.ids, 28, 0, false, 0), "");
  }
}

// Points alone: the convex hull bounds the domain. A split point on a hull edge must keep
// the hull convex without wrapping it round earlier vertices; where rounding leaves no such
// double, the edge stays, and its triangles are counted.
TEST(Refinement, PointsAloneRefineTheirConvexHull) {
  const std::vector<double> p = testing::uniformPoints(500, 9);
  RefineOptions ro;
  ro.minAngle = 25;
  const Refined r = refine(p, {}, ro);
  ASSERT_TRUE(r.status.ok());
  EXPECT_FALSE(r.stats.refineCapped);
  EXPECT_LT(r.stats.refineSkipped * 10, r.mesh.triangles.size() / 3);
  EXPECT_EQ(testing::checkRefined(r.mesh, p, {}, r.ids, 25, 0, false, r.stats.refineSkipped), "");
  // An axis-aligned hull splits exactly: nothing is left.
  const std::vector<double> lattice = testing::latticePoints(12);
  const Refined l = refine(lattice, {}, ro);
  EXPECT_EQ(l.stats.refineSkipped, 0u);
  EXPECT_EQ(testing::checkRefined(l.mesh, lattice, {}, l.ids, 25, 0, false, 0), "");
}

// A fan of segments from one vertex, a degree apart: the angles between them cannot be
// mended; refinement ends anyway, owning up to what it left in the fan.
TEST(Refinement, TinyInputAnglesEndAndAreCounted) {
  Polylines lines;
  for (int i = 0; i < 6; ++i) {
    const double a = (40 + i) * kPi / 180;
    lines.push_back({0, 0, 100 * std::cos(a), 100 * std::sin(a)});
  }
  lines.push_back({-50, -50, 150, -50, 150, 150, -50, 150, -50, -50});
  RefineOptions ro;
  ro.minAngle = 20;
  const Refined r = refine({}, lines, ro);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_FALSE(r.stats.refineCapped);
  EXPECT_GT(r.stats.refineSkipped, 0u);
  EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, 20, 0, false, r.stats.refineSkipped),
            "");
  // Every triangle left bad has a corner at the fan's apex, or lies within the fan.
  for (std::size_t t = 0; t < r.mesh.triangles.size() / 3; ++t) {
    if (testing::smallestAngle(r.mesh, t) >= 20 * (1 - 1e-9)) continue;
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; ++k) {
      cx += r.mesh.points[2 * r.mesh.triangles[3 * t + k]] / 3;
      cy += r.mesh.points[2 * r.mesh.triangles[3 * t + k] + 1] / 3;
    }
    const double a = std::atan2(cy, cx) * 180 / kPi;
    EXPECT_TRUE(a > 39.5 && a < 45.5) << "a bad triangle at angle " << a;
  }
}

// Small input angles where one segment ends on another (a T-junction: a breakline ending on
// a raster's border) or two cross, so that the apex is not an end of both: refinement leaves
// the angle, owns up to it, and ends with a few Steiner points.
TEST(Refinement, TinyAnglesAtJunctionsAndCrossingsEnd) {
  const Polylines box = {{-50, -50, 150, -50, 150, 150, -50, 150, -50, -50}};
  const std::vector<Polylines> cases = {
      {{0, -20, 0, 100}, {0.9, 0, 0, 50}},               // ends on the other, 1 degree
      {{0, -20, 0, 100}, {0.0096, 17, 0, 18}},           // ends on the other, 0.55 degrees
      {{0, -20, 0, 100}, {-0.9, -40, 0.9, 60}},          // crosses it, 1 degree
      {{-40, -40, 140, 140}, {-40.5, -40, 140.5, 140}},  // crosses it, 0.3 degrees
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    Polylines lines = box;
    lines.insert(lines.end(), cases[i].begin(), cases[i].end());
    RefineOptions ro;
    ro.minAngle = 20;
    const Refined r = refine({}, lines, ro);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_FALSE(r.stats.refineCapped);
    EXPECT_GT(r.stats.refineSkipped, 0u);
    // 91, 48, 208 and 1001 points; 3808, 5826, 7279 and unending before the crossings counted
    EXPECT_LT(r.stats.steinerPoints, 2000u);
    EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, 20, 0, false, r.stats.refineSkipped),
              "");
  }
}

TEST(Refinement, TheCapStopsItAndSaysSo) {
  RefineOptions ro;
  ro.minAngle = 30;
  ro.maxSteinerPoints = 7;
  ro.keep = Keep::Inside;
  const Refined r = refine({}, kSquareWithHole, ro);
  ASSERT_TRUE(r.status.ok());
  EXPECT_TRUE(r.stats.refineCapped);
  EXPECT_EQ(r.mesh.steiner.size(), 7u);
  EXPECT_GT(r.stats.refineSkipped, 0u);
  EXPECT_EQ(
      testing::checkRefined(r.mesh, {}, kSquareWithHole, r.ids, 30, 0, true, r.stats.refineSkipped),
      "");
  // Beyond the proven angle with no cap given, a default cap still ends it.
  ro.maxSteinerPoints = 0;
  ro.minAngle = 45;
  const Refined d = refine({}, kSquareWithHole, ro);
  ASSERT_TRUE(d.status.ok());
  EXPECT_TRUE(d.stats.refineCapped);
  EXPECT_EQ(testing::checkRefined(d.mesh, {}, kSquareWithHole, d.ids, 0, 0, true, 0), "");
}

TEST(Refinement, SteinerPointsOnConstraintsKeepProvenance) {
  // Two overlapping polylines along y = 0 and a third crossing: the split edges keep all.
  const Polylines lines = {{0, 0, 10, 0},
                           {2, 0, 8, 0},
                           {5, -1, 5, 3},
                           {0, 0.1, 10, 0.1},
                           {-2, -2, 12, -2, 12, 4, -2, 4, -2, -2}};
  RefineOptions ro;
  ro.minAngle = 30;
  const Refined r = refine({}, lines, ro);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, 30, 0, false, 0), "");
  // Constrained edges between x = 2 and 8 on y = 0 list polylines 0 and 1.
  const Mesh& m = r.mesh;
  int shared = 0;
  for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
    const std::uint32_t e = m.constraintEdges[i];
    const std::uint32_t a = m.triangles[e], b = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
    if (m.points[2 * a + 1] != 0 || m.points[2 * b + 1] != 0) continue;
    const double mid = 0.5 * (m.points[2 * a] + m.points[2 * b]);
    const std::size_t n = m.sourceOffsets[i + 1] - m.sourceOffsets[i];
    EXPECT_EQ(n, mid > 2 && mid < 8 ? 2u : 1u) << mid;
    shared += n == 2;
  }
  EXPECT_GT(shared, 2);
}

TEST(Refinement, AgainAfterMoreInsertions) {
  Triangulation t;
  const std::vector<double> ring = kSquareWithHole[0];
  ASSERT_TRUE(t.insertPolyline(ring.data(), ring.size() / 2).ok());
  RefineOptions ro;
  ro.minAngle = 25;
  ASSERT_TRUE(t.refine(ro).ok());
  const std::size_t first = t.stats().steinerPoints;
  const std::vector<double> more = testing::transformed(testing::uniformPoints(50, 2), 10, 0, 0);
  ASSERT_TRUE(t.insertPoints(more.data(), more.size() / 2).ok());
  const std::vector<double> line = {1, 1, 9, 2};
  ASSERT_TRUE(t.insertPolyline(line.data(), 2).ok());
  ASSERT_TRUE(t.refine(ro).ok());
  EXPECT_GT(t.stats().steinerPoints, first);
  MeshOptions mo;
  mo.insideFlags = true;
  const Mesh m = t.mesh(mo);
  EXPECT_EQ(testing::checkTriangulation(m), "");
  EXPECT_EQ(testing::countBadTriangles(m, 25, 0, false), 0u);
  EXPECT_EQ(m.steiner.size(), t.stats().steinerPoints);
}

TEST(Refinement, OneShotTriangulateRefinesBeforeExport) {
  std::vector<PolylineView> views;
  for (const auto& l : kSquareWithHole) views.push_back({l.data(), l.size() / 2});
  RefineOptions ro;
  ro.minAngle = 30;
  MeshOptions mo;
  mo.keep = Keep::Inside;
  Mesh m;
  ASSERT_TRUE(
      triangulate(nullptr, 0, views.data(), views.size(), {}, mo, m, nullptr, nullptr, &ro).ok());
  EXPECT_GT(m.steiner.size(), 0u);
  for (std::size_t t = 0; t < m.triangles.size() / 3; ++t)
    EXPECT_GE(testing::smallestAngle(m, t), 30 * (1 - 1e-9));
}

TEST(Refinement, InvalidOptionsChangeNothing) {
  Triangulation t;
  const std::vector<double> ring = kSquareWithHole[0];
  ASSERT_TRUE(t.insertPolyline(ring.data(), ring.size() / 2).ok());
  for (const double angle : {-1.0, 60.0, std::nan("")}) {
    RefineOptions ro;
    ro.minAngle = angle;
    EXPECT_EQ(t.refine(ro).code, StatusCode::InvalidArgument);
  }
  RefineOptions ro;
  ro.maxArea = -1;
  EXPECT_EQ(t.refine(ro).code, StatusCode::InvalidArgument);
  EXPECT_EQ(t.vertexCount(), 4u);
  // Nothing to refine: no triangles yet.
  Triangulation empty;
  EXPECT_TRUE(empty.refine({}).ok());
}

TEST(Refinement, ScaleFreeFromTinyToHugeCoordinates) {
  for (const double scale : {0x1p-30, 1.0, 0x1p40}) {
    Polylines lines;
    for (const auto& l : kSquareWithHole)
      lines.push_back(testing::transformed(l, scale, 3 * scale, 0));
    RefineOptions ro;
    ro.minAngle = 30;
    ro.keep = Keep::Inside;
    const Refined r = refine({}, lines, ro);
    ASSERT_TRUE(r.status.ok());
    EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, 30, 0, true, 0), "") << scale;
  }
}

TEST(Refinement, LargeCavitiesOnAManySidedRing) {
  // Nearly cocircular vertices: the first Steiner points' cavities hold most of the ring's
  // triangles, past the short list the cavity search starts with.
  const Polylines lines = {circle(0, 0, 100, 400), circle(0, 0, 30, 7)};
  for (const Keep keep : {Keep::Inside, Keep::All}) {
    RefineOptions ro;
    ro.minAngle = 30;
    ro.keep = keep;
    const Refined r = refine({}, lines, ro);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_FALSE(r.stats.refineCapped);
    EXPECT_GT(r.mesh.steiner.size(), 400u);
    EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, 30, 0, keep == Keep::Inside,
                                    r.stats.refineSkipped),
              "");
  }
}

TEST(Refinement, WindingsKeptThroughRefinementMatchAFreshFlood) {
  // The export takes refinement's own windings; a change after it (here a duplicate point,
  // which adds nothing) makes the export flood them again. Both must give the same inside.
  // The square winds clockwise: with non-zero, the circles' overlaps with it cancel to holes.
  const Polylines lines = {circle(5, 5, 4, 40),
                           circle(8, 5, 3, 30),
                           circle(5, 5, 1, 12),
                           {0, 0, 1, 12, 11, 11, 12, 1, 0, 0}};
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero})
    for (const Keep keep : {Keep::Inside, Keep::All}) {
      Triangulation t;
      for (const auto& l : lines) ASSERT_TRUE(t.insertPolyline(l.data(), l.size() / 2).ok());
      RefineOptions ro;
      ro.minAngle = 30;
      ro.keep = keep;
      ro.fill = fill;
      ASSERT_TRUE(t.refine(ro).ok());
      MeshOptions mo;
      mo.insideFlags = true;
      mo.fill = fill;
      const Mesh kept = t.mesh(mo);
      ASSERT_TRUE(t.insertPoints(lines[0].data(), 1).ok());
      const Mesh flooded = t.mesh(mo);
      ASSERT_EQ(kept.triangles, flooded.triangles);
      EXPECT_EQ(kept.inside, flooded.inside);
      std::size_t inside = 0;
      for (const std::uint8_t f : kept.inside) inside += f;
      EXPECT_GT(inside, 0u);
      EXPECT_LT(inside, kept.inside.size());
      mo.keep = Keep::Inside;
      EXPECT_EQ(t.mesh(mo).triangles.size(), 3 * inside);
    }
}

}  // namespace
}  // namespace geocdt

namespace geocdt {
namespace {

TEST(Refinement, SteinerVerticesInterpolateTheValues) {
  // A linear function given at the input points (a square ring and points inside) must come
  // out exactly linear at every Steiner vertex, on constrained edges and inside alike.
  const auto f = [](double x, double y) { return 3.0 * x - 2.0 * y + 7.0; };
  Options options;
  options.valuesPerPoint = 1;
  Triangulation t(options);
  std::vector<double> xy = testing::uniformPoints(200, 5);
  std::vector<double> values;
  for (std::size_t i = 0; i < xy.size(); i += 2) values.push_back(f(xy[i], xy[i + 1]));
  ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2, nullptr, values.data()).ok());
  const std::vector<double> ring{-0.5, -0.5, 1.5, -0.5, 1.5, 1.5, -0.5, 1.5, -0.5, -0.5};
  std::vector<double> ringValues;
  for (std::size_t i = 0; i < ring.size(); i += 2) ringValues.push_back(f(ring[i], ring[i + 1]));
  ASSERT_TRUE(t.insertPolyline(ring.data(), ring.size() / 2, nullptr, ringValues.data()).ok());
  RefineOptions ro;
  ro.minAngle = 30;
  ASSERT_TRUE(t.refine(ro).ok());
  const Mesh m = t.mesh();
  ASSERT_FALSE(m.steiner.empty());
  ASSERT_EQ(m.values.size(), m.points.size() / 2);
  for (const std::uint32_t v : m.steiner) {
    const double expected = f(m.points[2 * v], m.points[2 * v + 1]);
    EXPECT_NEAR(m.values[v], expected, 1e-12 * 16) << "Steiner vertex " << v;
  }
}

}  // namespace
}  // namespace geocdt

namespace geocdt {
namespace {

TEST(Refinement, AreaOfATriangleWithSidesHundredsOfOrdersApart) {
  // A side of 4e58 across from a subnormal height (fuzz, seed 9205): the area measured in a
  // frame scaled to the longest side was 0, so a triangle of area 7e-261 passed a maxArea
  // of 1.4e-262 uncounted. With one Steiner point allowed, what is left over is counted.
  const std::vector<double> points = {4.3933631939690594e+58,  0, 3.6648815163398159e-179,
                                      3.2257546016974987e-319, 0, 0};
  RefineOptions ro;
  ro.minAngle = 0;
  ro.maxArea = 1.4171911539874115e-262;
  ro.maxSteinerPoints = 1;
  Options o;
  o.gridDensity = 2;
  const Refined r = refine(points, {}, ro, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_GE(r.stats.refineSkipped, 1u);
  EXPECT_EQ(testing::checkRefined(r.mesh, points, {}, r.ids, ro.minAngle, ro.maxArea, false,
                                  r.stats.refineSkipped),
            "");
}

TEST(Refinement, ASplitStaysInOrderAlongEverySegmentOfItsEdge) {
  // Fuzz (refine, in CI): segments 0 and 1 part at vertex 1 (x 3.3e-304, y subnormal) and
  // both chains run through vertex 4, within their bounds of them, so edge 1-4 lies on
  // both. Its split point, placed from segment 0's ends 1e67 apart, fell next to vertex 1
  // with a subnormal y one ulp up: strictly between the ends along segment 0, behind vertex 1
  // along segment 1, whose chain then went back and forth. (A cap of 1, the finding itself,
  // is replayed from tests/fuzz/corpus/fuzz_refine.)
  Polylines lines = {{-1.4262809271217239e+67, 3.4034399518420463e-304, 3.3042031719858117e-304,
                      4.751695953872378e-312, -4.0917418857736508e+149, -601603585.85159075,
                      -595821443.5137254, -595821443.5137254, -595821443.5137254,
                      3.3042031719857939e-304, -1.3611369490239656e+67, 3.427629824588232e-319}};
  for (int k = 0; k < 10; ++k) lines[0].insert(lines[0].end(), {0.0, 0.0});
  lines[0].insert(lines[0].end(), {lines[0][0], lines[0][1]});
  Options o;
  o.order = InsertionOrder::Input;
  o.start = LocateStart::LastTriangle;
  o.gridDensity = 2;
  for (const std::uint64_t cap : {4, 64}) {
    RefineOptions ro;
    ro.minAngle = 0;
    ro.maxSteinerPoints = cap;
    const Refined r = refine({}, lines, ro, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(testing::checkRefined(r.mesh, {}, lines, r.ids, ro.minAngle, 0, false,
                                    r.stats.refineSkipped),
              "")
        << "cap " << cap;
  }
}

}  // namespace
}  // namespace geocdt
