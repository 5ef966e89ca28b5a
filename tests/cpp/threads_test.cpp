// Options::threads: a large first batch of points triangulated in strips on several threads
// and joined along the seams. Without cocircular points the triangles are those of one
// thread; with them (lattices) any Delaunay triangulation is right, so the checker decides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "constraint_invariants.h"
#include "geocdt/polygons.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

struct Result {
  Mesh mesh;
  std::vector<std::uint32_t> ids;
  Stats stats;
};

Result triangulateWith(const std::vector<double>& xy, std::uint32_t threads) {
  Options options;
  options.threads = threads;
  Triangulation t(options);
  Result r;
  r.ids.resize(xy.size() / 2);
  const Status s = t.insertPoints(xy.data(), xy.size() / 2, r.ids.data());
  EXPECT_TRUE(s.ok()) << s.message;
  r.stats = t.stats();
  r.mesh = t.mesh();
  return r;
}

std::string check(const std::vector<double>& xy, const Result& r) {
  testing::CheckOptions c;
  c.inputXY = &xy;
  c.inputToVertex = &r.ids;
  return testing::checkTriangulation(r.mesh, c);
}

// Each thread count's result is valid, numbers vertices as one thread does, and (without
// cocircular points) has one thread's triangles.
void expectSameAsOneThread(const std::vector<double>& xy, bool generalPosition) {
  const Result one = triangulateWith(xy, 1);
  EXPECT_EQ(one.stats.threads, 1u);
  for (const std::uint32_t threads : {2u, 3u, 4u}) {
    SCOPED_TRACE(threads);
    const Result many = triangulateWith(xy, threads);
    // A strip on each thread asked for, as far as the points go (16,384 at least a strip).
    EXPECT_EQ(many.stats.threads, std::min<std::size_t>(threads, xy.size() / 2 / 16384));
    EXPECT_EQ(check(xy, many), "");
    EXPECT_EQ(many.ids, one.ids);
    EXPECT_EQ(many.mesh.points, one.mesh.points);
    EXPECT_EQ(many.stats.inserted, one.stats.inserted);
    EXPECT_EQ(many.stats.duplicates, one.stats.duplicates);
    EXPECT_EQ(many.mesh.triangles.size(), one.mesh.triangles.size());
    if (generalPosition)
      EXPECT_TRUE(testing::triangleSet(many.mesh) == testing::triangleSet(one.mesh));
  }
}

TEST(Threads, UniformPointsGiveOneThreadsTriangles) {
  expectSameAsOneThread(testing::uniformPoints(120000, 3), true);
}

TEST(Threads, ClusteredPointsGiveOneThreadsTriangles) {
  expectSameAsOneThread(testing::gaussianClusters(120000, 4), true);
}

TEST(Threads, LatticeWithCocircularPointsEverywhereIsDelaunay) {
  expectSameAsOneThread(testing::latticePoints(260), false);
}

TEST(Threads, PointsOnOneCircleAreDelaunay) {
  expectSameAsOneThread(testing::circlePoints(70000), false);
}

// Circumcircles computed in doubles overflow or underflow at the extremes of the coordinate
// range: the join must then keep nothing it is unsure of, and still be right.
TEST(Threads, TinyAndHugeCoordinates) {
  const std::vector<double> xy = testing::uniformPoints(40000, 13);
  expectSameAsOneThread(testing::transformed(xy, 1e-200, 0, 0), true);
  expectSameAsOneThread(testing::transformed(xy, 1e140, -3e139, 1e139), true);
  expectSameAsOneThread(testing::transformed(xy, 1e-3, 1e6, -2e6), true);
}

TEST(Threads, DuplicatesNumberedAsOneThreadNumbersThem) {
  std::vector<double> xy = testing::uniformPoints(60000, 5);
  const std::vector<double> again = testing::uniformPoints(30000, 5);
  xy.insert(xy.end(), again.begin(), again.end());  // every point of again is a duplicate
  std::reverse(xy.begin(), xy.end());               // (y, x) pairs: the repeats come first
  EXPECT_EQ(triangulateWith(xy, 1).stats.duplicates, 30000u);
  expectSameAsOneThread(xy, true);
}

TEST(Threads, RunToRunIdentical) {
  const std::vector<double> xy = testing::uniformPoints(100000, 6);
  const Result a = triangulateWith(xy, 4), b = triangulateWith(xy, 4);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.halfedges, b.mesh.halfedges);
}

TEST(Threads, SmallBatchStaysOnOneThread) {
  const std::vector<double> xy = testing::uniformPoints(20000, 7);
  const Result r = triangulateWith(xy, 4);
  EXPECT_EQ(r.stats.threads, 1u);
  EXPECT_EQ(check(xy, r), "");
}

TEST(Threads, CollinearStripFallsBackToOneThread) {
  // Half the points on one vertical line: the right strip would be all collinear.
  std::vector<double> xy = testing::uniformPoints(50000, 8);
  testing::Random random(9);
  for (int i = 0; i < 50000; ++i) {
    xy.push_back(2.0);
    xy.push_back(static_cast<double>(random.next() % 1000000) / 1e6);
  }
  const Result r = triangulateWith(xy, 2);
  EXPECT_EQ(r.stats.threads, 1u);
  EXPECT_EQ(check(xy, r), "");
}

TEST(Threads, AllOnOneVerticalLineFallsBack) {
  std::vector<double> xy;
  for (int i = 0; i < 40000; ++i) {
    xy.push_back(1.0);
    xy.push_back(i);
  }
  xy.push_back(2.0);
  xy.push_back(0.5);
  const Result r = triangulateWith(xy, 2);
  EXPECT_EQ(r.stats.threads, 1u);
  EXPECT_EQ(check(xy, r), "");
}

// What comes after the points (more points, constraints) works on the joined triangulation.
TEST(Threads, ConstraintsAndMorePointsAfterTheStrips) {
  const std::vector<double> xy = testing::uniformPoints(100000, 10);
  testing::Random random(11);
  testing::Polylines lines;
  for (int i = 0; i < 200; ++i) {
    std::vector<double> line;
    for (int k = 0; k < 4; ++k) {
      line.push_back(static_cast<double>(random.next() % 1000000) / 1e6);
      line.push_back(static_cast<double>(random.next() % 1000000) / 1e6);
    }
    lines.push_back(line);
  }
  const std::vector<double> more = testing::uniformPoints(5000, 12);
  Mesh meshes[2];
  std::vector<std::uint32_t> ids[2];
  for (int r = 0; r < 2; ++r) {
    Options options;
    options.threads = r == 0 ? 1 : 2;
    Triangulation t(options);
    ids[r].resize(xy.size() / 2 + more.size() / 2 + 800);
    ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2, ids[r].data()).ok());
    EXPECT_EQ(t.stats().threads, r == 0 ? 1u : 2u);
    std::vector<PolylineView> views;
    for (const auto& line : lines) views.push_back({line.data(), line.size() / 2});
    ASSERT_TRUE(t.insertPolylines(views.data(), views.size(), ids[r].data() + xy.size() / 2).ok());
    ASSERT_TRUE(
        t.insertPoints(more.data(), more.size() / 2, ids[r].data() + xy.size() / 2 + 800).ok());
    MeshOptions mo;
    mo.segmentSources = true;
    meshes[r] = t.mesh(mo);
  }
  std::vector<double> all = xy;
  for (const auto& line : lines) all.insert(all.end(), line.begin(), line.end());
  all.insert(all.end(), more.begin(), more.end());
  testing::CheckOptions c;
  c.inputXY = &all;
  c.inputToVertex = &ids[1];
  EXPECT_EQ(testing::checkTriangulation(meshes[1], c), "");
  const std::vector<std::uint32_t> lineIds(ids[1].begin() + xy.size() / 2,
                                           ids[1].begin() + xy.size() / 2 + 800);
  EXPECT_EQ(testing::checkConstraints(meshes[1], lines, lineIds), "");
  EXPECT_EQ(ids[0], ids[1]);
  EXPECT_TRUE(testing::triangleSet(meshes[0]) == testing::triangleSet(meshes[1]));
}

TEST(Threads, ExportListsProvenanceAsOneThreadDoes) {
  // More than 65,536 constrained edges, so that the provenance is listed side by side: one
  // long ring through every point of a lattice row by row (each edge its own), plus lines
  // across it, some edges shared by two polylines (an overlap).
  testing::Polylines lines(1);
  testing::Random random(31);
  for (int y = 0; y < 300; ++y)
    for (int k = 0; k < 300; ++k) {
      const int x = y % 2 ? 299 - k : k;
      lines[0].push_back(x + static_cast<double>(random.next() % 1000) / 4000);
      lines[0].push_back(y + static_cast<double>(random.next() % 1000) / 4000);
    }
  for (int i = 0; i < 20; ++i) lines.push_back({0.5 + i * 10, 0.5, 290.5 - i * 10, 298.5});
  lines.push_back({lines[0][0], lines[0][1], lines[0][2], lines[0][3]});  // the ring's first edge
  Mesh meshes[3];
  for (std::uint32_t threads = 1; threads <= 3; ++threads) {
    Options options;
    options.threads = threads;
    Triangulation t(options);
    std::vector<PolylineView> views;
    for (const auto& line : lines) views.push_back({line.data(), line.size() / 2});
    ASSERT_TRUE(t.insertPolylines(views.data(), views.size()).ok());
    MeshOptions mo;
    mo.segmentSources = true;
    meshes[threads - 1] = t.mesh(mo);
  }
  ASSERT_GT(meshes[0].constraintEdges.size(), 65536u);
  // The slots' order differs between thread counts (the ring's points went in as strips), so
  // each edge's provenance is compared by its vertices (numbered alike), and the listing
  // order checked: by half-edge, each edge once, from the lower of its two.
  using Sources = std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>>;
  const auto provenance = [](const Mesh& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, Sources> out;
    for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
      const std::uint32_t e = m.constraintEdges[i];
      const std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
      Sources& at = out[{std::min(u, v), std::max(u, v)}];
      at.first.assign(m.sources.begin() + m.sourceOffsets[i],
                      m.sources.begin() + m.sourceOffsets[i + 1]);
      at.second.assign(m.segmentSources.begin() + m.segmentOffsets[i],
                       m.segmentSources.begin() + m.segmentOffsets[i + 1]);
    }
    return out;
  };
  const auto expected = provenance(meshes[0]);
  for (int r = 1; r < 3; ++r) {
    const Mesh& m = meshes[r];
    EXPECT_EQ(m.sourceOffsets.size(), m.constraintEdges.size() + 1);
    EXPECT_EQ(m.segmentOffsets.size(), m.constraintEdges.size() + 1);
    bool ordered = true;
    for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
      const std::int32_t e = static_cast<std::int32_t>(m.constraintEdges[i]);
      ordered &= (i == 0 || m.constraintEdges[i - 1] < m.constraintEdges[i]) &&
                 (m.halfedges[e] < 0 || m.halfedges[e] > e);
    }
    EXPECT_TRUE(ordered) << r + 1 << " threads";
    EXPECT_TRUE(provenance(m) == expected) << r + 1 << " threads";
  }
}

TEST(Threads, CoordinatesCheckedSideBySideNameTheFirstBadPoint) {
  // Bad values in both halves: the one in the first half is named, as one thread names it.
  std::vector<double> xy = testing::uniformPoints(100000, 21);
  xy[2 * 70000 + 1] = std::nan("");
  xy[2 * 30000] = 1e200;
  for (std::uint32_t threads = 1; threads <= 4; ++threads) {
    Options options;
    options.threads = threads;
    Triangulation t(options);
    const Status s = t.insertPoints(xy.data(), xy.size() / 2);
    EXPECT_EQ(s.code, StatusCode::InvalidCoordinate) << threads;
    EXPECT_EQ(s.index, 30000u) << threads;
    EXPECT_EQ(s.message, "point 30000 has x = " + std::to_string(1e200) +
                             ": coordinates must lie within +-1e150")
        << threads;
    EXPECT_EQ(t.vertexCount(), 0u) << threads;
  }
}

// Polygon batches: ranges of polygons taken in turn by the threads, joined in polygon order.
// Polygons of 4 to about 400 points, every fifth with a bow-tie hole whose crossing adds an
// extra point, so that ranges renumber extras when joined.
TEST(Threads, PolygonBatchGivesOneThreadsArrays) {
  std::vector<double> xy;
  std::vector<std::uint32_t> rings{0}, polygons{0};
  std::uint32_t seed = 7;
  const auto next = [&seed] { return seed = seed * 1103515245u + 12345u; };
  for (int p = 0; p < 1500; ++p) {
    const double cx = 100.0 * (p % 40), cy = 100.0 * (p / 40);
    const int n = 4 + static_cast<int>(next() >> 16) % (p % 7 == 0 ? 400 : 40);
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * 3.14159265358979 * k / n;
      const double radius = 30 + static_cast<double>((next() >> 16) % 15);
      xy.insert(xy.end(), {cx + radius * std::cos(angle), cy + radius * std::sin(angle)});
    }
    rings.push_back(static_cast<std::uint32_t>(xy.size() / 2));
    if (p % 5 == 0) {  // a bow tie: its two middle segments cross
      xy.insert(xy.end(), {cx - 10, cy - 10, cx + 10, cy + 10, cx + 10, cy - 10, cx - 10, cy + 10});
      rings.push_back(static_cast<std::uint32_t>(xy.size() / 2));
    }
    polygons.push_back(static_cast<std::uint32_t>(rings.size() - 1));
  }
  PolygonBatch batch;
  batch.xy = xy.data();
  batch.pointCount = xy.size() / 2;
  batch.ringOffsets = rings.data();
  batch.ringCount = rings.size() - 1;
  batch.polygonOffsets = polygons.data();
  batch.polygonCount = polygons.size() - 1;
  ASSERT_GT(batch.pointCount, 40000u);  // enough for threads
  PolygonTriangles one;
  PolygonStats oneStats;
  ASSERT_TRUE(triangulatePolygons(batch, PolygonOptions(), one, &oneStats).ok());
  EXPECT_EQ(oneStats.crossings, 300u);
  for (const std::uint32_t threads : {2u, 3u, 4u}) {
    PolygonOptions options;
    options.threads = threads;
    PolygonTriangles many;
    PolygonStats stats;
    ASSERT_TRUE(triangulatePolygons(batch, options, many, &stats).ok()) << threads;
    EXPECT_EQ(stats.threads, threads);
    EXPECT_EQ(stats.crossings, oneStats.crossings);
    EXPECT_EQ(many.triangles, one.triangles) << threads;
    EXPECT_EQ(many.extraPoints, one.extraPoints) << threads;
    EXPECT_EQ(many.triangleOffsets, one.triangleOffsets) << threads;
  }
}
}  // namespace
}  // namespace geocdt
