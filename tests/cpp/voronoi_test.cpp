// Voronoi cells clipped to boxes, hulls and rings: every result checked by voronoi_checks (the
// cells tile the domain, share their edges, keep their vertices nearest their own site, and hold
// random sample points exactly when those are nearest their site).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geocdt/voronoi.h"
#include "point_generators.h"
#include "voronoi_checks.h"

namespace geocdt {
namespace {

using testing::checkVoronoi;

VoronoiCells clipToBox(const std::vector<double>& sites, const double box[4],
                       std::uint32_t threads = 1) {
  VoronoiOptions o;
  o.clip = VoronoiClip::Box;
  for (int i = 0; i < 4; ++i) o.box[i] = box[i];
  o.threads = threads;
  VoronoiCells cells;
  const Status s = voronoi(sites.data(), sites.size() / 2, nullptr, 0, o, cells);
  EXPECT_TRUE(s.ok()) << s.message;
  return cells;
}

VoronoiCells clipToRings(const std::vector<double>& sites, const std::vector<PolylineView>& rings,
                         FillRule fill = FillRule::EvenOdd) {
  VoronoiOptions o;
  o.fill = fill;
  VoronoiCells cells;
  const Status s = voronoi(sites.data(), sites.size() / 2, rings.data(), rings.size(), o, cells);
  EXPECT_TRUE(s.ok()) << s.message;
  return cells;
}

std::size_t polygonsOf(const VoronoiCells& c, std::size_t site) {
  return c.siteOffsets[site + 1] - c.siteOffsets[site];
}

TEST(Voronoi, UniformSitesInABox) {
  const std::vector<double> sites = testing::uniformPoints(2000, 1);
  const double box[4] = {0, 0, 1, 1};
  const VoronoiCells cells = clipToBox(sites, box);
  testing::VoronoiReport report;
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 3000, 1e-12, &report), "");
  EXPECT_EQ(report.polygons, 2000u);
  EXPECT_GT(report.samples, 2500u);
}

TEST(Voronoi, OneSiteGetsTheWholeBox) {
  const std::vector<double> sites = {0.25, 0.5};
  const double box[4] = {-1, -2, 3, 4};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 500, 0), "");
  ASSERT_EQ(cells.ringOffsets.size(), 2u);
  EXPECT_EQ(cells.ringOffsets[1], 5u);
}

}  // namespace
}  // namespace geocdt
