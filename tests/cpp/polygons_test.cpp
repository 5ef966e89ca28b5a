// triangulatePolygons(): the small path and the general engine behind it, held to the exact
// polygon checker (support/polygon_checks.h) on the troubles earcut's users meet (touching and
// overlapping holes, holes outside the shell, self-tangent and zero-area rings, repeated
// points, crossings), on random rings of small grids, and on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "geocdt/polygons.h"
#include "polygon_checks.h"
#include "polygons/general_polygon.h"
#include "polygons/polygon_cdt.h"
#include "polygons/tiny_ring.h"

namespace geocdt {
namespace {

using testing::checkPolygonTriangles;
using testing::PolygonCheckOptions;
using Ring = std::vector<double>;
using Polygon = std::vector<Ring>;

// A batch in GeoArrow's layout built from polygons of rings.
struct Batch {
  std::vector<double> xy;
  std::vector<std::uint32_t> rings{0}, polygons{0};

  explicit Batch(const std::vector<Polygon>& list = {}) {
    for (const Polygon& p : list) add(p);
  }
  void add(const Polygon& polygon) {
    for (const Ring& ring : polygon) {
      xy.insert(xy.end(), ring.begin(), ring.end());
      rings.push_back(static_cast<std::uint32_t>(xy.size() / 2));
    }
    polygons.push_back(static_cast<std::uint32_t>(rings.size() - 1));
  }
  PolygonBatch view() const {
    return {xy.data(),        xy.size() / 2,   rings.data(),
            rings.size() - 1, polygons.data(), polygons.size() - 1};
  }
};

struct Outcome {
  PolygonTriangles out;
  PolygonStats stats;
  Status status;
};

Outcome run(const Batch& b, FillRule fill = FillRule::EvenOdd, std::uint32_t threads = 1) {
  Outcome r;
  PolygonOptions options;
  options.fill = fill;
  options.threads = threads;
  r.status = triangulatePolygons(b.view(), options, r.out, &r.stats);
  return r;
}

// Triangulates and checks; returns the run for more assertions.
Outcome checked(const Batch& b, FillRule fill = FillRule::EvenOdd) {
  Outcome r = run(b, fill);
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  PolygonCheckOptions options;
  options.fill = fill;
  EXPECT_EQ(checkPolygonTriangles(b.view(), r.out, options), "");
  return r;
}

std::size_t triangles(const Outcome& r, std::size_t p) {
  return r.out.triangleOffsets[p + 1] - r.out.triangleOffsets[p];
}

const Ring kSquare = {0, 0, 10, 0, 10, 10, 0, 10, 0, 0};

TEST(Polygons, SquareClosedOrOpenGivesTwoTriangles) {
  const Outcome closed = checked(Batch({{kSquare}}));
  EXPECT_EQ(triangles(closed, 0), 2u);
  EXPECT_EQ(closed.stats.smallPath, 1u);
  const Outcome open = checked(Batch({{{0, 0, 10, 0, 10, 10, 0, 10}}}));
  EXPECT_EQ(open.out.triangles, closed.out.triangles);
}

TEST(Polygons, ClockwiseRingsGiveCounterClockwiseTriangles) {
  const Outcome r = checked(Batch({{{0, 0, 0, 10, 10, 10, 10, 0, 0, 0}}}));
  EXPECT_EQ(triangles(r, 0), 2u);  // the checker holds each to counter-clockwise
}

TEST(Polygons, SquareWithHole) {
  const Outcome r = checked(Batch({{kSquare, {2, 2, 2, 4, 4, 4, 4, 2, 2, 2}}}));
  EXPECT_EQ(triangles(r, 0), 8u);
}

TEST(Polygons, IndicesPointAtTheFirstOfEqualPositions) {
  // The closing point and a repeated point share the index of the first.
  const Outcome r = checked(Batch({{{0, 0, 10, 0, 10, 0, 10, 10, 0, 0}}}));
  for (const std::uint32_t i : r.out.triangles) EXPECT_TRUE(i == 0 || i == 1 || i == 3) << i;
}

TEST(Polygons, TroublesEarcutMeets) {
  const std::vector<Polygon> cases = {
      // holes touching the shell at a vertex, and along an edge
      {kSquare, {0, 0, 3, 2, 2, 3, 0, 0}},
      {kSquare, {0, 2, 3, 2, 3, 5, 0, 5, 0, 2}},
      // two holes touching at a vertex, two overlapping holes, a hole on a hole
      {kSquare, {2, 2, 5, 2, 5, 5, 2, 2}, {5, 5, 8, 5, 8, 8, 5, 5}},
      {kSquare, {2, 2, 6, 2, 6, 6, 2, 6, 2, 2}, {4, 4, 8, 4, 8, 8, 4, 8, 4, 4}},
      {kSquare, {2, 2, 6, 2, 6, 6, 2, 6, 2, 2}, {2, 2, 6, 2, 6, 6, 2, 6, 2, 2}},
      // a hole outside the shell, a hole crossing the shell
      {kSquare, {20, 20, 22, 20, 22, 22, 20, 20}},
      {kSquare, {8, 4, 12, 4, 12, 6, 8, 6, 8, 4}},
      // self-tangent rings: a figure eight through one vertex, a ring touching its own edge
      {{0, 0, 4, 0, 2, 2, 4, 4, 0, 4, 2, 2, 0, 0}},
      {{0, 0, 10, 0, 10, 10, 5, 0, 0, 10, 0, 0}},
      // a bow tie (its rings cross: an extra point)
      {{0, 0, 4, 4, 4, 0, 0, 4, 0, 0}},
      // zero-area and collinear rings, spikes, repeated points
      {{0, 0, 5, 0, 10, 0, 0, 0}},
      {{0, 0, 10, 0, 10, 10, 10, 10, 10, 10, 0, 10, 0, 0}},
      {{0, 0, 10, 0, 15, 0, 10, 0, 10, 10, 0, 10, 0, 0}},
      {{0, 0, 10, 0, 10, 10, 12, 12, 10, 10, 0, 10, 0, 0}},
      {kSquare, {5, 5, 5, 5, 5, 5}},
      // collinear points along the shell's edges (a tile's clipped border)
      {{0, 0, 2, 0, 4, 0, 6, 0, 8, 0, 10, 0, 10, 5, 10, 10, 5, 10, 0, 10, 0, 5, 0, 0}},
      // islands in lakes in islands; a ring wound twice
      {{0, 0, 12, 0, 12, 12, 0, 12, 0, 0},
       {2, 2, 10, 2, 10, 10, 2, 10, 2, 2},
       {4, 4, 8, 4, 8, 8, 4, 8, 4, 4}},
      {{0, 0, 10, 0, 10, 10, 0, 10, 0, 0, 10, 0, 10, 10, 0, 10, 0, 0}},
      // nothing to fill: no rings, empty rings, a point, a segment
      {},
      {{}, {}},
      {{3, 3}},
      {{0, 0, 4, 4}},
  };
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE("case " + std::to_string(i));
      checked(Batch({cases[i]}), fill);
    }
    SCOPED_TRACE("all cases in one batch");
    checked(Batch(cases), fill);
  }
}

TEST(Polygons, CrossingsBecomeExtraPoints) {
  const Outcome r = checked(Batch({{kSquare}, {{0, 0, 4, 4, 4, 0, 0, 4, 0, 0}}, {kSquare}}));
  EXPECT_EQ(r.stats.general, 1u);
  EXPECT_EQ(r.out.extraPoints, (std::vector<double>{2, 2}));
  EXPECT_EQ(triangles(r, 1), 2u);
  // The extra point is index pointCount (15 points in the batch) + 0.
  const std::uint32_t pointCount = 15;
  EXPECT_NE(std::count(r.out.triangles.begin(), r.out.triangles.end(), pointCount), 0);
}

TEST(Polygons, NonZeroFillsWhatEvenOddLeavesOut) {
  const Batch b({{kSquare, {2, 2, 8, 2, 8, 8, 2, 8, 2, 2}}});  // the hole winds like the shell
  EXPECT_EQ(triangles(checked(b, FillRule::EvenOdd), 0), 8u);
  EXPECT_EQ(triangles(checked(b, FillRule::NonZero), 0), 10u);
}

// Rings of random points on small grids: collinear points, repeated points, vertices on
// other segments and crossings are the rule.
std::vector<Polygon> randomPolygons(std::uint32_t seed, std::size_t count, int grid) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(0, grid), rings(1, 3), points(1, 9);
  std::vector<Polygon> out;
  for (std::size_t i = 0; i < count; ++i) {
    Polygon p;
    for (int r = rings(rng); r > 0; --r) {
      Ring ring;
      for (int k = points(rng); k > 0; --k) {
        ring.push_back(coordinate(rng));
        ring.push_back(coordinate(rng));
      }
      if (rng() % 2) ring.insert(ring.end(), {ring[0], ring[1]});
      p.push_back(ring);
    }
    out.push_back(p);
  }
  return out;
}

TEST(Polygons, RandomRingsOnSmallGrids) {
  for (const int grid : {3, 6, 20}) {
    SCOPED_TRACE("grid " + std::to_string(grid));
    const Batch b(randomPolygons(static_cast<std::uint32_t>(grid), 1500, grid));
    const Outcome even = checked(b, FillRule::EvenOdd);
    checked(b, FillRule::NonZero);
    EXPECT_GT(even.stats.smallPath, 0u);
    EXPECT_GT(even.stats.general, 0u);
  }
}

// Star-shaped polygons of many points: the small path's long rings.
TEST(Polygons, LargeStarShapedRingsWithHoles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(0.5, 1.0);
  std::vector<Polygon> list;
  for (const int n : {50, 400, 3000}) {
    Ring shell, hole;
    for (int k = 0; k < n; ++k) {
      const double a = 6.283185307179586 * k / n, r = 100 * radius(rng);
      shell.push_back(r * std::cos(a));
      shell.push_back(r * std::sin(a));
      hole.push_back(10 * std::cos(-a));
      hole.push_back(10 * std::sin(-a));
    }
    list.push_back({shell, hole});
  }
  const Outcome r = checked(Batch(list));
  EXPECT_EQ(r.stats.smallPath, 3u);
}

// Rings of three and four points take their own path: its triangles must pass the checker
// and cover what the small path's do, on every quad of a small grid's kind (convex, concave,
// crossed, with collinear or repeated corners, cocircular), either way round, open or closed.
TEST(Polygons, TinyRingsAgreeWithTheSmallPath) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> coordinate(0, 4);
  PolygonCdt small;
  std::size_t handled = 0;
  Batch all;
  for (int i = 0; i < 20000; ++i) {
    Ring ring;
    const int corners = 3 + i % 3;  // five: refused unless some repeat
    for (int k = 0; k < corners; ++k) {
      ring.push_back(coordinate(rng));
      ring.push_back(coordinate(rng));
    }
    if (i % 3 == 0) ring.insert(ring.end(), {ring[0], ring[1]});
    const auto n = static_cast<std::uint32_t>(ring.size() / 2);
    std::vector<std::uint32_t> tiny, full;
    const std::uint32_t starts[2] = {0, n};
    if (!triangulateTinyRing(ring.data(), n, 0, tiny)) continue;
    ++handled;
    ASSERT_TRUE(small.triangulate(ring.data(), n, starts, 1, FillRule::EvenOdd, 0, full));
    EXPECT_EQ(tiny.size(), full.size());
    all.add({ring});
  }
  EXPECT_GT(handled, 10000u);
  const Outcome r = checked(all);
  EXPECT_EQ(r.out.triangles.size() % 3, 0u);
}

TEST(Polygons, ThreadsGiveTheSameArrays) {
  Batch b(randomPolygons(11, 5000, 1000));  // about 50,000 points: enough for threads
  b.add({{0, 0, 4, 4, 4, 0, 0, 4, 0, 0}});  // and extra points from a later range
  b.add({{0, 0, 4, 4, 4, 0, 0, 4, 0, 0}});
  const Outcome one = run(b);
  ASSERT_TRUE(one.status.ok());
  for (const std::uint32_t threads : {2u, 3u, 8u}) {
    const Outcome many = run(b, FillRule::EvenOdd, threads);
    ASSERT_TRUE(many.status.ok());
    EXPECT_GT(many.stats.threads, 1u);
    EXPECT_EQ(many.out.triangles, one.out.triangles);
    EXPECT_EQ(many.out.extraPoints, one.out.extraPoints);
    EXPECT_EQ(many.out.triangleOffsets, one.out.triangleOffsets);
  }
  EXPECT_EQ(checkPolygonTriangles(b.view(), one.out), "");
}

// The small path and the general engine agree on the polygons the small path takes.
TEST(Polygons, SmallPathAgreesWithTheGeneralEngine) {
  PolygonCdt small;
  GeneralPolygon general;
  std::size_t compared = 0;
  for (const Polygon& p : randomPolygons(5, 2000, 12)) {
    const Batch b({p});
    std::vector<std::uint32_t> starts;
    for (const std::uint32_t r : b.rings) starts.push_back(r);
    const auto n = static_cast<std::uint32_t>(b.xy.size() / 2);
    std::vector<std::uint32_t> fast, slow;
    std::vector<double> extras;
    if (!small.triangulate(b.xy.data(), n, starts.data(), static_cast<std::uint32_t>(p.size()),
                           FillRule::EvenOdd, 0, fast))
      continue;
    ASSERT_TRUE(general
                    .triangulate(b.xy.data(), n, starts.data(),
                                 static_cast<std::uint32_t>(p.size()), FillRule::EvenOdd, 0, n,
                                 slow, extras)
                    .ok());
    EXPECT_TRUE(extras.empty());
    EXPECT_EQ(fast.size(), slow.size());
    ++compared;
  }
  EXPECT_GT(compared, 300u);
}

// The checker itself: each broken output below must be caught.
TEST(Polygons, CheckerCatchesBrokenOutputs) {
  const Batch b({{kSquare, {2, 2, 2, 8, 8, 8, 8, 2, 2, 2}}, {{0, 0, 10, 0, 10, 2, 0, 0}}});
  const Outcome good = checked(b);
  const auto broken = [&](auto edit) {
    PolygonTriangles out = good.out;
    edit(out);
    return checkPolygonTriangles(b.view(), out);
  };
  EXPECT_NE(broken([](PolygonTriangles& o) { std::swap(o.triangles[0], o.triangles[1]); }), "");
  EXPECT_NE(broken([](PolygonTriangles& o) {  // a triangle dropped: a border edge off the rings
              o.triangles.erase(o.triangles.begin(), o.triangles.begin() + 3);
              for (std::uint32_t& t : o.triangleOffsets) t = t > 0 ? t - 1 : 0;
            }),
            "");
  EXPECT_NE(broken([](PolygonTriangles& o) {  // a triangle over the hole, and its twin edge
              o.triangles.insert(o.triangles.begin(), {5, 6, 7});
              for (std::size_t i = 1; i < o.triangleOffsets.size(); ++i) ++o.triangleOffsets[i];
            }),
            "");
  EXPECT_NE(broken([](PolygonTriangles& o) { o.triangleOffsets[1] -= 1; }), "");
  EXPECT_NE(broken([](PolygonTriangles& o) { o.triangles.back() = 99; }), "");
  // Not constrained Delaunay: the long diagonal of a thin convex quad.
  const Batch quad({{{0, 0, 10, 0, 11, 1, 1, 1, 0, 0}}});
  PolygonTriangles wrong;
  wrong.triangles = {0, 1, 2, 0, 2, 3};
  wrong.triangleOffsets = {0, 2};
  PolygonTriangles right;
  right.triangles = {0, 1, 3, 1, 2, 3};
  right.triangleOffsets = {0, 2};
  EXPECT_EQ(checkPolygonTriangles(quad.view(), right), "");
  EXPECT_NE(checkPolygonTriangles(quad.view(), wrong).find("not constrained Delaunay"),
            std::string::npos);
}

TEST(Polygons, BadLayoutIsRefusedNamingThePolygonAndRing) {
  Batch b({{kSquare}, {kSquare, kSquare}});
  b.rings[2] = 3;  // ring 1 (polygon 1's shell) ends before it starts
  Outcome r = run(b);
  EXPECT_EQ(r.status.code, StatusCode::InvalidArgument);
  EXPECT_EQ(r.status.index, 1u);
  EXPECT_EQ(r.status.segment, 1u);
  EXPECT_NE(r.status.message.find("polygon 1 ring 0"), std::string::npos) << r.status.message;
  EXPECT_TRUE(r.out.triangles.empty());

  Batch past({{kSquare}});
  past.rings[1] = 99;
  r = run(past);
  EXPECT_EQ(r.status.code, StatusCode::InvalidArgument);
  EXPECT_NE(r.status.message.find("past the 5 points"), std::string::npos) << r.status.message;

  Batch polygons({{kSquare}, {kSquare}});
  polygons.polygons[1] = 2;
  polygons.polygons[2] = 1;
  r = run(polygons);
  EXPECT_EQ(r.status.code, StatusCode::InvalidArgument);
  EXPECT_EQ(r.status.index, 1u);
  polygons.polygons[2] = 7;
  r = run(polygons);
  EXPECT_NE(r.status.message.find("past the 2 rings"), std::string::npos) << r.status.message;
}

TEST(Polygons, InvalidCoordinatesAreRefusedNamingThePoint) {
  Batch b({{kSquare}, {kSquare, {2, 2, 3, 2, 3, std::nan(""), 2, 2}}});
  const Outcome r = run(b);
  EXPECT_EQ(r.status.code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(r.status.index, 1u);
  EXPECT_EQ(r.status.segment, 2u);
  EXPECT_NE(r.status.message.find("polygon 1 ring 1"), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("point 2 (point 12 of the batch)"), std::string::npos)
      << r.status.message;
  // Points that no ring uses are not read.
  Batch unused({{kSquare}});
  unused.xy.push_back(std::nan(""));
  unused.xy.push_back(0);
  EXPECT_TRUE(run(unused).status.ok());
}

}  // namespace
}  // namespace geocdt
