// geocdt::voronoi(): the sites' Delaunay triangulation from the core, the domain's boundary
// walked through its cells, the cells the boundary enters assembled from their pieces, the
// others kept whole or dropped by the winding of their corners, and everything written out in
// input order. Lloyd's relaxation repeats it with the sites moved to their cells' centroids.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "geocdt/voronoi.h"
#include "invalid_coordinate.h"
#include "out_of_memory.h"
#include "voronoi/boundary_walk.h"
#include "voronoi/cell_assembly.h"
#include "voronoi/cell_output.h"
#include "voronoi/domain.h"
#include "voronoi/lloyd.h"
#include "voronoi/site_diagram.h"
#include "voronoi/vertex_windings.h"

namespace geocdt {
namespace {

Status invalidSites(const std::string& message) {
  return {StatusCode::InvalidArgument, "voronoi: " + message};
}

Status checkInput(const double* xy, std::size_t count, std::size_t ringCount,
                  const VoronoiOptions& options) {
  if (count == 0) return invalidSites("no sites");
  if (xy == nullptr) return invalidSites("null sites with a count");
  if (count >= kGhost - 8) return invalidSites("too many sites: at most 4294967287");
  const std::size_t bad = firstInvalidCoordinate(xy, 0, 2 * count);
  if (bad < 2 * count)
    return {StatusCode::InvalidCoordinate,
            "site " + std::to_string(bad / 2) + " has " +
                describeInvalidCoordinate(xy[bad], bad % 2 == 1),
            bad / 2};
  if (options.clip == VoronoiClip::Box) {
    const double* b = options.box;
    if (firstInvalidCoordinate(b, 0, 4) < 4)
      return invalidSites("the box's coordinates must be finite numbers within 1e150");
    if (!(b[0] < b[2]) || !(b[1] < b[3]))
      return invalidSites("the box must have xmin < xmax and ymin < ymax");
  }
  if (options.clip == VoronoiClip::Rings && ringCount == 0)
    return invalidSites("clipping to rings needs rings");
  if (!(options.lloydTolerance >= 0)) return invalidSites("lloydTolerance must be 0 or more");
  return Status::success();
}

// The sites' pieces grouped by cell, each cell assembled.
Status assembleCells(const Domain& domain, const SiteDiagram& diagram, const BoundaryWalk& walk,
                     const CellSides& sides, ClippedCells& clipped) {
  std::vector<std::int32_t> order(walk.pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return walk.pieces[a].cell < walk.pieces[b].cell;
  });
  clipped = ClippedCells();
  CellAssembler assembler(domain, diagram, walk, sides);
  for (std::size_t begin = 0; begin < order.size();) {
    const std::uint32_t v = walk.pieces[order[begin]].cell;
    std::size_t end = begin;
    while (end < order.size() && walk.pieces[order[end]].cell == v) ++end;
    const Status s = assembler.assemble(v, order.data() + begin, end - begin, clipped.polygons);
    if (!s.ok()) return s;
    clipped.vertices.push_back(v);
    clipped.polygonStarts.push_back(clipped.polygons.polygonCount());
    begin = end;
  }
  return Status::success();
}

// Inside or outside for the cells the boundary does not cut: by the sites for a box or for
// their own hull (cell_sides.h), else by the windings of the Voronoi vertices.
CellSides sidesOf(const VoronoiOptions& options, const SiteDiagram& diagram,
                  const BoundaryWalk& walk, bool hullOfTheseSites) {
  if (options.clip == VoronoiClip::Box) return CellSides::ofBox(diagram, options.box);
  // After Lloyd's steps the hull is the first sites', which moved sites may leave.
  if (hullOfTheseSites) return CellSides::ofHull(diagram);
  return CellSides::ofWindings(diagram, vertexWindings(diagram, walk));
}

// The cells of the sites xy clipped to domain; with hull, the domain is first made the sites'
// convex hull.
Status clipCells(const double* xy, std::size_t count, Domain& domain, bool hull,
                 const VoronoiOptions& options, VoronoiCells& out) {
  const std::uint32_t threads = options.threads;
  double minX = xy[0], maxX = xy[0], minY = xy[1], maxY = xy[1];
  for (std::size_t i = 1; i < count; ++i) {
    minX = std::min(minX, xy[2 * i]);
    maxX = std::max(maxX, xy[2 * i]);
    minY = std::min(minY, xy[2 * i + 1]);
    maxY = std::max(maxY, xy[2 * i + 1]);
  }
  if (!domain.empty()) {
    minX = std::min(minX, domain.minX);
    maxX = std::max(maxX, domain.maxX);
    minY = std::min(minY, domain.minY);
    maxY = std::max(maxY, domain.maxY);
  }
  SiteDiagram diagram;
  Status s = diagram.build(xy, static_cast<std::uint32_t>(count), minX, minY, maxX, maxY, threads);
  if (!s.ok()) return s;
  if (hull) domain = convexDomain(diagram.hull());
  out.stats.domainArea = domain.area;
  out.stats.threads = diagram.threads();
  out.stats.crossings = out.stats.clippedCells = 0;
  if (domain.empty()) {
    writeEmptyCells(count, out);
    return Status::success();
  }
  BoundaryWalk walk;
  s = walkBoundary(domain, diagram, walk);
  if (!s.ok()) return s;
  const CellSides sides = sidesOf(options, diagram, walk, hull);
  ClippedCells clipped;
  s = assembleCells(domain, diagram, walk, sides, clipped);
  if (!s.ok()) return s;
  writeCells(diagram, sides, clipped, out);
  out.stats.crossings = walk.crossings.size();
  out.stats.clippedCells = clipped.vertices.size();
  return Status::success();
}

Status run(const double* xy, std::size_t count, const PolylineView* rings, std::size_t ringCount,
           const VoronoiOptions& options, VoronoiCells& out) {
  Domain domain;
  if (options.clip == VoronoiClip::Box) domain = boxDomain(options.box);
  if (options.clip == VoronoiClip::Rings) {
    const Status s = ringDomain(rings, ringCount, options.fill, options.threads, domain);
    if (!s.ok()) return s;
  }
  out.sites.assign(xy, xy + 2 * count);
  bool hull = options.clip == VoronoiClip::Hull;
  for (std::uint32_t step = 0; step < options.lloydIterations; ++step) {
    const Status s = clipCells(out.sites.data(), count, domain, hull, options, out);
    if (!s.ok()) return s;
    hull = false;
    out.stats.lloydMovement = moveToCentroids(out, out.sites);
    out.stats.lloydIterations = step + 1;
    if (out.stats.lloydMovement <= options.lloydTolerance) break;
  }
  return clipCells(out.sites.data(), count, domain, hull, options, out);
}

}  // namespace

Status voronoi(const double* xy, std::size_t count, const PolylineView* rings,
               std::size_t ringCount, const VoronoiOptions& options, VoronoiCells& out) {
  out = VoronoiCells();
  const Status s = checkInput(xy, count, ringCount, options);
  if (!s.ok()) return s;
  const Status r = catchOutOfMemory([&] { return run(xy, count, rings, ringCount, options, out); },
                                    [&] { out = VoronoiCells(); });
  if (!r.ok()) out = VoronoiCells();
  return r;
}

}  // namespace geocdt
