// Delaunay triangulation of points: every result goes through the one invariant checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geocdt/predicates.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

using testing::CheckOptions;
using testing::checkTriangulation;

struct Built {
  Status status;
  Mesh mesh;
  std::vector<std::uint32_t> ids;
};

Built build(const std::vector<double>& xy, const Options& options = {}) {
  Built b;
  b.status = triangulate(xy.data(), xy.size() / 2, nullptr, 0, options, {}, b.mesh, &b.ids);
  return b;
}

std::string check(const std::vector<double>& xy, const Options& options = {}) {
  Built b = build(xy, options);
  if (!b.status.ok()) return "status: " + b.status.message;
  CheckOptions c;
  c.inputXY = &xy;
  c.inputToVertex = &b.ids;
  return checkTriangulation(b.mesh, c);
}

TEST(Delaunay, FewPointsGiveNoTriangles) {
  for (std::size_t n : {0, 1, 2}) {
    const std::vector<double> xy = testing::uniformPoints(n, 7);
    Built b = build(xy);
    ASSERT_TRUE(b.status.ok());
    EXPECT_EQ(b.mesh.triangles.size(), 0u);
    EXPECT_EQ(b.mesh.points.size(), 2 * n);
    EXPECT_EQ(check(xy), "");
  }
}

TEST(Delaunay, ThreePointsInEitherOrientation) {
  for (const std::vector<double>& xy :
       {std::vector<double>{0, 0, 1, 0, 0, 1}, std::vector<double>{0, 0, 0, 1, 1, 0}}) {
    Built b = build(xy);
    ASSERT_TRUE(b.status.ok());
    EXPECT_EQ(b.mesh.triangles.size(), 3u);
    EXPECT_EQ(check(xy), "");
  }
}

TEST(Delaunay, AllCollinearGivesNoTrianglesAndMergesDuplicates) {
  std::vector<double> xy = testing::collinearPoints(500, 3);
  Built b = build(xy);
  ASSERT_TRUE(b.status.ok());
  EXPECT_EQ(b.mesh.triangles.size(), 0u);
  EXPECT_EQ(check(xy), "");
  // Then one point off the line makes it a fan of triangles.
  xy.push_back(5);
  xy.push_back(0);
  EXPECT_EQ(check(xy), "");
}

TEST(Delaunay, AllDuplicatesGiveOneVertex) {
  std::vector<double> xy;
  for (int i = 0; i < 100; ++i) {
    xy.push_back(2.5);
    xy.push_back(-1.0);
  }
  Built b = build(xy);
  ASSERT_TRUE(b.status.ok());
  EXPECT_EQ(b.mesh.points.size(), 2u);
  for (const std::uint32_t id : b.ids) EXPECT_EQ(id, 0u);
}

TEST(Delaunay, DuplicatesKeepFirstOccurrenceOrder) {
  const std::vector<double> base = testing::uniformPoints(3000, 11);
  std::vector<double> xy;
  for (int copy = 0; copy < 3; ++copy) xy.insert(xy.end(), base.begin(), base.end());
  Built b = build(xy);
  ASSERT_TRUE(b.status.ok());
  EXPECT_EQ(b.mesh.points.size(), base.size());
  for (std::size_t i = 0; i < b.ids.size(); ++i) EXPECT_EQ(b.ids[i], i % 3000);
  EXPECT_EQ(check(xy), "");
}

TEST(Delaunay, UniformGaussianLatticeCircle) {
  EXPECT_EQ(check(testing::uniformPoints(20000, 1)), "");
  EXPECT_EQ(check(testing::gaussianClusters(20000, 2)), "");
  EXPECT_EQ(check(testing::latticePoints(120)), "");
  EXPECT_EQ(check(testing::circlePoints(2000)), "");
}

TEST(Delaunay, HullWithManyCollinearPoints) {
  // The border of a lattice: 4 long collinear sides, plus a few interior points.
  std::vector<double> xy;
  for (int i = 0; i <= 200; ++i) {
    for (const double v : {0.0 + i, 0.0, 200.0, 0.0 + i, 0.0 + i, 200.0, 0.0, 0.0 + i})
      xy.push_back(v);
  }
  for (const double v : {50.5, 70.25, 120.0, 3.0, 199.0, 199.0}) xy.push_back(v);
  Built b = build(xy);
  ASSERT_TRUE(b.status.ok());
  EXPECT_EQ(testing::hullSize(b.mesh), 800u);
  EXPECT_EQ(check(xy), "");
}

TEST(Delaunay, EveryOrderAndLocateStart) {
  const std::vector<double> sets[] = {testing::uniformPoints(5000, 5), testing::latticePoints(60),
                                      testing::gaussianClusters(5000, 6)};
  for (const auto order : {InsertionOrder::Input, InsertionOrder::Hilbert, InsertionOrder::Brio})
    for (const auto start : {LocateStart::Grid, LocateStart::LastTriangle})
      for (const auto& xy : sets) {
        Options o;
        o.order = order;
        o.start = start;
        EXPECT_EQ(check(xy, o), "") << "order " << int(order) << " start " << int(start);
      }
}

TEST(Delaunay, ScaledFrom1e_9To1e9) {
  const std::vector<double> sets[] = {testing::uniformPoints(3000, 8), testing::latticePoints(40),
                                      testing::circlePoints(500),
                                      testing::gaussianClusters(3000, 9)};
  for (const auto& xy : sets)
    for (double scale = 1e-9; scale <= 1e9 * 1.01; scale *= 10)
      EXPECT_EQ(check(testing::transformed(xy, scale, 0, 0)), "") << "scale " << scale;
}

TEST(Delaunay, TinyBoxAtHugeOffsetAndMercatorAndLonLat) {
  EXPECT_EQ(check(testing::transformed(testing::uniformPoints(5000, 12), 1e-6, 1e7, -3e7)), "");
  // Web Mercator metres with sub-metre spacing.
  EXPECT_EQ(check(testing::transformed(testing::latticePoints(50), 0.25, 1.6e7, 4.2e6)), "");
  EXPECT_EQ(check(testing::transformed(testing::uniformPoints(5000, 13), 0.37, 1.6e7, 4.2e6)), "");
  // lon/lat, and a lattice of lon/lat with a step that is not exact in binary.
  EXPECT_EQ(check(testing::transformed(testing::uniformPoints(5000, 14), 360, -180, 0)), "");
  EXPECT_EQ(check(testing::transformed(testing::latticePoints(40), 0.1, -73.9, 40.7)), "");
}

TEST(Delaunay, InvalidCoordinatesNameTheIndexAndInsertNothing) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity(), -1e151};
  for (const double v : bad) {
    std::vector<double> xy = testing::uniformPoints(10, 4);
    xy[11] = v;  // point 5, y
    Triangulation t;
    Status s = t.insertPoints(xy.data(), 10);
    EXPECT_EQ(s.code, StatusCode::InvalidCoordinate);
    EXPECT_EQ(s.index, 5u);
    EXPECT_NE(s.message.find("point 5"), std::string::npos) << s.message;
    EXPECT_EQ(t.vertexCount(), 0u);
  }
  std::vector<double> ok = {1e150, -1e150, 0, 1e150, -1e150, 0};
  EXPECT_EQ(check(ok), "");
}

TEST(Delaunay, IncrementalBatchesKeepIdsAndStayValid) {
  const std::vector<double> all = testing::uniformPoints(6000, 21);
  Triangulation t;
  std::vector<std::uint32_t> ids(3000);
  ASSERT_TRUE(t.insertPoints(all.data(), 3000, ids.data()).ok());
  const Mesh first = t.mesh();
  // The second batch repeats 100 points of the first and adds new ones outside the first box.
  std::vector<double> more(all.begin() + 6000, all.end());
  more.insert(more.end(), all.begin(), all.begin() + 200);
  for (std::size_t i = 0; i < more.size(); i += 2) more[i] += 0.5;
  std::vector<std::uint32_t> ids2(more.size() / 2);
  ASSERT_TRUE(t.insertPoints(more.data(), more.size() / 2, ids2.data()).ok());
  const Mesh second = t.mesh();
  for (std::size_t i = 0; i < first.points.size(); ++i)
    EXPECT_EQ(first.points[i], second.points[i]);
  std::vector<double> input(all.begin(), all.begin() + 6000);
  input.insert(input.end(), more.begin(), more.end());
  std::vector<std::uint32_t> map(ids);
  map.insert(map.end(), ids2.begin(), ids2.end());
  CheckOptions c;
  c.inputXY = &input;
  c.inputToVertex = &map;
  EXPECT_EQ(checkTriangulation(second, c), "");
}

TEST(Delaunay, ManySmallBatchesWithDuplicates) {
  // Small batches keep input numbering and rename only around the vertices that move.
  const std::vector<double> pool = testing::uniformPoints(3000, 23);
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(pool.data(), 1000).ok());
  std::vector<double> input(pool.begin(), pool.begin() + 2000);
  std::vector<std::uint32_t> map(1000);
  for (std::uint32_t i = 0; i < 1000; ++i) map[i] = i;  // no duplicates in the first batch
  testing::Random r(4);
  for (int batch = 0; batch < 150; ++batch) {
    std::vector<double> xy;
    for (int k = 0; k < 12; ++k) {
      // Each point is new, a repeat of an earlier point, or a repeat within the batch.
      const std::size_t pick =
          r.next() % 3 == 0 ? r.next() % (input.size() / 2) : 1000 + r.next() % 2000;
      const double* src = k > 0 && r.next() % 4 == 0 ? &xy[xy.size() - 2] : &pool[2 * pick];
      const double x = src[0], y = src[1];
      xy.push_back(x);
      xy.push_back(y);
    }
    std::vector<std::uint32_t> ids(12);
    ASSERT_TRUE(t.insertPoints(xy.data(), 12, ids.data()).ok());
    input.insert(input.end(), xy.begin(), xy.end());
    map.insert(map.end(), ids.begin(), ids.end());
  }
  const Mesh m = t.mesh();
  testing::CheckOptions c;
  c.inputXY = &input;
  c.inputToVertex = &map;
  EXPECT_EQ(testing::checkTriangulation(m, c), "");
  // Vertex ids follow first appearance: each new id is one more than the largest before it.
  std::uint32_t largest = 999;
  for (const std::uint32_t id : map) {
    EXPECT_LE(id, largest + 1);
    largest = std::max(largest, id);
  }
  EXPECT_EQ(largest + 1, m.points.size() / 2);
}

// Inputs with duplicates (repeats of earlier points, in and out of order) on a lattice.
std::vector<double> withRepeats(std::size_t side) {
  std::vector<double> xy = testing::latticePoints(side);
  testing::Random r(41);
  const std::size_t n = xy.size() / 2;
  for (std::size_t k = 0; k < n / 3; ++k) {
    const std::size_t pick = r.next() % n;
    xy.push_back(xy[2 * pick]);
    xy.push_back(xy[2 * pick + 1]);
  }
  return xy;
}

TEST(Delaunay, AdoptedBufferBecomesTheCoordinates) {
  for (const std::vector<double>& xy : {testing::uniformPoints(20000, 43), withRepeats(90)}) {
    const Built copied = build(xy);
    ASSERT_TRUE(copied.status.ok());
    std::vector<double> buffer = xy;
    const double* memory = buffer.data();
    Triangulation t;
    std::vector<std::uint32_t> ids(xy.size() / 2);
    ASSERT_TRUE(t.insertPoints(std::move(buffer), ids.data()).ok());
    EXPECT_EQ(t.points().data(), memory);  // taken over, not copied
    EXPECT_EQ(ids, copied.ids);
    const Mesh m = t.release();
    EXPECT_EQ(m.points.data(), memory);
    EXPECT_EQ(m.points, copied.mesh.points);
    EXPECT_EQ(m.triangles, copied.mesh.triangles);
    EXPECT_EQ(m.halfedges, copied.mesh.halfedges);
  }
}

TEST(Delaunay, AdoptedBufferAfterOtherPointsIsAppended) {
  const std::vector<double> all = withRepeats(60);
  const std::size_t half = all.size() / 4 * 2;
  Triangulation t;
  std::vector<std::uint32_t> ids(all.size() / 2);
  ASSERT_TRUE(t.insertPoints(all.data(), half / 2, ids.data()).ok());
  std::vector<double> rest(all.begin() + static_cast<std::ptrdiff_t>(half), all.end());
  ASSERT_TRUE(t.insertPoints(std::move(rest), ids.data() + half / 2).ok());
  EXPECT_TRUE(rest.empty());  // freed once appended
  CheckOptions c;
  c.inputXY = &all;
  c.inputToVertex = &ids;
  EXPECT_EQ(checkTriangulation(t.mesh(), c), "");
}

TEST(Delaunay, AdoptedBufferWithInvalidCoordinatesIsLeftAsItWas) {
  std::vector<double> xy = testing::uniformPoints(100, 44);
  xy[77] = std::numeric_limits<double>::quiet_NaN();
  const std::size_t size = xy.size();
  Triangulation t;
  const Status s = t.insertPoints(std::move(xy));
  EXPECT_EQ(s.code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(s.index, 38u);
  EXPECT_EQ(xy.size(), size);
  EXPECT_EQ(t.vertexCount(), 0u);
}

TEST(Delaunay, OneShotWithAdoptedBufferEqualsCopied) {
  const std::vector<double> xy = withRepeats(40);
  const std::vector<double> ring = {3.5, 3.5, 20.5, 7.25, 11, 30, 3.5, 3.5};
  const PolylineView view{ring.data(), ring.size() / 2};
  Mesh copied, adopted;
  std::vector<std::uint32_t> copiedIds, adoptedIds;
  ASSERT_TRUE(triangulate(xy.data(), xy.size() / 2, &view, 1, {}, {}, copied, &copiedIds).ok());
  std::vector<double> buffer = xy;
  ASSERT_TRUE(triangulate(std::move(buffer), &view, 1, {}, {}, adopted, &adoptedIds).ok());
  EXPECT_EQ(adoptedIds, copiedIds);
  EXPECT_EQ(adopted.points, copied.points);
  EXPECT_EQ(adopted.triangles, copied.triangles);
  EXPECT_EQ(adopted.constrained, copied.constrained);
}

TEST(Delaunay, DeterministicResult) {
  const std::vector<double> xy = testing::latticePoints(50);
  Built a = build(xy), b = build(xy);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.halfedges, b.mesh.halfedges);
}

TEST(Delaunay, LocateAgreesWithExactPredicates) {
  const std::vector<double> xy = testing::latticePoints(30);
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2).ok());
  const Mesh m = t.mesh();
  const std::vector<double>& p = m.points;
  testing::Random r(5);
  for (int i = 0; i < 3000; ++i) {
    // Queries on vertices, on edges (half-integers) and in faces, inside and outside.
    const double x = std::floor(r.uniform() * 70 - 20) / 2,
                 y = std::floor(r.uniform() * 70 - 20) / 2;
    const Location loc = t.locate(x, y);
    const bool inside = x >= 0 && x <= 29 && y >= 0 && y <= 29;
    if (!inside) {
      EXPECT_EQ(loc.kind, Location::Kind::Outside) << x << "," << y;
      continue;
    }
    ASSERT_GE(loc.triangle, 0) << x << "," << y;
    const std::uint32_t* v = &m.triangles[3 * loc.triangle];
    int zeros = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      const Sign s = orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y);
      EXPECT_NE(s, Sign::Negative);
      zeros += s == Sign::Zero;
    }
    const Location::Kind expected = zeros == 0   ? Location::Kind::Face
                                    : zeros == 1 ? Location::Kind::Edge
                                                 : Location::Kind::Vertex;
    EXPECT_EQ(loc.kind, expected) << x << "," << y;
    if (loc.kind == Location::Kind::Vertex) {
      EXPECT_EQ(p[2 * loc.vertices[0]], x);
      EXPECT_EQ(p[2 * loc.vertices[0] + 1], y);
    }
  }
}

TEST(Delaunay, LocateAnswersInvalidForNonFiniteCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double bad[][2] = {{nan, 1}, {1, nan}, {inf, 1}, {1, -inf}, {nan, inf}};
  Triangulation t;
  // Empty only while there are no triangles; a non-finite query is Invalid even then.
  EXPECT_EQ(t.locate(1, 1).kind, Location::Kind::Empty);
  EXPECT_EQ(t.locate(nan, 1).kind, Location::Kind::Invalid);
  const std::vector<double> xy = testing::latticePoints(4);
  ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2).ok());
  const std::uint64_t locates = t.stats().locates;
  for (const auto& q : bad) {
    const Location loc = t.locate(q[0], q[1]);
    EXPECT_EQ(loc.kind, Location::Kind::Invalid) << q[0] << "," << q[1];
    EXPECT_EQ(loc.triangle, -1);
  }
  EXPECT_EQ(t.stats().locates, locates);  // nothing was walked
  // Finite coordinates beyond what insertPoints accepts are still positions: outside.
  const double huge = std::numeric_limits<double>::max();
  EXPECT_EQ(t.locate(huge, -huge).kind, Location::Kind::Outside);
  EXPECT_EQ(t.locate(1.5, 1.5).kind, Location::Kind::Edge);
}

TEST(Delaunay, StatsIsACopyAndLocateCountsItsWalk) {
  const std::vector<double> xy = testing::uniformPoints(1000, 12);
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(xy.data(), 1000).ok());
  const Stats before = t.stats();
  EXPECT_EQ(before.inserted, 1000u);
  EXPECT_GT(before.gridSize, 1u);
  // locate() is const but counts (see the header): one more location, at least one step.
  t.locate(0.5, 0.5);
  const Stats after = t.stats();
  EXPECT_EQ(after.locates, before.locates + 1);
  EXPECT_GT(after.walkSteps, before.walkSteps);
  EXPECT_EQ(after.inserted, before.inserted);
  EXPECT_EQ(after.gridSize, before.gridSize);
}

TEST(Delaunay, WalkStaysShortInHilbertOrder) {
  // Not a timing: the number of triangles visited per insertion, which the paper's O(N)
  // argument needs to stay flat as n grows.
  double previous = 0;
  for (std::size_t n : {10000, 100000}) {
    const std::vector<double> xy = testing::uniformPoints(n, 31);
    Triangulation t;
    ASSERT_TRUE(t.insertPoints(xy.data(), n).ok());
    const double mean = double(t.stats().walkSteps) / double(t.stats().locates);
    EXPECT_LT(mean, 8.0);
    if (previous > 0) {
      EXPECT_LT(mean, previous * 1.5);
    }
    previous = mean;
  }
}

}  // namespace
}  // namespace geocdt
