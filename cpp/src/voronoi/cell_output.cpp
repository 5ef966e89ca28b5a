#include "voronoi/cell_output.h"

namespace geocdt {
namespace {

// The corners of cell v counter-clockwise, repeats closed up (cocircular sites share a corner)
// and closed (the last repeats the first): put(point) for each. Returns how many.
template <typename Put>
std::uint32_t closedCorners(const SiteDiagram& d, std::uint32_t v, Put put) {
  const std::int32_t first = d.outEdge(v);
  const XY start = d.center(first / 3);
  put(start);
  XY last = start;
  std::uint32_t n = 1;
  for (std::int32_t e = d.turn(first); e != first; e = d.turn(e)) {
    const XY c = d.center(e / 3);
    if (c == last) continue;
    put(c);
    last = c;
    ++n;
  }
  if (last != start) {
    put(start);
    ++n;
  }
  return n;
}

std::uint32_t ringBegin(const CellPolygons& p, std::uint32_t ring) {
  return ring == 0 ? 0 : p.ringEnds[ring - 1];
}
std::uint32_t polygonBegin(const CellPolygons& p, std::uint32_t polygon) {
  return polygon == 0 ? 0 : p.polygonEnds[polygon - 1];
}

// What site i's cell holds: kClipped (polygons in ClippedCells), 0 (empty: outside, an equal
// site's, or a whole cell that rounding left without area), or the points of a whole cell's
// ring.
constexpr std::uint32_t kClipped = 0xFFFFFFFFu;

std::uint32_t cellSize(const SiteDiagram& d, const std::vector<std::int8_t>& windings,
                       const ClippedCells& clipped, std::uint32_t v,
                       std::vector<std::uint8_t>& claimed) {
  if (claimed[v]) return 0;  // the first of equal sites claims the cell
  claimed[v] = 1;
  if (clipped.first[v] >= 0) return kClipped;
  if (windings[d.outEdge(v) / 3] == 0) return 0;
  const std::uint32_t points = closedCorners(d, v, [](XY) {});
  return points >= 4 ? points : 0;
}

}  // namespace

void writeEmptyCells(std::size_t sites, VoronoiCells& out) {
  out.coords.clear();
  out.ringOffsets.assign(1, 0);
  out.polygonOffsets.assign(1, 0);
  out.siteOffsets.assign(sites + 1, 0);
}

// Sizes first (one turn around each whole cell), then the offsets, then the points (a second
// turn), each written once in place.
void writeCells(const SiteDiagram& d, const std::vector<std::int8_t>& windings,
                const ClippedCells& clipped, VoronoiCells& out) {
  const std::size_t sites = d.siteVertices().size();
  const CellPolygons& p = clipped.polygons;
  std::vector<std::uint32_t> sizes(sites);
  std::size_t points = 0, rings = 0, polygons = 0;
  {
    std::vector<std::uint8_t> claimed(d.vertexCount(), 0);
    for (std::size_t i = 0; i < sites; ++i) {
      const std::uint32_t v = d.siteVertices()[i];
      const std::uint32_t size = cellSize(d, windings, clipped, v, claimed);
      sizes[i] = size;
      if (size == kClipped) {
        const auto first = static_cast<std::uint32_t>(clipped.first[v]);
        const auto last = static_cast<std::uint32_t>(clipped.last[v]);
        const std::uint32_t firstRing = polygonBegin(p, first), lastRing = polygonBegin(p, last);
        points += ringBegin(p, lastRing) - ringBegin(p, firstRing);
        rings += lastRing - firstRing;
        polygons += last - first;
      } else if (size > 0) {
        points += size;
        ++rings;
        ++polygons;
      }
    }
  }
  out.coords.resize(2 * points);
  out.ringOffsets.assign(rings + 1, 0);
  out.polygonOffsets.assign(polygons + 1, 0);
  out.siteOffsets.assign(sites + 1, 0);
  double* coords = out.coords.data();
  std::uint32_t point = 0, ring = 0, polygon = 0;
  const auto put = [&](XY c) {
    coords[2 * point] = c.x;
    coords[2 * point + 1] = c.y;
    ++point;
  };
  for (std::size_t i = 0; i < sites; ++i) {
    const std::uint32_t v = d.siteVertices()[i];
    if (sizes[i] == kClipped) {
      for (auto j = static_cast<std::uint32_t>(clipped.first[v]);
           j < static_cast<std::uint32_t>(clipped.last[v]); ++j) {
        for (std::uint32_t r = polygonBegin(p, j); r < p.polygonEnds[j]; ++r) {
          for (std::uint32_t k = ringBegin(p, r); k < p.ringEnds[r]; ++k) put(p.points[k]);
          out.ringOffsets[++ring] = point;
        }
        out.polygonOffsets[++polygon] = ring;
      }
    } else if (sizes[i] > 0) {
      closedCorners(d, v, put);
      out.ringOffsets[++ring] = point;
      out.polygonOffsets[++polygon] = ring;
    }
    out.siteOffsets[i + 1] = polygon;
  }
}

}  // namespace geocdt
