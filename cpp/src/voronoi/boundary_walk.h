#pragma once
// The domain's boundary walked through the cells. Along a boundary segment the nearest site
// changes only where the segment crosses a bisector, so each loop goes from cell to cell across
// their shared edges: from the nearest site of its first vertex, a segment ends in the current
// cell unless its end is nearer a neighbour; then it leaves through the bisector it meets
// first. The loops come out cut into pieces, one per stay in a cell, joined by crossings.
#include <cstdint>
#include <vector>

#include "geocdt/status.h"
#include "voronoi/domain.h"
#include "voronoi/site_diagram.h"

namespace geocdt {

struct Crossing {
  std::int32_t edge = -1;          // the sites' half-edge from the cell left to the cell entered
  XY at;                           // where, rounded (crossing_point.h)
  double error = 0;                // at's error bound along its bisector's dominant axis
  std::uint32_t from = 0, to = 0;  // the boundary segment crossing: Domain::points indices
  std::int32_t leaving = -1, entering = -1;  // the pieces it ends and starts
};

// A stay of a loop in one cell: from its entry crossing through `count` boundary vertices
// (Domain::points first, then the loop's next ones) to its exit crossing; a loop that never
// leaves its cell is one piece with neither.
struct Piece {
  std::uint32_t cell = 0;  // a real site's vertex
  std::int32_t entry = -1, exit = -1;
  std::uint32_t loop = 0;
  std::uint32_t first = 0, count = 0;
};

struct BoundaryWalk {
  std::vector<Crossing> crossings;
  std::vector<Piece> pieces;
  // Per half-edge e of the sites' triangulation, modulo 256: the winding number of the Voronoi
  // vertex of e's triangle minus that of its twin's, from the crossings of their Voronoi edge.
  std::vector<std::uint8_t> windingStep;
};

Status walkBoundary(const Domain& domain, SiteDiagram& diagram, BoundaryWalk& out);

}  // namespace geocdt
