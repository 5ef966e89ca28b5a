#pragma once
// Voronoi cells clipped to a domain (Thiessen polygons): for each site, the part of the domain
// nearer to it than to any other site. The domain is the inside of rings (by a fill rule, with
// holes, islands and shared borders, as Triangulation decides inside), the sites' convex hull,
// or a box. Cells come out as a GeoArrow MultiPolygon per site.
//
// Exactness: which cell holds each boundary vertex, which cell edges the boundary crosses and
// in which order are decided exactly (ties broken by a fixed infinitesimal shift of the
// diagram), so the cells partition the domain. Only coordinates are rounded: a Voronoi vertex
// (the circumcentre of three sites a, b, c with circumradius R) lies within
// 2^-48 (M + R) of the exact one in each coordinate, M the largest |coordinate| of a, b, c; a
// vertex where the boundary crosses a cell edge is computed once for both cells, from the
// boundary segment's ends (keeping a coordinate along which the segment does not move); the
// boundary's own vertices are kept exactly.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt {

enum class VoronoiClip : std::uint8_t {
  Rings,  // the inside of the rings, by VoronoiOptions::fill
  Hull,   // the sites' convex hull (nothing when they are collinear)
  Box,    // VoronoiOptions::box
};

struct VoronoiOptions {
  VoronoiClip clip = VoronoiClip::Rings;
  double box[4] = {0, 0, 0, 0};       // xmin, ymin, xmax, ymax, for VoronoiClip::Box
  FillRule fill = FillRule::EvenOdd;  // how the rings decide inside
  std::uint32_t threads = 1;          // Options::threads for the sites' and the rings' points
  // Lloyd's relaxation: this many times at most, every site moves to the centroid of its
  // clipped cell (a site with an empty cell stays), and the cells are made again; it stops
  // early once no site moved farther than lloydTolerance. The domain stays the first one (the
  // hull of the sites as given, for VoronoiClip::Hull).
  std::uint32_t lloydIterations = 0;
  double lloydTolerance = 0;
};

struct VoronoiStats {
  double domainArea = 0;              // of the domain, summed over its triangles in doubles
  std::uint64_t crossings = 0;        // where the domain's boundary crosses cell edges
  std::uint64_t clippedCells = 0;     // cells the boundary enters
  std::uint32_t lloydIterations = 0;  // relaxation steps done
  double lloydMovement = 0;           // how far the farthest site moved in the last step
  std::uint32_t threads = 1;          // that triangulated the sites (last step)
};

// A GeoArrow MultiPolygon per site: site i's polygons are siteOffsets[i] .. siteOffsets[i + 1];
// polygon p's rings are polygonOffsets[p] .. [p + 1], the first its outer ring
// (counter-clockwise), the others its holes (clockwise); ring r's points are ringOffsets[r] ..
// [r + 1] of coords (x, y pairs), closed: the last point repeats the first.
struct VoronoiCells {
  std::vector<double> coords;
  std::vector<std::uint32_t> ringOffsets;
  std::vector<std::uint32_t> polygonOffsets;
  std::vector<std::uint32_t> siteOffsets;
  std::vector<double> sites;  // where the sites are at the end (moved by Lloyd's relaxation)
  VoronoiStats stats;
};

// The cells of count sites (xy: 2 * count doubles) clipped as options say; rings (ringCount of
// them) bound the domain for VoronoiClip::Rings. Equal sites: the first of them gets the cell,
// the others an empty one. A site outside the domain gets the part of its cell inside it
// (empty when none is). Errors: no sites, a NaN, infinite or too large coordinate, a box that
// is not one, Rings without rings.
Status voronoi(const double* xy, std::size_t count, const PolylineView* rings,
               std::size_t ringCount, const VoronoiOptions& options, VoronoiCells& out);

}  // namespace geocdt
