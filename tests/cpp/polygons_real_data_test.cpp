// triangulatePolygons() on real data, every polygon held to the exact polygon checker: the
// real-world vector tiles of @mapbox/mvt-fixtures, Natural Earth 10m countries cut into tiles
// by geojson-vt, Natural Earth countries (one polygon per country, all its rings) and US
// counties.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geocdt/polygons.h"
#include "polygon_checks.h"
#include "polyline_file.h"

namespace geocdt {
namespace {

struct Loaded {
  testing::PolylineSet rings;
  std::vector<std::uint32_t> polygons{0};

  PolygonBatch batch() const {
    return {rings.xy.data(),       rings.pointCount(), rings.offsets.data(),
            rings.polylineCount(), polygons.data(),    polygons.size() - 1};
  }
};

// name.gpl (rings) grouped into polygons by name.gpg.
Loaded load(const std::string& name) {
  Loaded l;
  const std::string dir = std::string(GEOCDT_REAL_DATA_DIR) + "/";
  EXPECT_EQ(testing::readPolylineFile(dir + name + ".gpl", l.rings), "");
  std::vector<std::int32_t> polygonOf;
  EXPECT_EQ(testing::readPolygonFile(dir + name + ".gpg", polygonOf), "");
  for (std::size_t r = 0; r < polygonOf.size(); ++r) {
    if (r + 1 == polygonOf.size() || polygonOf[r + 1] != polygonOf[r])
      l.polygons.push_back(static_cast<std::uint32_t>(r + 1));
  }
  return l;
}

struct Result {
  PolygonTriangles out;
  PolygonStats stats;
};

// compareArea: against the reference, a triangulation per polygon (most of the time).
Result check(const Loaded& l, FillRule fill, bool compareArea = true) {
  Result r;
  PolygonOptions options;
  options.fill = fill;
  const Status s = triangulatePolygons(l.batch(), options, r.out, &r.stats);
  EXPECT_TRUE(s.ok()) << s.message;
  testing::PolygonCheckOptions c;
  c.fill = fill;
  c.compareArea = compareArea;
  EXPECT_EQ(testing::checkPolygonTriangles(l.batch(), r.out, c), "");
  return r;
}

TEST(PolygonsRealData, VectorTiles) {
  const Loaded l = load("polygons_tiles");
  ASSERT_GT(l.polygons.size(), 100000u);
  const Result even = check(l, FillRule::EvenOdd);
  // Tiles are valid polygons but for a few rings touching themselves: no crossing at all.
  EXPECT_EQ(even.stats.crossings, 0u);
  EXPECT_LT(even.stats.general, 10u);
  check(l, FillRule::NonZero, false);
  // Threads: the same arrays.
  Result many;
  PolygonOptions options;
  options.threads = 2;
  ASSERT_TRUE(triangulatePolygons(l.batch(), options, many.out, &many.stats).ok());
  EXPECT_EQ(many.stats.threads, 2u);
  EXPECT_EQ(many.out.triangles, even.out.triangles);
  EXPECT_EQ(many.out.triangleOffsets, even.out.triangleOffsets);
}

TEST(PolygonsRealData, CountriesCutByGeojsonVt) {
  const Loaded l = load("polygons_geojson_vt");
  const Result r = check(l, FillRule::EvenOdd);
  EXPECT_GT(r.stats.crossings, 0u);  // shared borders cut and simplified do cross
}

TEST(PolygonsRealData, NaturalEarthCountries) {
  for (const char* scale : {"110m", "50m", "10m"}) {
    SCOPED_TRACE(scale);
    const Loaded l = load(std::string("ne_") + scale + "_rings");
    check(l, FillRule::EvenOdd);
  }
}

TEST(PolygonsRealData, UsCounties) {
  const Loaded l = load("us_counties_rings");
  check(l, FillRule::EvenOdd);
  check(l, FillRule::NonZero);
}

}  // namespace
}  // namespace geocdt
