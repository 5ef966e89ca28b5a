// Voronoi cells clipped to real boundaries: the Natural Earth country rings (shared borders,
// islands, lakes, rings that touch) and the US counties, with uniform, clustered and lattice
// sites over their bounds and beyond. Every result goes through voronoi_checks.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geocdt/voronoi.h"
#include "point_generators.h"
#include "polyline_file.h"
#include "voronoi_checks.h"

namespace geocdt {
namespace {

struct Rings {
  testing::PolylineSet set;
  std::vector<PolylineView> views;
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
};

Rings load(const std::string& name) {
  Rings r;
  EXPECT_EQ(testing::readPolylineFile(std::string(GEOCDT_REAL_DATA_DIR) + "/" + name, r.set), "");
  r.views = r.set.views();
  r.minX = r.maxX = r.set.xy[0];
  r.minY = r.maxY = r.set.xy[1];
  for (std::size_t i = 0; i < r.set.pointCount(); ++i) {
    r.minX = std::min(r.minX, r.set.xy[2 * i]);
    r.maxX = std::max(r.maxX, r.set.xy[2 * i]);
    r.minY = std::min(r.minY, r.set.xy[2 * i + 1]);
    r.maxY = std::max(r.maxY, r.set.xy[2 * i + 1]);
  }
  return r;
}

// Points of the unit square mapped onto the rings' bounds grown by `margin` of their size.
std::vector<double> over(const Rings& r, std::vector<double> unit, double margin) {
  const double w = r.maxX - r.minX, h = r.maxY - r.minY;
  for (std::size_t i = 0; i < unit.size(); i += 2) {
    unit[i] = r.minX - margin * w + unit[i] * w * (1 + 2 * margin);
    unit[i + 1] = r.minY - margin * h + unit[i + 1] * h * (1 + 2 * margin);
  }
  return unit;
}

void check(const Rings& rings, const std::vector<double>& sites, std::size_t samples,
           const testing::CheckDomain& domain) {
  VoronoiOptions o;
  VoronoiCells cells;
  const Status s =
      voronoi(sites.data(), sites.size() / 2, rings.views.data(), rings.views.size(), o, cells);
  ASSERT_TRUE(s.ok()) << s.message;
  testing::VoronoiReport report;
  EXPECT_EQ(checkVoronoi(cells, sites, domain, samples, 1e-9, &report), "");
  EXPECT_NEAR(cells.stats.domainArea, static_cast<double>(domain.area),
              1e-12 * cells.stats.domainArea);
  EXPECT_GT(report.samples, samples / 5);
  EXPECT_GT(cells.stats.crossings, 0u);
}

TEST(VoronoiRealData, NaturalEarth50mRingsWith20000Sites) {
  const Rings rings = load("ne_50m_rings.gpl");
  const testing::CheckDomain domain = testing::ringCheckDomain(rings.views, FillRule::EvenOdd);
  check(rings, over(rings, testing::uniformPoints(20000, 1), 0.02), 20000, domain);
  check(rings, over(rings, testing::gaussianClusters(20000, 2), 0), 20000, domain);
}

TEST(VoronoiRealData, NaturalEarth110mRingsWithLatticeSites) {
  const Rings rings = load("ne_110m_rings.gpl");
  const testing::CheckDomain domain = testing::ringCheckDomain(rings.views, FillRule::EvenOdd);
  // Whole degrees: sites on the rings' own vertices, ring vertices on bisectors.
  std::vector<double> sites = testing::latticePoints(90);
  for (std::size_t i = 0; i < sites.size(); i += 2) {
    sites[i] = -180 + 4 * sites[i];
    sites[i + 1] = -90 + 2 * sites[i + 1];
  }
  check(rings, sites, 20000, domain);
  check(rings, over(rings, testing::uniformPoints(300, 3), 0.5), 5000, domain);
}

TEST(VoronoiRealData, UsCountiesWithSites) {
  Rings rings = load("us_counties_rings.gpl");
  const testing::CheckDomain domain = testing::ringCheckDomain(rings.views, FillRule::EvenOdd);
  check(rings, over(rings, testing::uniformPoints(10000, 4), 0.01), 20000, domain);
  // Clusters over the contiguous states (the bounds run across the antimeridian).
  rings.minX = -125;
  rings.maxX = -67;
  rings.minY = 25;
  rings.maxY = 49;
  check(rings, over(rings, testing::gaussianClusters(5000, 5), 0), 10000, domain);
}

}  // namespace
}  // namespace geocdt
