#include "voronoi/cell_output.h"

namespace geocdt {
namespace {

std::uint32_t ringBegin(const CellPolygons& p, std::uint32_t ring) {
  return ring == 0 ? 0 : p.ringEnds[ring - 1];
}
std::uint32_t polygonBegin(const CellPolygons& p, std::uint32_t polygon) {
  return polygon == 0 ? 0 : p.polygonEnds[polygon - 1];
}

// Appends the corners of cell v counter-clockwise, repeats closed up (cocircular sites share a
// corner) and closed (the last repeats the first); false, with nothing appended, when fewer
// than three are left (rounding can merge the corners of a sliver).
bool appendCorners(const SiteDiagram& d, std::uint32_t v, std::vector<double>& coords) {
  const std::size_t begin = coords.size();
  const std::int32_t first = d.outEdge(v);
  const XY start = d.center(first / 3);
  coords.push_back(start.x);
  coords.push_back(start.y);
  XY last = start;
  for (std::int32_t e = d.turn(first); e != first; e = d.turn(e)) {
    const XY c = d.center(e / 3);
    if (c == last) continue;
    coords.push_back(c.x);
    coords.push_back(c.y);
    last = c;
  }
  if (last != start) {
    coords.push_back(start.x);
    coords.push_back(start.y);
  }
  if (coords.size() - begin >= 8) return true;
  coords.resize(begin);
  return false;
}

void appendClipped(const CellPolygons& p, std::uint32_t first, std::uint32_t last,
                   VoronoiCells& out) {
  for (std::uint32_t j = first; j < last; ++j) {
    for (std::uint32_t r = polygonBegin(p, j); r < p.polygonEnds[j]; ++r) {
      for (std::uint32_t k = ringBegin(p, r); k < p.ringEnds[r]; ++k) {
        out.coords.push_back(p.points[k].x);
        out.coords.push_back(p.points[k].y);
      }
      out.ringOffsets.push_back(static_cast<std::uint32_t>(out.coords.size() / 2));
    }
    out.polygonOffsets.push_back(static_cast<std::uint32_t>(out.ringOffsets.size() - 1));
  }
}

}  // namespace

void writeEmptyCells(std::size_t sites, VoronoiCells& out) {
  out.coords.clear();
  out.ringOffsets.assign(1, 0);
  out.polygonOffsets.assign(1, 0);
  out.siteOffsets.assign(sites + 1, 0);
}

// One pass in input order, appending: room is reserved for the most a whole cell can have (its
// degree plus the closing point, over all real half-edges), so nothing moves as it grows.
void writeCells(const SiteDiagram& d, const std::vector<std::int8_t>& windings,
                const ClippedCells& clipped, VoronoiCells& out) {
  const std::size_t sites = d.siteVertices().size();
  const CellPolygons& p = clipped.polygons;
  const std::size_t halfEdges = d.topo().tri.size();
  out.coords.clear();
  out.coords.reserve(2 * (halfEdges + d.vertexCount() + p.points.size()));
  out.ringOffsets.assign(1, 0);
  out.ringOffsets.reserve(d.vertexCount() + p.ringCount() + 1);
  out.polygonOffsets.assign(1, 0);
  out.polygonOffsets.reserve(d.vertexCount() + p.polygonCount() + 1);
  out.siteOffsets.assign(1, 0);
  out.siteOffsets.reserve(sites + 1);
  std::vector<std::uint8_t> claimed(d.vertexCount(), 0);
  for (std::size_t i = 0; i < sites; ++i) {
    const std::uint32_t v = d.siteVertices()[i];
    if (!claimed[v]) {  // the first of equal sites claims the cell
      claimed[v] = 1;
      if (clipped.first[v] >= 0) {
        appendClipped(p, static_cast<std::uint32_t>(clipped.first[v]),
                      static_cast<std::uint32_t>(clipped.last[v]), out);
      } else if (windings[d.outEdge(v) / 3] != 0 && appendCorners(d, v, out.coords)) {
        out.ringOffsets.push_back(static_cast<std::uint32_t>(out.coords.size() / 2));
        out.polygonOffsets.push_back(static_cast<std::uint32_t>(out.ringOffsets.size() - 1));
      }
    }
    out.siteOffsets.push_back(static_cast<std::uint32_t>(out.polygonOffsets.size() - 1));
  }
}

}  // namespace geocdt
