// Real GIS data: Natural Earth countries at three scales (every ring alone, so that shared
// borders overlap; and the mesh of arcs) and US counties. Crossings, T-junctions, collinear
// overlaps and repeated points all occur here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "constraint_invariants.h"
#include "geocdt/predicates.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"
#include "polyline_file.h"
#include "refinement_checks.h"

namespace geocdt {
namespace {

struct Loaded {
  testing::PolylineSet set;
  testing::Polylines lines;
};

Loaded load(const std::string& name) {
  Loaded l;
  const std::string error =
      testing::readPolylineFile(std::string(GEOCDT_REAL_DATA_DIR) + "/" + name, l.set);
  EXPECT_EQ(error, "");
  for (std::size_t i = 0; i < l.set.polylineCount(); ++i)
    l.lines.emplace_back(l.set.xy.begin() + 2 * l.set.offsets[i],
                         l.set.xy.begin() + 2 * l.set.offsets[i + 1]);
  return l;
}

void checkDataset(const std::string& name, std::size_t minimumCrossings,
                  SnapRounding snapRounding = SnapRounding::WhenNeeded, std::uint32_t threads = 1) {
  const Loaded l = load(name);
  ASSERT_GT(l.set.pointCount(), 0u);
  const std::vector<PolylineView> views = l.set.views();
  Options options;
  options.snapRounding = snapRounding;
  options.threads = threads;
  Triangulation t(options);
  std::vector<std::uint32_t> ids(l.set.pointCount());
  const Status s = t.insertPolylines(views.data(), views.size(), ids.data());
  ASSERT_TRUE(s.ok()) << s.message;
  // Every dataset here has enough points for strips on every thread asked for.
  EXPECT_EQ(t.stats().threads, threads);
  EXPECT_GE(t.stats().crossings, minimumCrossings);
  // Real data keeps every computed crossing: none of it is a tangle.
  EXPECT_EQ(t.stats().snapRoundings, snapRounding == SnapRounding::Always ? 1u : 0u);
  MeshOptions mo;
  mo.insideFlags = true;
  mo.segmentSources = true;  // each segment's chain as routed, for the checker
  const Mesh m = t.mesh(mo);
  testing::CheckOptions c;
  c.inputXY = &l.set.xy;
  c.inputToVertex = &ids;
  EXPECT_EQ(testing::checkTriangulation(m, c), "");
  EXPECT_EQ(testing::checkConstraints(m, l.lines, ids, true), "");

  // Inside flags against ray casting over the input rings, on a sample of triangles away
  // from the rings (where rounding of crossing points cannot matter).
  bool anyRing = false;
  for (const auto& line : l.lines)
    anyRing |= line.size() >= 6 && line[0] == line[line.size() - 2] && line[1] == line.back();
  if (!anyRing) return;
  testing::Random r(1);
  int compared = 0;
  for (int i = 0; i < 150; ++i) {
    const std::size_t tri = r.next() % (m.triangles.size() / 3);
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += m.points[2 * m.triangles[3 * tri + k]] / 3;
      y += m.points[2 * m.triangles[3 * tri + k] + 1] / 3;
    }
    if (testing::distanceToPolylines(l.lines, x, y) < 1e-9) continue;
    EXPECT_EQ(m.inside[tri] != 0, testing::insideEvenOdd(l.lines, x, y))
        << name << " triangle at " << x << ", " << y;
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

// The minimum crossings are well below what the data has: they show the crossing path ran.
TEST(RealData, NaturalEarth110mRings) { checkDataset("ne_110m_rings.gpl", 50); }
TEST(RealData, NaturalEarth110mArcs) { checkDataset("ne_110m_arcs.gpl", 50); }
TEST(RealData, NaturalEarth50mRings) { checkDataset("ne_50m_rings.gpl", 100); }
TEST(RealData, NaturalEarth50mArcs) { checkDataset("ne_50m_arcs.gpl", 100); }
TEST(RealData, NaturalEarth10mRings) { checkDataset("ne_10m_rings.gpl", 400); }
TEST(RealData, NaturalEarth10mArcs) { checkDataset("ne_10m_arcs.gpl", 400); }
TEST(RealData, UsCountiesRings) { checkDataset("us_counties_rings.gpl", 0); }
// Snap rounding everywhere keeps the guarantee on real data too.
// The same on 2 and 4 threads: the points in strips, joined, then the constraints.
class RealDataOnThreads : public ::testing::TestWithParam<std::uint32_t> {};
TEST_P(RealDataOnThreads, NaturalEarth50mRings) {
  checkDataset("ne_50m_rings.gpl", 100, SnapRounding::WhenNeeded, GetParam());
}
TEST_P(RealDataOnThreads, NaturalEarth50mArcs) {
  checkDataset("ne_50m_arcs.gpl", 100, SnapRounding::WhenNeeded, GetParam());
}
TEST_P(RealDataOnThreads, NaturalEarth10mRings) {
  checkDataset("ne_10m_rings.gpl", 400, SnapRounding::WhenNeeded, GetParam());
}
TEST_P(RealDataOnThreads, NaturalEarth10mArcs) {
  checkDataset("ne_10m_arcs.gpl", 400, SnapRounding::WhenNeeded, GetParam());
}
TEST_P(RealDataOnThreads, UsCountiesRings) {
  checkDataset("us_counties_rings.gpl", 0, SnapRounding::WhenNeeded, GetParam());
}
TEST_P(RealDataOnThreads, NaturalEarth50mRingsSnapRounded) {
  checkDataset("ne_50m_rings.gpl", 100, SnapRounding::Always, GetParam());
}
INSTANTIATE_TEST_SUITE_P(Threads, RealDataOnThreads, ::testing::Values(2u, 4u));

TEST(RealData, NaturalEarth50mRingsSnapRounded) {
  checkDataset("ne_50m_rings.gpl", 100, SnapRounding::Always);
}

// Region labels on countries (and counties) whose rings share borders, touch at vertices and
// cross where the data is imprecise: a triangle's label must be the country whose rings hold
// its centroid by an exact even-odd test against the input rings. Centroids within 1e-9 of a
// ring are skipped: there the rounding of crossing points may put the mesh on either side.
struct RingTest {
  int winding = 0;
  double distance = 1e300;
};

void addRing(const std::vector<double>& ring, double x, double y, RingTest& r) {
  for (std::size_t k = 0; k + 3 < ring.size(); k += 2) {
    const double ax = ring[k], ay = ring[k + 1], bx = ring[k + 2], by = ring[k + 3];
    const Sign side = orient2d(ax, ay, bx, by, x, y);
    if (ay <= y && by > y && side == Sign::Positive) ++r.winding;
    if (by <= y && ay > y && side == Sign::Negative) --r.winding;
    const double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
    double t = length2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / length2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    r.distance = std::min(r.distance, std::hypot(ax + t * dx - x, ay + t * dy - y));
  }
}

void checkRegions(const std::string& name, std::size_t samples, std::uint32_t threads = 1) {
  const Loaded l = load(name + ".gpl");
  std::vector<std::int32_t> polygonOf;
  ASSERT_EQ(
      testing::readPolygonFile(std::string(GEOCDT_REAL_DATA_DIR) + "/" + name + ".gpg", polygonOf),
      "");
  ASSERT_EQ(polygonOf.size(), l.lines.size());
  const std::size_t polygons = static_cast<std::size_t>(polygonOf.back()) + 1;
  std::vector<std::vector<std::size_t>> rings(polygons);
  std::vector<std::array<double, 4>> box(polygons, {1e300, 1e300, -1e300, -1e300});
  for (std::size_t i = 0; i < l.lines.size(); ++i) {
    rings[polygonOf[i]].push_back(i);
    std::array<double, 4>& b = box[polygonOf[i]];
    for (std::size_t k = 0; k < l.lines[i].size(); k += 2) {
      b = {std::min(b[0], l.lines[i][k]), std::min(b[1], l.lines[i][k + 1]),
           std::max(b[2], l.lines[i][k]), std::max(b[3], l.lines[i][k + 1])};
    }
  }
  const std::vector<PolylineView> views = l.set.views();
  Options options;
  options.threads = threads;
  Triangulation t(options);
  ASSERT_TRUE(t.insertPolylines(views.data(), views.size()).ok());
  MeshOptions mo;
  mo.regions = true;
  mo.polylinePolygons = polygonOf;
  const Mesh m = t.mesh(mo);
  const std::size_t n = m.triangles.size() / 3;
  ASSERT_EQ(m.regions.size(), n);

  // Which polygons hold each sampled centroid, exactly; and, when every triangle is checked,
  // each polygon's area from the triangles found inside it, to check the overlap rule.
  testing::Random r(5);
  const bool all = samples >= n;
  std::vector<std::pair<std::size_t, std::vector<std::int32_t>>> found;
  std::vector<double> area(polygons, 0.0);
  std::size_t checked = 0, labelled = 0;
  for (std::size_t i = 0; i < std::min(samples, n); ++i) {
    const std::size_t tri = all ? i : r.next() % n;
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += m.points[2 * m.triangles[3 * tri + k]] / 3;
      y += m.points[2 * m.triangles[3 * tri + k] + 1] / 3;
    }
    constexpr double kNear = 1e-9;
    std::vector<std::int32_t> holders;
    bool near = false;
    for (std::size_t g = 0; g < polygons && !near; ++g) {
      const std::array<double, 4>& b = box[g];
      if (x < b[0] - kNear || y < b[1] - kNear || x > b[2] + kNear || y > b[3] + kNear) continue;
      RingTest test;
      for (const std::size_t ring : rings[g]) addRing(l.lines[ring], x, y, test);
      near = test.distance < kNear;
      if (test.winding % 2 != 0) holders.push_back(static_cast<std::int32_t>(g));
    }
    if (near) continue;
    ++checked;
    const std::int32_t label = m.regions[tri];
    labelled += label >= 0;
    if (holders.empty()) {
      EXPECT_EQ(label, -1) << name << " triangle at " << x << ", " << y;
      continue;
    }
    EXPECT_NE(std::find(holders.begin(), holders.end(), label), holders.end())
        << name << " triangle at " << x << ", " << y << " labelled " << label;
    const double* p = m.points.data();
    const std::uint32_t a = m.triangles[3 * tri], b = m.triangles[3 * tri + 1],
                        c = m.triangles[3 * tri + 2];
    for (const std::int32_t g : holders)
      area[g] += ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
                  (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) /
                 2;
    found.push_back({tri, std::move(holders)});
  }
  EXPECT_GT(checked, std::min(samples, n) / 2);
  EXPECT_GT(labelled, checked / 4);
  // Where the data's polygons overlap (rings across the antimeridian span the whole plane),
  // the label is the holder of least area, when the areas differ clearly.
  std::size_t overlaps = 0;
  for (const auto& [tri, holders] : found) {
    if (!all || holders.size() < 2) continue;
    std::vector<std::int32_t> bySize = holders;
    std::sort(bySize.begin(), bySize.end(),
              [&](std::int32_t u, std::int32_t v) { return area[u] < area[v]; });
    if (area[bySize[1]] < 1.01 * area[bySize[0]]) continue;
    EXPECT_EQ(m.regions[tri], bySize[0]) << name << " triangle " << tri;
    ++overlaps;
  }
  if (all) EXPECT_GT(overlaps, 0u);
}

TEST(RealData, RegionsOfNaturalEarth110mCountries) { checkRegions("ne_110m_rings", 1u << 30); }
TEST(RealData, RegionsOfNaturalEarth50mCountries) { checkRegions("ne_50m_rings", 3000); }
TEST(RealData, RegionsOfNaturalEarth10mCountries) { checkRegions("ne_10m_rings", 1000); }
TEST(RealData, RegionsOfUsCounties) { checkRegions("us_counties_rings", 10000); }
// The same on 2 and 4 threads: the strips, then the export's loops side by side.
class RegionsOnThreads : public ::testing::TestWithParam<std::uint32_t> {};
TEST_P(RegionsOnThreads, NaturalEarth10mCountries) {
  checkRegions("ne_10m_rings", 1000, GetParam());
}
TEST_P(RegionsOnThreads, UsCounties) { checkRegions("us_counties_rings", 10000, GetParam()); }
INSTANTIATE_TEST_SUITE_P(Threads, RegionsOnThreads, ::testing::Values(2u, 4u));

TEST(RealData, CountriesAsPointsAndScaled) {
  // The same vertices as a point set, and the 50m rings scaled and moved far away.
  const Loaded l = load("ne_50m_rings.gpl");
  Mesh m;
  std::vector<std::uint32_t> ids;
  ASSERT_TRUE(triangulate(l.set.xy.data(), l.set.pointCount(), nullptr, 0, {}, {}, m, &ids).ok());
  testing::CheckOptions c;
  c.inputXY = &l.set.xy;
  c.inputToVertex = &ids;
  EXPECT_EQ(testing::checkTriangulation(m, c), "");

  testing::Polylines moved;
  for (const auto& line : l.lines)
    moved.push_back(testing::transformed(line, 111319.49, 1.6e7, -4e6));
  std::vector<PolylineView> views;
  for (const auto& line : moved) views.push_back({line.data(), line.size() / 2});
  Triangulation t;
  std::vector<std::uint32_t> ids2(l.set.pointCount());
  ASSERT_TRUE(t.insertPolylines(views.data(), views.size(), ids2.data()).ok());
  const Mesh m2 = t.mesh();
  EXPECT_EQ(testing::checkTriangulation(m2), "");
  EXPECT_EQ(testing::checkConstraints(m2, moved, ids2), "");
}

// Refinement of country and county rings, inside only: a valid CDT of the rings, Steiner
// records that place their vertices, and every inside triangle within minAngle except those
// the stats own up to (corners where the data's segments meet at smaller angles: a small
// share of them). `polylines` takes the first that many rings.
void checkRefinedDataset(const std::string& name, double minAngle, std::size_t polylines) {
  const Loaded all = load(name);
  testing::PolylineSet set;
  testing::Polylines lines;
  for (std::size_t i = 0; i < std::min(polylines, all.lines.size()); ++i) {
    set.add(all.lines[i].data(), all.lines[i].size() / 2);
    lines.push_back(all.lines[i]);
  }
  const std::vector<PolylineView> views = set.views();
  Triangulation t;
  std::vector<std::uint32_t> ids(set.pointCount());
  ASSERT_TRUE(t.insertPolylines(views.data(), views.size(), ids.data()).ok());
  RefineOptions ro;
  ro.minAngle = minAngle;
  ro.keep = Keep::Inside;
  ASSERT_TRUE(t.refine(ro).ok());
  const Stats stats = t.stats();
  EXPECT_FALSE(stats.refineCapped) << name;
  MeshOptions mo;
  mo.insideFlags = true;
  const Mesh m = t.mesh(mo);
  std::size_t inside = 0;
  for (const std::uint8_t f : m.inside) inside += f;
  EXPECT_GT(stats.steinerPoints, 0u);
  EXPECT_LT(stats.refineSkipped * 50, inside) << name << ": " << stats.refineSkipped;
  EXPECT_EQ(testing::checkRefined(m, {}, lines, ids, minAngle, 0, true, stats.refineSkipped), "")
      << name;
}

TEST(RealData, RefineNaturalEarth110mCountriesInside) {
  checkRefinedDataset("ne_110m_rings.gpl", 20, 1u << 30);
  checkRefinedDataset("ne_110m_rings.gpl", 30, 1u << 30);
}
// maxArea holds on every triangle (as Triangle's -a does), in corners of small input angles
// and where a triangle's circumcentre lies across a subsegment it may not split: 2 triangles of
// the Natural Earth 50m rings stayed larger than 0.05 square degrees at 30 degrees.
TEST(RealData, RefineNaturalEarth50mToAMaximumArea) {
  testing::PolylineSet set;
  ASSERT_EQ(testing::readPolylineFile(std::string(GEOCDT_REAL_DATA_DIR) + "/ne_50m_rings.gpl", set),
            "");
  Triangulation t;
  const std::vector<PolylineView> views = set.views();
  std::vector<std::uint32_t> ids(set.pointCount());
  ASSERT_TRUE(t.insertPolylines(views.data(), views.size(), ids.data()).ok());
  RefineOptions ro;
  ro.minAngle = 30;
  ro.maxArea = 0.05;
  ro.keep = Keep::Inside;
  ASSERT_TRUE(t.refine(ro).ok());
  MeshOptions mo;
  mo.keep = Keep::Inside;
  const Mesh m = t.mesh(mo);
  EXPECT_FALSE(t.stats().refineCapped);
  // Only the inside is exported: every triangle counts.
  EXPECT_EQ(testing::countBadTriangles(m, 0, ro.maxArea, false), 0u);
  EXPECT_EQ(testing::countBadTriangles(m, 30, ro.maxArea, false), t.stats().refineSkipped);
}

TEST(RealData, RefineUsCountiesInside) { checkRefinedDataset("us_counties_rings.gpl", 30, 400); }

}  // namespace
}  // namespace geocdt
