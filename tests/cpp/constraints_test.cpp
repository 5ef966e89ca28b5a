// Constrained triangulation: polylines of any form, checked by both halves of the checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>

#include "constraint_invariants.h"
#include "constraints/present_segments.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

using testing::Polylines;

struct Result {
  Status status;
  Mesh mesh;
  std::vector<std::uint32_t> ids;
};

Result run(const std::vector<double>& points, const Polylines& lines, const MeshOptions& mo = {},
           const Options& options = {}) {
  std::vector<PolylineView> views;
  for (const auto& l : lines) views.push_back({l.data(), l.size() / 2});
  Result r;
  r.status = triangulate(points.data(), points.size() / 2, views.data(), views.size(), options, mo,
                         r.mesh, &r.ids);
  return r;
}

// Runs the whole checker; returns "" when everything holds.
std::string check(const std::vector<double>& points, const Polylines& lines,
                  const Options& options = {}) {
  Result r = run(points, lines, {}, options);
  if (!r.status.ok()) return "status: " + r.status.message;
  std::vector<double> input(points);
  for (const auto& l : lines) input.insert(input.end(), l.begin(), l.end());
  testing::CheckOptions c;
  c.inputXY = &input;
  c.inputToVertex = &r.ids;
  std::string s = testing::checkTriangulation(r.mesh, c);
  if (!s.empty()) return s;
  const std::vector<std::uint32_t> lineIds(r.ids.begin() + points.size() / 2, r.ids.end());
  return testing::checkConstraints(r.mesh, lines, lineIds);
}

Polylines scaled(const Polylines& lines, double scale, double dx, double dy) {
  Polylines out;
  for (const auto& l : lines) out.push_back(testing::transformed(l, scale, dx, dy));
  return out;
}

TEST(Constraints, OneSegmentAcrossRandomPoints) {
  const std::vector<double> pts = testing::uniformPoints(2000, 1);
  EXPECT_EQ(check(pts, {{0.01, 0.02, 0.98, 0.97}}), "");
  EXPECT_EQ(check(pts, {{0.5, 0.0, 0.5, 1.0}, {0.0, 0.5, 1.0, 0.5}}), "");
}

TEST(Constraints, StarOf64SegmentsThroughOnePoint) {
  Polylines rays, diameters;
  for (int i = 0; i < 64; ++i) {
    const double a = 2 * M_PI * i / 64, x = std::cos(a), y = std::sin(a);
    rays.push_back({0, 0, x, y});
    if (i < 32) diameters.push_back({x, y, -x, -y});  // all cross at the origin, not an input point
  }
  EXPECT_EQ(check(testing::uniformPoints(300, 2), rays), "");
  EXPECT_EQ(check({}, diameters), "");
  EXPECT_EQ(check(testing::transformed(testing::uniformPoints(300, 3), 2, -1, -1), diameters), "");
}

TEST(Constraints, CollinearOverlappingChains) {
  const Polylines lines = {{0, 0, 10, 0}, {2, 0, 5, 0, 12, 0}, {-3, 0, 1, 0, 1, 0, 7, 0},
                           {0, 0, 10, 0}, {5, -5, 5, 5},       {0, 0, 5, 5, 10, 10},
                           {3, 3, 8, 8}};
  EXPECT_EQ(check({-5, -5, 15, 8, 4, 7, 6, -2}, lines), "");
}

TEST(Constraints, PolylineThatBacktracks) {
  EXPECT_EQ(check({0, 10, 10, -3}, {{0, 0, 6, 6, 2, 2, 9, 9, 1, 1, 4, 1, 0, 0, 9, 9}}), "");
}

TEST(Constraints, RepeatedPointsAndZeroLengthSegments) {
  EXPECT_EQ(check({0, 0, 5, 5}, {{1, 1, 1, 1, 2, 3, 2, 3, 2, 3, 4, 1}, {3, 3}, {2, 2, 2, 2}}), "");
}

TEST(Constraints, ThousandsOfRandomCrossingSegments) {
  testing::Random r(9);
  Polylines lines;
  for (int i = 0; i < 1500; ++i)
    lines.push_back({r.uniform(), r.uniform(), r.uniform(), r.uniform()});
  EXPECT_EQ(check(testing::uniformPoints(1000, 4), lines), "");
}

TEST(Constraints, RandomPolylinesScaledAndOffset) {
  testing::Random r(10);
  Polylines lines;
  for (int i = 0; i < 60; ++i) {
    std::vector<double> l;
    double x = r.uniform(), y = r.uniform();
    for (int k = 0; k < 12; ++k) {
      l.push_back(x);
      l.push_back(y);
      x += (r.uniform() - 0.5) * 0.3;
      y += (r.uniform() - 0.5) * 0.3;
    }
    lines.push_back(l);
  }
  const std::vector<double> pts = testing::uniformPoints(500, 5);
  for (double scale = 1e-9; scale <= 1.01e9; scale *= 100)
    EXPECT_EQ(check(testing::transformed(pts, scale, 0, 0), scaled(lines, scale, 0, 0)), "")
        << scale;
  EXPECT_EQ(check(testing::transformed(pts, 0.37, 1.6e7, 4.2e6), scaled(lines, 0.37, 1.6e7, 4.2e6)),
            "");
  EXPECT_EQ(check(testing::transformed(pts, 1e-6, 1e7, -3e7), scaled(lines, 1e-6, 1e7, -3e7)), "");
}

// Rings: a square with a hole, an island in the hole, a lake in the island; rings that
// share vertices and edges.
Polylines nestedRings() {
  return {
      {0, 0, 10, 0, 10, 10, 0, 10, 0, 0},     // outer
      {2, 2, 8, 2, 8, 8, 2, 8, 2, 2},         // hole
      {3, 3, 7, 3, 7, 7, 3, 7, 3, 3},         // island in the hole
      {4, 4, 6, 4, 6, 6, 4, 6, 4, 4},         // lake in the island
      {10, 0, 14, 0, 14, 10, 10, 10, 10, 0},  // shares an edge with the outer ring
      {14, 10, 16, 12, 12, 12, 14, 10},       // shares a vertex
      {0, 0, 10, 0, 5, -4, 0, 0},             // shares an edge, other side
  };
}

void expectInsideMatchesOracle(const Polylines& rings, const Mesh& m) {
  ASSERT_EQ(m.inside.size(), m.triangles.size() / 3);
  int compared = 0;
  for (std::size_t t = 0; t < m.inside.size(); ++t) {
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += m.points[2 * m.triangles[3 * t + k]] / 3;
      y += m.points[2 * m.triangles[3 * t + k] + 1] / 3;
    }
    if (testing::distanceToPolylines(rings, x, y) < 1e-9) continue;
    EXPECT_EQ(m.inside[t] != 0, testing::insideEvenOdd(rings, x, y))
        << "triangle " << t << " at " << x << "," << y;
    ++compared;
  }
  EXPECT_GT(compared, 0);
}

TEST(Constraints, NestedRingsEvenOdd) {
  const Polylines rings = nestedRings();
  EXPECT_EQ(check(testing::transformed(testing::uniformPoints(400, 6), 20, -3, -5), rings), "");
  MeshOptions mo;
  mo.insideFlags = true;
  Result r = run(testing::transformed(testing::uniformPoints(400, 6), 20, -3, -5), rings, mo);
  ASSERT_TRUE(r.status.ok());
  expectInsideMatchesOracle(rings, r.mesh);
}

TEST(Constraints, KeepInsideDropsOutsideTriangles) {
  const Polylines rings = nestedRings();
  MeshOptions all, inside;
  all.insideFlags = true;
  inside.keep = Keep::Inside;
  Result a = run({}, rings, all), b = run({}, rings, inside);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  std::size_t expected = 0;
  for (const std::uint8_t f : a.mesh.inside) expected += f;
  EXPECT_EQ(b.mesh.triangles.size() / 3, expected);
  EXPECT_GT(expected, 0u);
  // The kept triangles' twins are symmetric and point only at kept triangles.
  for (std::size_t e = 0; e < b.mesh.halfedges.size(); ++e)
    if (b.mesh.halfedges[e] >= 0) {
      EXPECT_EQ(b.mesh.halfedges[b.mesh.halfedges[e]], std::int32_t(e));
    }
}

void expectNonZeroAndEvenOdd(const Polylines& rings, const Options& options);

TEST(Constraints, NonZeroWindingDiffersFromEvenOdd) {
  // Two overlapping squares wound the same way: the overlap has winding 2.
  const Polylines rings = {{0, 0, 4, 0, 4, 4, 0, 4, 0, 0}, {2, 2, 6, 2, 6, 6, 2, 6, 2, 2}};
  // With snap rounding too: the chains it rebuilds keep each ring's winding.
  for (const SnapRounding snap : {SnapRounding::WhenNeeded, SnapRounding::Always}) {
    SCOPED_TRACE(snap == SnapRounding::Always ? "snap-rounded" : "computed crossings");
    Options options;
    options.snapRounding = snap;
    expectNonZeroAndEvenOdd(rings, options);
  }
}

void expectNonZeroAndEvenOdd(const Polylines& rings, const Options& options) {
  MeshOptions eo, nz;
  eo.insideFlags = nz.insideFlags = true;
  nz.fill = FillRule::NonZero;
  Result a = run({}, rings, eo, options), b = run({}, rings, nz, options);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  ASSERT_EQ(a.mesh.triangles, b.mesh.triangles);
  int differ = 0;
  for (std::size_t t = 0; t < a.mesh.inside.size(); ++t) {
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += a.mesh.points[2 * a.mesh.triangles[3 * t + k]] / 3;
      y += a.mesh.points[2 * a.mesh.triangles[3 * t + k] + 1] / 3;
    }
    const bool overlap = x > 2 && x < 4 && y > 2 && y < 4;
    EXPECT_EQ(b.mesh.inside[t] != 0, (x < 4 && y < 4) || (x > 2 && y > 2)) << x << "," << y;
    EXPECT_EQ(a.mesh.inside[t] != 0, ((x < 4 && y < 4) != (x > 2 && y > 2))) << x << "," << y;
    differ += overlap;
  }
  EXPECT_GT(differ, 0);
}

TEST(Constraints, ProvenanceOffsetsHaveOneEntryMoreThanTheEdgesEvenWithNone) {
  // Points alone, and a polyline of one repeated point: no constrained edge, offsets {0}.
  MeshOptions mo;
  mo.segmentSources = true;
  for (const Polylines& lines : {Polylines{}, Polylines{{0, 1, 0, 1, 0, 1}}}) {
    Result r = run({0, 0, 1, 0, 0, 1}, lines, mo);
    ASSERT_TRUE(r.status.ok());
    EXPECT_TRUE(r.mesh.constraintEdges.empty());
    EXPECT_EQ(r.mesh.sourceOffsets, std::vector<std::uint32_t>{0});
    EXPECT_EQ(r.mesh.segmentOffsets, std::vector<std::uint32_t>{0});
  }
  Result r = run({0, 0, 1, 0, 0, 1}, {});
  EXPECT_EQ(r.mesh.sourceOffsets, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(r.mesh.segmentOffsets.empty());  // not asked for
}

TEST(Constraints, ProvenanceListsEveryPolylineOfAnEdge) {
  // Polylines 0 and 1 overlap on 2..5; polyline 2 crosses them at (3, 0).
  const Polylines lines = {{0, 0, 5, 0}, {2, 0, 8, 0}, {3, -1, 3, 1}};
  Result r = run({}, lines);
  ASSERT_TRUE(r.status.ok());
  const Mesh& m = r.mesh;
  ASSERT_EQ(m.sourceOffsets.size(), m.constraintEdges.size() + 1);
  int shared = 0;
  for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
    const std::uint32_t e = m.constraintEdges[i];
    ASSERT_TRUE(m.constrained[e]);
    const std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
    const double x0 = std::min(m.points[2 * u], m.points[2 * v]),
                 x1 = std::max(m.points[2 * u], m.points[2 * v]);
    const bool horizontal = m.points[2 * u + 1] == 0 && m.points[2 * v + 1] == 0;
    std::vector<std::uint32_t> src(m.sources.begin() + m.sourceOffsets[i],
                                   m.sources.begin() + m.sourceOffsets[i + 1]);
    std::sort(src.begin(), src.end());
    std::vector<std::uint32_t> expected;
    if (horizontal && x1 <= 5) expected.push_back(0);
    if (horizontal && x0 >= 2) expected.push_back(1);
    if (!horizontal) expected.push_back(2);
    EXPECT_EQ(src, expected) << "edge " << x0 << ".." << x1;
    shared += src.size() == 2;
  }
  EXPECT_GT(shared, 0);
  // The crossing at (3, 0) is an input vertex of neither horizontal line: it was added.
  EXPECT_EQ(m.points.size() / 2, 7u);
}

TEST(Constraints, IncrementalPointsAndPolylinesStayValid) {
  Triangulation t;
  const std::vector<double> pts = testing::uniformPoints(500, 7);
  ASSERT_TRUE(t.insertPoints(pts.data(), 250).ok());
  const std::vector<double> a = {0.1, 0.1, 0.9, 0.9, 0.9, 0.1}, b = {0.1, 0.9, 0.9, 0.2};
  ASSERT_TRUE(t.insertPolyline(a.data(), 3).ok());
  ASSERT_TRUE(t.insertPoints(pts.data() + 500, 250).ok());  // points after constraints
  ASSERT_TRUE(t.insertPolyline(b.data(), 2).ok());
  const std::vector<double> onEdge = {0.5, 0.5, 0.7, 0.7};  // exactly on constraint a
  ASSERT_TRUE(t.insertPoints(onEdge.data(), 2).ok());
  const Mesh m = t.mesh();
  EXPECT_EQ(testing::checkTriangulation(m), "");
  // Re-derive the polyline vertex ids by exact coordinates for the constraint check.
  std::vector<std::uint32_t> ids;
  for (const auto* l : {&a, &b})
    for (std::size_t k = 0; k < l->size(); k += 2) {
      const Location loc = t.locate((*l)[k], (*l)[k + 1]);
      ASSERT_EQ(loc.kind, Location::Kind::Vertex);
      ids.push_back(loc.vertices[0]);
    }
  EXPECT_EQ(testing::checkConstraints(m, {a, b}, ids), "");
}

TEST(Constraints, PointsLandingOnConstraintsKeepProvenanceAndInside) {
  // Large and small batches of points exactly on an existing ring, copied or in a buffer
  // taken over: the ring's pieces keep their polyline and winding whatever working ids the
  // batch used.
  for (const auto& [extra, adopt] :
       {std::pair<std::size_t, bool>{400, false}, {400, true}, {3, false}, {3, true}}) {
    Triangulation t;
    const std::vector<double> ring = {0, 0, 10, 0, 10, 10, 0, 10, 0, 0};
    const std::vector<double> line = {-5, 5, 15, 5};
    ASSERT_TRUE(t.insertPolyline(ring.data(), 5).ok());
    ASSERT_TRUE(t.insertPolyline(line.data(), 2).ok());
    std::vector<double> xy = testing::transformed(testing::uniformPoints(extra, 3), 20, -5, -5);
    for (int k = 1; k < 20; ++k)
      for (const double v : {k * 0.5, 0.0, 10.0, k * 0.5, k * 0.5, 10.0, 0.0, k * 0.5})
        xy.push_back(v);
    ASSERT_TRUE(
        (adopt ? t.insertPoints(std::move(xy)) : t.insertPoints(xy.data(), xy.size() / 2)).ok());
    MeshOptions mo;
    mo.insideFlags = true;
    const Mesh m = t.mesh(mo);
    EXPECT_EQ(testing::checkTriangulation(m), "");
    for (std::size_t tri = 0; tri < m.inside.size(); ++tri) {
      double x = 0, y = 0;
      for (int k = 0; k < 3; ++k) {
        x += m.points[2 * m.triangles[3 * tri + k]] / 3;
        y += m.points[2 * m.triangles[3 * tri + k] + 1] / 3;
      }
      EXPECT_EQ(m.inside[tri] != 0, x > 0 && x < 10 && y > 0 && y < 10) << x << "," << y;
    }
    ASSERT_EQ(m.sourceOffsets.size(), m.constraintEdges.size() + 1);
    std::size_t onRing = 0;
    for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
      const std::uint32_t e = m.constraintEdges[i];
      const std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
      const bool horizontalLine = m.points[2 * u + 1] == 5 && m.points[2 * v + 1] == 5;
      const std::uint32_t expected =
          horizontalLine && !(m.points[2 * u] == 0 || m.points[2 * u] == 10) ? 1 : 0;
      ASSERT_EQ(m.sourceOffsets[i + 1] - m.sourceOffsets[i], 1u);
      EXPECT_EQ(m.sources[m.sourceOffsets[i]], horizontalLine ? 1u : expected);
      onRing += !horizontalLine;
    }
    EXPECT_GE(onRing, 4u * 20u);  // each side split at its 19 points: 20 pieces
  }
}

// Regressions found by fuzzing, each named after what went wrong: inputs reduced from the
// findings. The findings themselves are in tests/fuzz/corpus, which ctest replays.

TEST(Constraints, FuzzTinyCoordinatesAndHugeSegments) {
  // Products of 1e-171 coordinates underflow in double; a 6e76-long segment must not make
  // every vertex "near" a crossing with a short one.
  std::vector<double> ring = {-7.4036710823662963e-171,
                              -7.4036710823662963e-171,
                              -7.4036710823662963e-171,
                              2.2301954389232176e-266,
                              1.4464930455059793e-208,
                              -7.2663735934183412e-171,
                              0,
                              0,
                              -7.4036710823662963e-171,
                              -7.4036710823662963e-171};
  EXPECT_EQ(check({}, {ring}), "");
  EXPECT_EQ(check({}, {{11, 10, -6.1514547407324216e+76, 20.000000000000224},
                       {1, 0, 1, 20.000000014668331}}),
            "");
}

TEST(Constraints, FuzzCrossingMeasuredFromTheNearEnd) {
  // A 1.3e67-long segment crosses a 7e49-long one 2e-321 from its end: measured from the far
  // end of the long one, the crossing landed 2.6e47 off the short one.
  Options input;
  input.order = InsertionOrder::Input;
  std::vector<double> line = {7.4278671450229415e+49,  7.3787698243938564e+49,
                              7.4278671450229415e+49,  0,
                              7.4278671450230972e+49,  7.4278671450229415e+49,
                              1.3101507285431828e+67,  3.4034399518190365e-304,
                              2.8205219589785083e-319, 0};
  line.insert(line.end(), {0, 0, 0, 0});
  EXPECT_EQ(check({}, {line}, input), "");
  EXPECT_EQ(check({}, {line}), "");
}

TEST(Constraints, FuzzCrossingNotMeasuredAcrossACancellation) {
  // A segment 2.1 long ends next to one 5e-299 long: measured from the short one's end, the
  // crossing's parameter cancelled to nothing and the point fell on that end, off the
  // long segment.
  Options input;
  input.order = InsertionOrder::Input;
  std::vector<double> ring = {-1.030730845916203e-279, 2.1250724792965388,
                              4.7783097445378864e-299, 7.291122070187139e-304,
                              1.6628243732494243e-316, 0};
  ring.insert(ring.end(), {0, 0, -1.030730845916203e-279, 2.1250724792965388});
  const Polylines lines = {
      {11, 5.4323924391225434e-312, 2.064330555345791e-310, -1.0961440264327563e+141},
      {5.2408767532627783e-299, 0, 7.2913862538674818e-304, 1.090607744992117e-299},
      ring};
  EXPECT_EQ(check({}, lines, input), "");
}

TEST(Constraints, FuzzSubnormalCrossingGetsItsOwnVertex) {
  // Two segments among subnormals cross 1.6e-316 from an end: the crossing is a vertex, not
  // a bend through that end (which lies 1.2e-316 off the other segment).
  const Polylines lines = {{3.2049228321345884e-294, 3.4732827106519577e-310,
                            8.2890618685587619e-317, 2.4879282803014709e-316},
                           {1.7767971548758891e-307, 1.8026574931812249e-307, 0, 0}};
  EXPECT_EQ(check({}, lines), "");
  const Result r = run({}, lines);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.mesh.points.size() / 2, 5u);
}

// Tangles: segments among vertices a few ulps apart, where every crossing rounds onto the
// same few doubles. Computed crossings go round in circles there, or would break the
// guarantee; snap rounding takes over, and the checker holds the result to the bound, the
// order along each segment and the crossings.

// Inserts each polyline by its own call (or all in one), checks everything, and returns how
// often the triangulation was snap-rounded (-1 when a call failed).
int snapRoundings(const Polylines& lines, const Options& options, bool oneCall,
                  std::string& broken) {
  Triangulation t(options);
  std::vector<std::uint32_t> ids;
  std::vector<PolylineView> views;
  for (const auto& l : lines) views.push_back({l.data(), l.size() / 2});
  ids.resize(std::accumulate(lines.begin(), lines.end(), std::size_t{0},
                             [](std::size_t n, const auto& l) { return n + l.size() / 2; }));
  std::size_t offset = 0;
  for (std::size_t i = 0; i < views.size(); offset += views[i++].count) {
    if (oneCall) {
      if (!t.insertPolylines(views.data(), views.size(), ids.data()).ok()) return -1;
      break;
    }
    if (!t.insertPolyline(views[i].xy, views[i].count, ids.data() + offset).ok()) return -1;
  }
  MeshOptions mo;
  mo.insideFlags = true;
  mo.segmentSources = true;
  const Mesh m = t.mesh(mo);
  std::vector<double> input;
  for (const auto& l : lines) input.insert(input.end(), l.begin(), l.end());
  testing::CheckOptions c;
  c.inputXY = &input;
  c.inputToVertex = &ids;
  broken = testing::checkTriangulation(m, c);
  if (broken.empty()) broken = testing::checkConstraints(m, lines, ids);
  return static_cast<int>(t.stats().snapRoundings);
}

// Snap-rounded (when needed and always, in one call and a call per polyline) and valid.
void expectSnapRoundedAndValid(const Polylines& lines, Options o) {
  std::string broken;
  for (const bool always : {false, true}) {
    o.snapRounding = always ? SnapRounding::Always : SnapRounding::WhenNeeded;
    for (const bool oneCall : {false, true}) {
      EXPECT_GE(snapRoundings(lines, o, oneCall, broken), 1) << always << oneCall;
      EXPECT_EQ(broken, "") << always << oneCall;
    }
  }
}

TEST(Constraints, TangleWhereComputedCrossingsWouldCrossChains) {
  // Four segments within 4 ulps of (-3.5e-7, -12345.678): computed crossings made the chains
  // of two segments that do not meet cross.
  const Polylines lines = {
      {-3.500000000000001e-07, -12345.677999999998, -3.4999999999999993e-07, -12345.678000000004},
      {-3.500000000000001e-07, -12345.678000000004, -3.5e-07, -12345.678},
      {-3.4999999999999993e-07, -12345.678, -3.500000000000001e-07, -12345.678000000002},
      {-3.5000000000000004e-07, -12345.677999999998, -3.499999999999999e-07, -12345.678000000002}};
  std::string broken;
  EXPECT_EQ(snapRoundings(lines, {}, true, broken), 1);
  EXPECT_EQ(broken, "");
}

TEST(Constraints, TangleWhereComputedCrossingsWouldGoBack) {
  // Within 2 ulps of (1e100, -12345.678): a computed crossing routed a chain back along its
  // segment. Inserted a line a call, as when found; in one call the segments that are edges
  // already go in first (PresentSegments), which here leaves no tangle to snap.
  const Polylines lines = {
      {1.0000000000000002e+100, -12345.678000000002, 1e+100, -12345.677999999996},
      {9.999999999999998e+99, -12345.678, 1.0000000000000004e+100, -12345.678},
      {1.0000000000000002e+100, -12345.678, 1e+100, -12345.678000000004}};
  std::string broken;
  EXPECT_EQ(snapRoundings(lines, {}, false, broken), 1);
  EXPECT_EQ(broken, "");
  EXPECT_GE(snapRoundings(lines, {}, true, broken), 0);
  EXPECT_EQ(broken, "");
}

TEST(Constraints, FuzzCrossingOfBentPiecesCrossesChains) {
  // A ring among subnormals: a piece bent through one crossing met a segment that its input
  // segment misses, and the crossing of the two pieces fit: the chains crossed.
  const double u = std::numeric_limits<double>::denorm_min();
  const Polylines lines = {{-2 * u, -u, 3 * u, 4 * u, u, 0, 2 * u, 0, -3 * u, -3 * u, -u, -3 * u,
                            4 * u, 4 * u, -3 * u, -3 * u}};
  Options o;
  o.order = InsertionOrder::Input;
  o.gridDensity = 2;
  std::string broken;
  // Snap-rounded when found; since crossings round exactly, they resolve it by themselves.
  EXPECT_LE(snapRoundings(lines, o, true, broken), 1);
  EXPECT_EQ(broken, "");
}

TEST(Constraints, FuzzNearlyCollinearLongSegmentsOneCallEach) {
  // Five points of a lattice 1e9 a step, nearly on one line through (1, -12345.678), one
  // polyline a call: an edge held segment 1 and segment 0, bent onto it through a vertex; a
  // crossing of segment 1 split it without a check, though segment 0 does not meet the
  // crossing segment, and the chains of segments 0 and 3 crossed.
  const double ax = 1, ay = -12345.678;
  const Polylines lines = {
      {ax, ay, 4800000001, 1399987654.3220003},
      {ax, ay, 3840000001, 1119987654.322, -8679999999.0000019, 29759987654.321995},
      {18240000001, 5319987654.3219995, 960000001, 279987654.32200003, ax, ay, ax, ay, 18240000001,
       5319987654.3219995}};
  Options o;
  o.order = InsertionOrder::Hilbert;
  o.start = LocateStart::Grid;
  o.gridDensity = 8;
  // In one call or in three, the check finds the crossing chains and snap rounding takes over.
  for (const bool oneCall : {false, true}) {
    std::string broken;
    EXPECT_EQ(snapRoundings(lines, o, oneCall, broken), 1);
    EXPECT_EQ(broken, "");
  }
}

TEST(Constraints, SnapRoundingAcrossBinadeEnds) {
  // Where the spacing of doubles doubles (at 1 and at 2^24), rounding cells are uneven; a
  // vertex left between a segment and its chain joins the chain. Subnormal steps on the
  // other axis.
  const double u = std::numeric_limits<double>::denorm_min(), one = 1, big = 0x1p24;
  const auto below = [](double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, 0.0);
    return v;
  };
  const auto above = [](double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, 2 * v);
    return v;
  };
  const Polylines atOne = {{above(one, 2), 2 * u, below(one, 1), -2 * u, above(one, 1), 2 * u},
                           {below(one, 2), -2 * u, above(one, 1), u},
                           {above(one, 1), u, above(one, 1), -u},
                           {above(one, 1), -u, below(one, 2), -u}};
  const Polylines atBig = {{0, below(big, 2), 2 * u, big},
                           {2 * u, big, -2 * u, below(big, 2)},
                           {-2 * u, below(big, 2), -u, below(big, 1)},
                           {-2 * u, below(big, 1), u, below(big, 2)}};
  Options always;
  always.snapRounding = SnapRounding::Always;
  for (const Polylines* lines : {&atOne, &atBig}) {
    std::string broken;
    EXPECT_EQ(snapRoundings(*lines, always, true, broken), 1);
    EXPECT_EQ(broken, "");
  }
}

TEST(Constraints, SnapRoundingEverywhereKeepsTheGuarantee) {
  // Snap rounding of every call, on inputs that computed crossings handle: the guarantee
  // holds all the same, and rings still decide inside and outside.
  Options always;
  always.snapRounding = SnapRounding::Always;
  testing::Random r(12);
  Polylines random;
  for (int i = 0; i < 200; ++i)
    random.push_back({r.uniform(), r.uniform(), r.uniform(), r.uniform()});
  const Polylines lines = {{0, 0, 10, 0}, {2, 0, 5, 0, 12, 0},  {-3, 0, 1, 0, 1, 0, 7, 0},
                           {5, -5, 5, 5}, {0, 0, 5, 5, 10, 10}, {3, 3, 8, 8}};
  EXPECT_EQ(check(testing::uniformPoints(300, 13), random, always), "");
  EXPECT_EQ(check({-5, -5, 15, 8, 4, 7, 6, -2}, lines, always), "");
  EXPECT_EQ(check({}, scaled(random, 1e-300, 0, 0), always), "");
  EXPECT_EQ(check({}, scaled(random, 3, 1.6e7, -1e9), always), "");
  MeshOptions mo;
  mo.insideFlags = true;
  const Polylines rings = nestedRings();
  Result res =
      run(testing::transformed(testing::uniformPoints(400, 6), 20, -3, -5), rings, mo, always);
  ASSERT_TRUE(res.status.ok());
  expectInsideMatchesOracle(rings, res.mesh);
}

TEST(Constraints, ConstraintsBeforeAnyTriangle) {
  // Collinear points first: the segment waits until a point off the line arrives.
  Triangulation t;
  const std::vector<double> line = {0, 0, 4, 0}, off = {2, 3, 2, -3};
  ASSERT_TRUE(t.insertPolyline(line.data(), 2).ok());
  EXPECT_EQ(t.triangleCount(), 0u);
  ASSERT_TRUE(t.insertPoints(off.data(), 2).ok());
  const Mesh m = t.mesh();
  EXPECT_EQ(testing::checkTriangulation(m), "");
  EXPECT_EQ(testing::checkConstraints(m, {line}, {0, 1}), "");
  int constrained = 0;
  for (const std::uint8_t c : m.constrained) constrained += c;
  EXPECT_EQ(constrained, 2);  // the segment 0-1 crossing the diagonal 2-3
}

TEST(Constraints, PresentSegmentsAreTheExpectedEdges) {
  // New vertices 10..14: triangles 10-11-13 and 11-12-13, the hull edge 11->10 in a ghost
  // triangle, 14 in no triangle. Expected: 10-11, 12-11 (given backwards), 13-14 (no edge),
  // 9-10 (9 is older than the batch), 11-13 (an edge, but not consecutive ids); not expected:
  // 12-13, an edge between consecutive ids.
  Topology topo;
  topo.appendSlots(3);
  topo.setTriangle(0, 10, 11, 13);
  topo.setTriangle(1, 11, 12, 13);
  topo.setTriangle(2, 11, 10, kGhost);
  PresentSegments present(10, 15);
  for (const auto& [u, v] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {10, 11}, {12, 11}, {13, 14}, {9, 10}, {11, 13}})
    present.expect(u, v);
  present.fixPresent(topo);
  // Fixed: 10->11 (slot 0), 11->12 (slot 1), 11->10 (the ghost slot's real edge).
  const std::vector<std::uint8_t> fixed = {1, 0, 0, 1, 0, 0, 1, 0, 0};
  EXPECT_EQ(topo.fixed, fixed);
  EXPECT_TRUE(present.present(10, 11));
  EXPECT_TRUE(present.present(11, 10));
  EXPECT_TRUE(present.present(11, 12));
  EXPECT_FALSE(present.present(13, 12));
  EXPECT_FALSE(present.present(13, 14));
  EXPECT_FALSE(present.present(9, 10));
  EXPECT_FALSE(present.present(11, 13));
  EXPECT_FALSE(present.present(14, 15));  // past the batch
}

TEST(Constraints, SegmentEndsAreNotLocated) {
  // 400 disjoint jittered rings, each visited far from the one before: a segment starts from
  // its first vertex's half-edges, found without a walk, so the constrained call locates
  // only its points (and would locate each crossing it adds; these rings have none).
  Polylines rings;
  std::uint64_t seed = 12345;
  const auto jitter = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) * 0x1p-53 - 0.5;
  };
  for (int k = 0; k < 400; ++k) {
    const int cell = (k * 167) % 400;  // consecutive rings lie far apart
    const double x0 = 10.0 * (cell % 20), y0 = 10.0 * (cell / 20);
    std::vector<double> ring;
    const double corners[5][2] = {{0, 0}, {6, 0}, {6, 6}, {0, 6}, {0, 0}};
    for (int side = 0; side < 4; ++side)
      for (int i = 0; i < 6; ++i) {
        const double t = i / 6.0, dx = corners[side + 1][0] - corners[side][0],
                     dy = corners[side + 1][1] - corners[side][1];
        ring.push_back(x0 + corners[side][0] + t * dx + 0.2 * jitter());
        ring.push_back(y0 + corners[side][1] + t * dy + 0.2 * jitter());
      }
    ring.push_back(ring[0]);
    ring.push_back(ring[1]);
    // First a diagonal between opposite corners, which the ring's triangles cross: it is
    // flipped in, which moves half-edges out of the ring's vertices before the ring comes.
    rings.push_back({ring[0], ring[1], ring[24], ring[25]});
    rings.push_back(ring);
  }
  std::vector<double> all;
  std::vector<PolylineView> views;
  for (const auto& r : rings) {
    all.insert(all.end(), r.begin(), r.end());
    views.push_back({r.data(), r.size() / 2});
  }
  Triangulation points, constrained;
  ASSERT_TRUE(points.insertPoints(all.data(), all.size() / 2).ok());
  std::vector<std::uint32_t> ids(all.size() / 2);
  ASSERT_TRUE(constrained.insertPolylines(views.data(), views.size(), ids.data()).ok());
  EXPECT_EQ(constrained.stats().crossings, 0u);
  EXPECT_GT(constrained.stats().flips, points.stats().flips);  // segments were flipped in
  // The segments that are edges already are marked first (PresentSegments) and no longer
  // refresh their vertices' entries as they go: a flip of a later segment can move an entry's
  // half-edge, found again by a walk from where it was. A few, not one a ring.
  EXPECT_GE(constrained.stats().locates, points.stats().locates);
  EXPECT_LE(constrained.stats().locates, points.stats().locates + rings.size() / 100);
  const Mesh m = constrained.mesh();
  EXPECT_EQ(testing::checkTriangulation(m), "");
  EXPECT_EQ(testing::checkConstraints(m, rings, ids), "");
}

TEST(Constraints, InvalidPolylineNamesItAndInsertsNothing) {
  Triangulation t;
  const std::vector<double> good = {0, 0, 1, 0, 1, 1}, bad = {0, 0, NAN, 1};
  const PolylineView views[] = {{good.data(), 3}, {bad.data(), 2}};
  const Status s = t.insertPolylines(views, 2);
  EXPECT_EQ(s.code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(s.index, 1u);
  EXPECT_EQ(s.segment, 1u);
  EXPECT_NE(s.message.find("polyline 1 point 1"), std::string::npos) << s.message;
  EXPECT_EQ(t.vertexCount(), 0u);
}

TEST(Constraints, OneShotWithNullPolylinesAndACountIsInvalidArgument) {
  const std::vector<double> xy = {0, 0, 1, 0, 0, 1};
  Mesh m;
  m.points = {7, 7};  // left as it was
  std::vector<std::uint32_t> ids = {9};
  const Status s = triangulate(xy.data(), 3, nullptr, 2, {}, {}, m, &ids);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_NE(s.message.find("null polylines"), std::string::npos) << s.message;
  EXPECT_EQ(m.points, (std::vector<double>{7, 7}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{9}));
  // No polylines and a null pointer is the ordinary points-only call.
  EXPECT_TRUE(triangulate(xy.data(), 3, nullptr, 0, {}, {}, m, &ids).ok());
  EXPECT_EQ(m.triangles.size(), 3u);
}

namespace geocdt {
namespace {

// Polylines handed over in one buffer (GeoArrow's layout, as the WebAssembly binding does)
// give the mesh that views of the same coordinates give, with points before them or not:
// crossing rings and lines that share points, a repeated point, an empty polyline.
TEST(Constraints, SegmentSourcesNameEachEdgesInputSegments) {
  // Segments 0 (0,0)-(2,0) and 1 (2,0)-(2,2); 2 (1,-1)-(1,1) crosses 0 at (1,0); the third
  // polyline repeats a point (no segment) and then overlaps segment 1 as segment 3.
  const Polylines lines = {{0, 0, 2, 0, 2, 2}, {1, -1, 1, 1}, {2, 0, 2, 0, 2, 2}};
  std::vector<PolylineView> views;
  for (const auto& l : lines) views.push_back({l.data(), l.size() / 2});
  Triangulation t;
  ASSERT_TRUE(t.insertPolylines(views.data(), views.size()).ok());
  MeshOptions mo;
  mo.segmentSources = true;
  const Mesh m = t.mesh(mo);
  ASSERT_EQ(m.segmentOffsets.size(), m.constraintEdges.size() + 1);
  std::map<std::vector<double>, std::vector<std::uint32_t>> named;
  for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
    const std::uint32_t e = m.constraintEdges[i];
    std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
    if (std::make_pair(m.points[2 * u], m.points[2 * u + 1]) >
        std::make_pair(m.points[2 * v], m.points[2 * v + 1]))
      std::swap(u, v);
    std::vector<std::uint32_t> segments(m.segmentSources.begin() + m.segmentOffsets[i],
                                        m.segmentSources.begin() + m.segmentOffsets[i + 1]);
    std::sort(segments.begin(), segments.end());
    named[{m.points[2 * u], m.points[2 * u + 1], m.points[2 * v], m.points[2 * v + 1]}] = segments;
  }
  const std::map<std::vector<double>, std::vector<std::uint32_t>> expected = {
      {{0, 0, 1, 0}, {0}},
      {{1, 0, 2, 0}, {0}},
      {{2, 0, 2, 2}, {1, 3}},
      {{1, -1, 1, 0}, {2}},
      {{1, 0, 1, 1}, {2}}};
  EXPECT_EQ(named, expected);
  // Not asked for: not filled.
  EXPECT_TRUE(t.mesh().segmentOffsets.empty());
}

TEST(Constraints, AdoptedPolylineBufferGivesTheSameMesh) {
  Polylines lines;
  for (int r = 0; r < 40; ++r) {
    std::vector<double> ring;
    const double cx = (r % 8) * 1.5, cy = (r / 8) * 1.5, radius = 0.6 + 0.3 * (r % 3);
    for (int k = 0; k <= 24; ++k) {
      const double a = 2 * M_PI * (k % 24) / 24;
      ring.push_back(cx + radius * std::cos(a));
      ring.push_back(cy + radius * std::sin(a));
    }
    lines.push_back(ring);
  }
  lines.push_back({0, 0, 12, 7.5, 12, 7.5, 0, 7.5});
  lines.push_back({});
  lines.push_back({1.5, 1.5, 3, 3});
  std::vector<double> flat;
  std::vector<std::uint32_t> offsets(1, 0);
  for (const auto& l : lines) {
    flat.insert(flat.end(), l.begin(), l.end());
    offsets.push_back(static_cast<std::uint32_t>(flat.size() / 2));
  }
  for (const bool pointsFirst : {false, true}) {
    Triangulation viewed, adopted;
    if (pointsFirst) {
      const std::vector<double> pts = testing::uniformPoints(300, 21);
      ASSERT_TRUE(viewed.insertPoints(pts.data(), pts.size() / 2).ok());
      ASSERT_TRUE(adopted.insertPoints(pts.data(), pts.size() / 2).ok());
    }
    std::vector<PolylineView> views;
    for (const auto& l : lines) views.push_back({l.data(), l.size() / 2});
    std::vector<std::uint32_t> viewIds(flat.size() / 2), adoptIds(flat.size() / 2);
    ASSERT_TRUE(viewed.insertPolylines(views.data(), views.size(), viewIds.data()).ok());
    std::vector<double> buffer = flat;
    ASSERT_TRUE(
        adopted.insertPolylines(std::move(buffer), offsets.data(), lines.size(), adoptIds.data())
            .ok());
    EXPECT_EQ(viewIds, adoptIds);
    MeshOptions mo;
    mo.insideFlags = true;
    const Mesh a = viewed.mesh(mo), b = adopted.mesh(mo);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.constrained, b.constrained);
    EXPECT_EQ(a.sources, b.sources);
    EXPECT_EQ(a.inside, b.inside);
    EXPECT_GT(viewed.stats().crossings, 0u);
    EXPECT_EQ(viewed.stats().crossings, adopted.stats().crossings);
  }
}

TEST(Constraints, AdoptedPolylineBufferRefusedWithItsReason) {
  Triangulation t;
  std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1};
  const std::uint32_t shortOffsets[] = {0, 2, 3};
  Status s = t.insertPolylines(std::move(xy), shortOffsets, 2);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_EQ(xy.size(), 8u);  // left as it was
  const std::uint32_t decreasing[] = {0, 3, 2, 4};
  s = t.insertPolylines(std::move(xy), decreasing, 3);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.index, 1u);
  xy[5] = std::nan("");
  const std::uint32_t offsets[] = {0, 2, 4};
  s = t.insertPolylines(std::move(xy), offsets, 2);
  EXPECT_EQ(s.code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(s.index, 1u);
  EXPECT_EQ(xy.size(), 8u);
  EXPECT_EQ(t.vertexCount(), 0u);
}

}  // namespace
}  // namespace geocdt

TEST(Constraints, FuzzBentLinkMustNotPassAVertexOver) {
  // Three polylines within 2e-11 of (-12345.678, 0), reduced from CI's fuzz run: x has a
  // spacing of 1.8e-12 there and y one of about 1e-27, so each rounding cell is a sliver, and
  // y spans several binades. Snap rounding bent a link of segment 0 through the rounded
  // crossing of two links, and the bend passed over an input vertex that its segment passes
  // on the other side: the chains of segments 0 and 3 crossed twice, though the segments do
  // not meet. A bend now takes every vertex between its segment and the bent link with it
  // (and does so for links stored against their segment's direction too).
  const Polylines lines = {
      {-12345.678000000005, 5.3056564363842135e-12, -12345.678000000011, 9.9682030016915524e-12},
      {-12345.678000000018, 1.8650186261229356e-11, -12345.678000000005, 4.9841015008457762e-12,
       -12345.678, 1.9936406003383105e-11},
      {-12345.678, 6.4310987107687431e-13, -12345.678000000018, 1.9936406003383108e-11, -12345.678,
       0, -12345.678000000007, 7.7173184529224921e-12, -12345.678000000016, 2.3151955358767476e-11},
  };
  Options o;
  o.order = InsertionOrder::Hilbert;
  o.start = LocateStart::LastTriangle;
  o.gridDensity = 0.25;
  expectSnapRoundedAndValid(lines, o);
}
}  // namespace
}  // namespace geocdt
