// Real GIS data: Natural Earth countries at three scales (every ring alone, so that shared
// borders overlap; and the mesh of arcs) and US counties. Crossings, T-junctions, collinear
// overlaps and repeated points all occur here.
#include <gtest/gtest.h>

#include <string>

#include "constraint_invariants.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"
#include "polyline_file.h"

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
                  SnapRounding snapRounding = SnapRounding::WhenNeeded) {
  const Loaded l = load(name);
  ASSERT_GT(l.set.pointCount(), 0u);
  const std::vector<PolylineView> views = l.set.views();
  Options options;
  options.snapRounding = snapRounding;
  Triangulation t(options);
  std::vector<std::uint32_t> ids(l.set.pointCount());
  const Status s = t.insertPolylines(views.data(), views.size(), ids.data());
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GE(t.stats().crossings, minimumCrossings);
  // Real data keeps every computed crossing: none of it is a tangle.
  EXPECT_EQ(t.stats().snapRoundings, snapRounding == SnapRounding::Always ? 1u : 0u);
  MeshOptions mo;
  mo.insideFlags = true;
  const Mesh m = t.mesh(mo);
  testing::CheckOptions c;
  c.inputXY = &l.set.xy;
  c.inputToVertex = &ids;
  EXPECT_EQ(testing::checkTriangulation(m, c), "");
  EXPECT_EQ(testing::checkConstraints(m, l.lines, ids), "");

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
TEST(RealData, NaturalEarth50mRingsSnapRounded) {
  checkDataset("ne_50m_rings.gpl", 100, SnapRounding::Always);
}

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

}  // namespace
}  // namespace geocdt
