#pragma once
// Checks of clipped Voronoi cells, independent of how geocdt makes them: the domain rebuilt from
// the public API, nearest sites by brute force over a grid, point-in-polygon with exact
// orientation, distances compared in GMP rationals. Each returns "" when all hold, else the
// first failure.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"
#include "geocdt/voronoi.h"

namespace geocdt::testing {

// The domain as the checks see it.
struct CheckDomain {
  std::vector<std::array<double, 4>> segments;  // boundary, domain on the left: x0, y0, x1, y1
  long double area = 0;  // long double: tiny domains' areas underflow a double
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  // 1 inside, 0 outside, -1 on the boundary or undecided (not sampled).
  int inside(double x, double y) const;

  // For rings: their triangulation with inside flags.
  std::shared_ptr<Triangulation> rings;
  Mesh mesh;
  bool isBox = false;
};

CheckDomain boxCheckDomain(const double box[4]);
CheckDomain ringCheckDomain(const std::vector<PolylineView>& rings, FillRule fill);
CheckDomain hullCheckDomain(const std::vector<double>& sites);

// The documented accuracy: a cell vertex v of site s is no farther from s than from any other
// site by more than kVertexSlack * (|v| + |v - s| + l) + kSubnormalSlack, l the boundary
// segment it lies on (0 for a Voronoi vertex); the same bounds how far a vertex on the boundary
// lies from it.
inline constexpr double kVertexSlack = 0x1p-45;
inline constexpr double kSubnormalSlack = 0x1p-1070;

struct VoronoiReport {
  long double cellArea = 0;  // of all cells, signed by ring orientation
  std::size_t polygons = 0, rings = 0, points = 0;
  std::size_t samples = 0;        // sample points checked against their nearest site
  std::size_t boundaryEdges = 0;  // cell edges that no other cell shares
};

// Everything: layout, ring orientation, areas (relative to the domain's, within areaTolerance,
// plus what moving the boundary's vertices by the slack above can change),
// shared edges, boundary edges on the domain's boundary, vertices nearest their site, and
// `samples` random points each in the cell of its nearest site and no other.
std::string checkVoronoi(const VoronoiCells& cells, const std::vector<double>& sites,
                         const CheckDomain& domain, std::size_t samples, double areaTolerance,
                         VoronoiReport* report = nullptr);

}  // namespace geocdt::testing
