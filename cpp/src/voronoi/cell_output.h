#pragma once
// Writes every site's cell into the GeoArrow arrays, in input order: a clipped cell as its
// assembly made it, a cell that the boundary does not enter as the ring of its corners when
// they are inside the domain (nothing when outside), and nothing for a site equal to an earlier
// one.
#include <cstdint>
#include <vector>

#include "geocdt/voronoi.h"
#include "voronoi/cell_polygons.h"
#include "voronoi/cell_sides.h"
#include "voronoi/site_diagram.h"

namespace geocdt {

// The cells the boundary enters, as their assembly made them: cell k is the site vertex
// vertices[k] (in increasing order), with the polygons polygonStarts[k] .. [k + 1] of polygons.
struct ClippedCells {
  CellPolygons polygons;
  std::vector<std::uint32_t> vertices;
  std::vector<std::uint32_t> polygonStarts{0};

  // The index k of vertex v among the cells, or -1.
  std::int32_t find(std::uint32_t v) const;
};

// Fills out's coords and offsets.
void writeCells(const SiteDiagram& diagram, const CellSides& sides, const ClippedCells& clipped,
                VoronoiCells& out);

// Every cell empty (an empty domain).
void writeEmptyCells(std::size_t sites, VoronoiCells& out);

}  // namespace geocdt
