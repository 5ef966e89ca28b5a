#pragma once
// Inside or outside for every Voronoi vertex: the winding number of the domain's boundary
// around the circumcentre of each triangle of the sites' triangulation (0 outside, 1 inside;
// boundary loops keep the domain on their left). Spread from the ghost triangles, whose vertex
// is at infinity and outside, across the triangles' edges, each step adding the net crossings
// of the Voronoi edge between the two circumcentres. A cell that the boundary does not enter is
// wholly inside or wholly outside, as its corners say.
#include <cstdint>
#include <vector>

#include "voronoi/boundary_walk.h"
#include "voronoi/site_diagram.h"

namespace geocdt {

std::vector<std::int8_t> vertexWindings(const SiteDiagram& diagram, const BoundaryWalk& walk);

}  // namespace geocdt
