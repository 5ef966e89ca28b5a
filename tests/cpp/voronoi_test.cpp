// Voronoi cells clipped to boxes, hulls and rings: every result checked by voronoi_checks (the
// cells tile the domain, share their edges, keep their vertices nearest their own site, and hold
// random sample points exactly when those are nearest their site).
#include <gtest/gtest.h>

#include <algorithm>
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

TEST(Voronoi, ClusteredSitesInABox) {
  const std::vector<double> sites = testing::gaussianClusters(3000, 2);
  const double box[4] = {-2, -2, 2, 2};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 3000, 1e-12), "");
}

// A lattice: four sites cocircular around every Voronoi vertex, sites on the box's sides, and
// (with the half-offset box) box sides through Voronoi vertices and along Voronoi edges.
TEST(Voronoi, LatticeSitesInBoxesOnTheirDegeneracies) {
  const std::vector<double> sites = testing::latticePoints(20);
  for (const double margin : {0.0, 0.5, 0.25, 3.0}) {
    const double box[4] = {-margin, -margin, 19 + margin, 19 + margin};
    const VoronoiCells cells = clipToBox(sites, box);
    EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 2000, 1e-12), "")
        << "margin " << margin;
    std::size_t empty = 0;
    for (std::size_t i = 0; i < 400; ++i) empty += polygonsOf(cells, i) == 0;
    EXPECT_EQ(empty, 0u);
  }
}

// A lattice at 0.1 spacing: the sites are rounded, nearly cocircular, so circumcentres of one
// square's two triangles land a few ulps apart in either order.
TEST(Voronoi, RoundedLatticeSites) {
  std::vector<double> sites = testing::transformed(testing::latticePoints(30), 0.1, 0, 0);
  for (double& v : sites) v = static_cast<double>(static_cast<float>(v * 1.0));
  const double box[4] = {0.05, 0.05, 2.85, 2.85};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 2000, 1e-12), "");
}

TEST(Voronoi, CollinearSitesMakeStrips) {
  for (const bool diagonal : {false, true}) {
    std::vector<double> sites;
    for (int i = 0; i < 50; ++i) sites.insert(sites.end(), {i * 0.5, diagonal ? i * 0.25 : 3.0});
    const double box[4] = {-5, -5, 30, 20};
    const VoronoiCells cells = clipToBox(sites, box);
    EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 2000, 1e-12), "");
    for (std::size_t i = 0; i < 50; ++i) EXPECT_EQ(polygonsOf(cells, i), 1u);
  }
}

TEST(Voronoi, TwoSitesSplitTheBox) {
  const std::vector<double> sites = {1, 1, 3, 1};
  const double box[4] = {0, 0, 4, 2};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 500, 0), "");
  ASSERT_EQ(cells.ringOffsets.size(), 3u);
  EXPECT_EQ(cells.ringOffsets[1], 5u);  // a rectangle each
  EXPECT_EQ(cells.ringOffsets[2], 10u);
}

// Equal sites: the first one gets the cell, the others an empty one.
TEST(Voronoi, EqualSitesShareTheFirstOnesCell) {
  std::vector<double> sites = testing::uniformPoints(200, 3);
  const std::vector<double> copy(sites.begin(), sites.begin() + 40);
  sites.insert(sites.end(), copy.begin(), copy.end());
  const double box[4] = {0, 0, 1, 1};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 2000, 1e-12), "");
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(polygonsOf(cells, i), 1u);
    EXPECT_EQ(polygonsOf(cells, 200 + i), 0u);
  }
}

TEST(Voronoi, SitesOutsideTheBoxReachIntoIt) {
  std::vector<double> sites = testing::uniformPoints(300, 4);
  for (double& v : sites) v = v * 3 - 1;  // [-1, 2)^2 around the unit box
  const double box[4] = {0, 0, 1, 1};
  const VoronoiCells cells = clipToBox(sites, box);
  EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 3000, 1e-12), "");
  std::size_t outsideWithCells = 0;
  for (std::size_t i = 0; i < 300; ++i) {
    const bool outside =
        sites[2 * i] < 0 || sites[2 * i] > 1 || sites[2 * i + 1] < 0 || sites[2 * i + 1] > 1;
    outsideWithCells += outside && polygonsOf(cells, i) > 0;
  }
  EXPECT_GT(outsideWithCells, 5u);
}

TEST(Voronoi, HullClip) {
  for (const auto& sites :
       {testing::uniformPoints(1000, 5), testing::latticePoints(12), testing::circlePoints(64)}) {
    VoronoiOptions o;
    o.clip = VoronoiClip::Hull;
    VoronoiCells cells;
    ASSERT_TRUE(voronoi(sites.data(), sites.size() / 2, nullptr, 0, o, cells).ok());
    const testing::CheckDomain hull = testing::hullCheckDomain(sites);
    EXPECT_EQ(checkVoronoi(cells, sites, hull, 2000, 1e-12), "");
    EXPECT_NEAR(cells.stats.domainArea, hull.area, 1e-12 * hull.area);
  }
}

TEST(Voronoi, HullOfCollinearSitesIsEmpty) {
  const std::vector<double> sites = {0, 0, 1, 1, 2, 2, 3, 3};
  VoronoiOptions o;
  o.clip = VoronoiClip::Hull;
  VoronoiCells cells;
  ASSERT_TRUE(voronoi(sites.data(), 4, nullptr, 0, o, cells).ok());
  EXPECT_EQ(cells.siteOffsets, std::vector<std::uint32_t>(5, 0));
}

// A square with a square hole; sites inside, in the hole and outside.
TEST(Voronoi, RingsWithAHole) {
  const std::vector<double> outer = {0, 0, 10, 0, 10, 10, 0, 10, 0, 0};
  const std::vector<double> hole = {3, 3, 7, 3, 7, 7, 3, 7, 3, 3};
  const std::vector<PolylineView> rings = {{outer.data(), 5}, {hole.data(), 5}};
  std::vector<double> sites = testing::uniformPoints(400, 6);
  for (double& v : sites) v = v * 14 - 2;
  const VoronoiCells cells = clipToRings(sites, rings);
  const testing::CheckDomain domain = testing::ringCheckDomain(rings, FillRule::EvenOdd);
  EXPECT_NEAR(domain.area, 84, 1e-12);
  EXPECT_EQ(checkVoronoi(cells, sites, domain, 4000, 1e-12), "");
}

// One site and a domain of many parts with holes: its cell is all of it, holes included.
TEST(Voronoi, OneSiteGetsAllTheRings) {
  const std::vector<double> outer = {0, 0, 10, 0, 10, 10, 0, 10, 0, 0};
  const std::vector<double> hole = {3, 3, 7, 3, 7, 7, 3, 7, 3, 3};
  const std::vector<double> island = {4, 4, 6, 4, 6, 6, 4, 6, 4, 4};
  const std::vector<double> far = {20, 0, 21, 0, 21, 1, 20, 0};
  const std::vector<PolylineView> rings = {
      {outer.data(), 5}, {hole.data(), 5}, {island.data(), 5}, {far.data(), 4}};
  const std::vector<double> sites = {5, 5};
  const VoronoiCells cells = clipToRings(sites, rings);
  const testing::CheckDomain domain = testing::ringCheckDomain(rings, FillRule::EvenOdd);
  EXPECT_EQ(checkVoronoi(cells, sites, domain, 2000, 1e-12), "");
  EXPECT_EQ(polygonsOf(cells, 0), 3u);  // the square with its hole, the island, the triangle
  EXPECT_EQ(cells.ringOffsets.size() - 1, 4u);
}

// Two squares sharing a side are one domain (the shared side bounds nothing); nonzero fill with
// a clockwise ring inside a counter-clockwise one makes a hole.
TEST(Voronoi, SharedBordersAndNonzeroFill) {
  const std::vector<double> left = {0, 0, 5, 0, 5, 5, 0, 5, 0, 0};
  const std::vector<double> right = {5, 0, 10, 0, 10, 5, 5, 5, 5, 0};
  const std::vector<double> lake = {6, 1, 6, 4, 9, 4, 9, 1, 6, 1};  // clockwise
  const std::vector<PolylineView> rings = {{left.data(), 5}, {right.data(), 5}, {lake.data(), 5}};
  std::vector<double> sites = testing::uniformPoints(150, 7);
  for (std::size_t i = 0; i < sites.size(); ++i) sites[i] *= i % 2 == 0 ? 10 : 5;
  for (const FillRule fill : {FillRule::EvenOdd, FillRule::NonZero}) {
    const VoronoiCells cells = clipToRings(sites, rings, fill);
    const testing::CheckDomain domain = testing::ringCheckDomain(rings, fill);
    EXPECT_NEAR(domain.area, 41, 1e-12);
    EXPECT_EQ(checkVoronoi(cells, sites, domain, 3000, 1e-12), "");
  }
}

// Ties: a ring vertex equidistant from two sites, ring segments through a Voronoi vertex and
// along a Voronoi edge, sites on the ring.
TEST(Voronoi, RingsThroughTheDiagramsVertices) {
  const std::vector<double> sites = {0, 0, 2, 0, 0, 2, 2, 2, 1, 3};
  const std::vector<double> ring = {-1, 3, 1, 1, 3, -1, 3, 3, 1, 3, 1, 4, -1, 4, -1, 3};
  const std::vector<double> square = {0, 0, 2, 0, 2, 2, 0, 2, 0, 0};
  for (const auto* r : {&ring, &square}) {
    const std::vector<PolylineView> rings = {{r->data(), r->size() / 2}};
    const VoronoiCells cells = clipToRings(sites, rings);
    EXPECT_EQ(
        checkVoronoi(cells, sites, testing::ringCheckDomain(rings, FillRule::EvenOdd), 3000, 1e-12),
        "");
  }
}

// Lattice sites and rings on the lattice's half-integers: ring vertices at Voronoi vertices,
// ring segments along Voronoi edges, everywhere.
TEST(Voronoi, RingsAlongTheDiagramsEdges) {
  const std::vector<double> sites = testing::latticePoints(10);
  const std::vector<double> ring = {0.5, 0.5, 6.5, 0.5, 6.5, 3.5, 3.5, 3.5, 3.5,
                                    6.5, 8.5, 6.5, 8.5, 8.5, 0.5, 8.5, 0.5, 0.5};
  const std::vector<double> diamond = {4, 1, 7, 4, 4, 7, 1, 4, 4, 1};
  for (const auto* r : {&ring, &diamond}) {
    const std::vector<PolylineView> rings = {{r->data(), r->size() / 2}};
    const VoronoiCells cells = clipToRings(sites, rings);
    EXPECT_EQ(
        checkVoronoi(cells, sites, testing::ringCheckDomain(rings, FillRule::EvenOdd), 3000, 1e-12),
        "");
  }
}

// The same sites and box at scales from 1e-200 to 1e100: the same cells, scaled.
TEST(Voronoi, ScalesAndOffsets) {
  const std::vector<double> base = testing::uniformPoints(500, 8);
  for (const double scale : {0x1p-660, 0x1p-40, 1.0, 0x1p+330}) {
    for (const double offset : {0.0, 1e6}) {
      const std::vector<double> sites = testing::transformed(base, scale, offset * scale, 0);
      const double box[4] = {offset * scale, 0, offset * scale + scale, scale};
      const VoronoiCells cells = clipToBox(sites, box);
      EXPECT_EQ(checkVoronoi(cells, sites, testing::boxCheckDomain(box), 1000, 1e-9), "")
          << "scale " << scale << " offset " << offset;
    }
  }
}

TEST(Voronoi, LloydSpreadsTheSites) {
  std::vector<double> sites = testing::gaussianClusters(300, 9);
  const double box[4] = {-3, -3, 3, 3};
  VoronoiOptions o;
  o.clip = VoronoiClip::Box;
  for (int i = 0; i < 4; ++i) o.box[i] = box[i];
  double previous = INFINITY;
  for (const std::uint32_t steps : {1u, 5u, 20u}) {
    o.lloydIterations = steps;
    VoronoiCells cells;
    ASSERT_TRUE(voronoi(sites.data(), 300, nullptr, 0, o, cells).ok());
    EXPECT_EQ(cells.stats.lloydIterations, steps);
    EXPECT_LT(cells.stats.lloydMovement, previous);
    previous = cells.stats.lloydMovement;
    EXPECT_EQ(checkVoronoi(cells, cells.sites, testing::boxCheckDomain(box), 1000, 1e-12), "");
  }
  o.lloydIterations = 1000;
  o.lloydTolerance = 1e-3;
  VoronoiCells cells;
  ASSERT_TRUE(voronoi(sites.data(), 300, nullptr, 0, o, cells).ok());
  EXPECT_LT(cells.stats.lloydIterations, 1000u);
  EXPECT_LE(cells.stats.lloydMovement, 1e-3);
}

// Sites a few ulps apart at 1e150 x 1e100 (a fuzz finding): the centroid sums, cubes of the
// cells' coordinates relative to their sites, overflowed, and the moved sites were infinite.
TEST(Voronoi, LloydOnAHugeSliverKeepsTheSitesFinite) {
  const double x0 = -9.9999999999999998e+149, x1 = -9.9999999999999925e+149,
               x2 = -9.9999999999999707e+149, x3 = -9.999999999999978e+149;
  const double y0 = 1.0000000000000031e+100, y1 = 9.9999999999999768e+99,
               y2 = 1.0000000000000008e+100, y3 = 9.9999999999999924e+99,
               y4 = 1.0000000000000023e+100, y5 = 1.0000000000000016e+100;
  const std::vector<double> sites = {x0, y0, x0, y1, x0, y2, x1, y3, x0,
                                     y4, x2, y1, x0, y3, x3, y2, x0, y5};
  VoronoiOptions o;
  o.clip = VoronoiClip::Hull;
  o.lloydIterations = 2;
  VoronoiCells cells;
  ASSERT_TRUE(voronoi(sites.data(), sites.size() / 2, nullptr, 0, o, cells).ok());
  EXPECT_EQ(cells.stats.lloydIterations, 2u);
  for (const double v : cells.sites) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(checkVoronoi(cells, cells.sites, testing::hullCheckDomain(sites), 500, 1e-9), "");
}

// After a Lloyd step the domain is the first sites' hull, which the moved sites may leave: an
// uncut cell is then inside by its corners' windings, not because its site is (a fuzz finding:
// the guards' whole cells, 1e272 in area, came out as inside a hull of 3e219).
TEST(Voronoi, LloydKeepsTheFirstHullAsTheDomain) {
  const std::vector<double> sites = {-9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 1.0000000000000008e+100,
                                     -9.9999999999999998e+149, 1.0000000000000008e+100,
                                     -9.9999999999999962e+149, 1.0000000000000006e+100,
                                     -9.9999999999999998e+149, 9.9999999999999982e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 1e+100,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 1.0000000000000008e+100,
                                     -9.999999999999998e+149,  9.9999999999999963e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.999999999999998e+149,  9.9999999999999982e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99,
                                     -9.9999999999999998e+149, 9.9999999999999943e+99};
  VoronoiOptions o;
  o.clip = VoronoiClip::Hull;
  o.lloydIterations = 2;
  VoronoiCells cells;
  ASSERT_TRUE(voronoi(sites.data(), sites.size() / 2, nullptr, 0, o, cells).ok());
  EXPECT_EQ(checkVoronoi(cells, cells.sites, testing::hullCheckDomain(sites), 500, 1e-9), "");
}

// Enough sites for the threaded insertion's strips: the triangles' slots then differ from one
// thread's, and each cell's ring must still start at the same corner.
TEST(Voronoi, SameCellsOnAnyNumberOfThreads) {
  const std::vector<double> sites = testing::uniformPoints(40000, 12);
  const double box[4] = {0.1, 0.1, 0.9, 0.9};
  const VoronoiCells one = clipToBox(sites, box, 1);
  EXPECT_EQ(checkVoronoi(one, sites, testing::boxCheckDomain(box), 2000, 1e-12), "");
  for (const std::uint32_t threads : {2u, 3u}) {
    const VoronoiCells more = clipToBox(sites, box, threads);
    ASSERT_GT(more.stats.threads, 1u);
    EXPECT_EQ(more.siteOffsets, one.siteOffsets) << threads << " threads";
    EXPECT_EQ(more.polygonOffsets, one.polygonOffsets) << threads << " threads";
    EXPECT_EQ(more.ringOffsets, one.ringOffsets) << threads << " threads";
    EXPECT_TRUE(more.coords == one.coords) << threads << " threads";
  }
}

TEST(Voronoi, BadInputIsRefused) {
  const std::vector<double> sites = {0, 0, 1, 1};
  VoronoiOptions o;
  o.clip = VoronoiClip::Box;
  const double good[4] = {0, 0, 1, 1};
  std::copy(good, good + 4, o.box);
  VoronoiCells cells;
  EXPECT_EQ(voronoi(sites.data(), 0, nullptr, 0, o, cells).code, StatusCode::InvalidArgument);
  const std::vector<double> nan = {0, 0, NAN, 1};
  const Status s = voronoi(nan.data(), 2, nullptr, 0, o, cells);
  EXPECT_EQ(s.code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(s.index, 1u);
  o.box[2] = 0;
  EXPECT_EQ(voronoi(sites.data(), 2, nullptr, 0, o, cells).code, StatusCode::InvalidArgument);
  o.box[2] = NAN;
  EXPECT_EQ(voronoi(sites.data(), 2, nullptr, 0, o, cells).code, StatusCode::InvalidArgument);
  o.clip = VoronoiClip::Rings;
  EXPECT_EQ(voronoi(sites.data(), 2, nullptr, 0, o, cells).code, StatusCode::InvalidArgument);
  o.clip = VoronoiClip::Box;
  std::copy(good, good + 4, o.box);
  EXPECT_TRUE(voronoi(sites.data(), 2, nullptr, 0, o, cells).ok());
}

// The checker itself: a moved vertex, a dropped cell, a cell given to the wrong site.
TEST(Voronoi, CheckerFindsBrokenCells) {
  const std::vector<double> sites = testing::uniformPoints(100, 10);
  const double box[4] = {0, 0, 1, 1};
  const testing::CheckDomain domain = testing::boxCheckDomain(box);
  const VoronoiCells good = clipToBox(sites, box);
  ASSERT_EQ(checkVoronoi(good, sites, domain, 500, 1e-12), "");
  VoronoiCells moved = good;
  moved.coords[2 * moved.ringOffsets[10] + 2] += 1e-6;
  EXPECT_NE(checkVoronoi(moved, sites, domain, 500, 1e-3), "");
  VoronoiCells reversed = good;
  std::reverse(reversed.coords.begin() + 2 * reversed.ringOffsets[10],
               reversed.coords.begin() + 2 * reversed.ringOffsets[11]);
  for (std::uint32_t k = reversed.ringOffsets[10]; k < reversed.ringOffsets[11]; ++k)
    std::swap(reversed.coords[2 * k], reversed.coords[2 * k + 1]);  // (y, x) back to (x, y)
  EXPECT_EQ(checkVoronoi(reversed, sites, domain, 500, 1.0), "ring 10 winds the wrong way");
  VoronoiCells dropped = good;
  for (std::size_t i = 8; i < dropped.siteOffsets.size(); ++i) dropped.siteOffsets[i] -= 1;
  dropped.polygonOffsets.erase(dropped.polygonOffsets.begin() + 7);
  EXPECT_NE(checkVoronoi(dropped, sites, domain, 500, 1.0), "");
  std::vector<double> swapped = sites;
  std::swap(swapped[0], swapped[2]);
  std::swap(swapped[1], swapped[3]);
  EXPECT_NE(checkVoronoi(good, swapped, domain, 500, 1e-12), "");
}

}  // namespace
}  // namespace geocdt
