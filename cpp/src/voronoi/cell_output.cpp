#include "voronoi/cell_output.h"

#include <algorithm>

namespace geocdt {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;
constexpr std::uint32_t kClipped = 0xFFFFFFFEu;  // a cell size: see ClippedCells

std::uint32_t ringBegin(const CellPolygons& p, std::uint32_t ring) {
  return ring == 0 ? 0 : p.ringEnds[ring - 1];
}
std::uint32_t polygonBegin(const CellPolygons& p, std::uint32_t polygon) {
  return polygon == 0 ? 0 : p.polygonEnds[polygon - 1];
}

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

// Per vertex, what its cell holds: 0 (nothing: outside, or a sliver that rounding left without
// three distinct corners), kClipped, or the points of its whole ring (its distinct corners, a
// run of equal centres from cocircular sites counted once, then the closing point).
std::vector<std::uint32_t> cellSizes(const SiteDiagram& d, const CellSides& sides,
                                     const ClippedCells& clipped) {
  const std::uint32_t vertices = d.vertexCount();
  std::vector<std::uint32_t> sizes(vertices);
  std::size_t next = 0;  // the next clipped cell, in vertex order
  for (std::uint32_t v = 0; v < vertices; ++v) {
    if (next < clipped.vertices.size() && clipped.vertices[next] == v) {
      sizes[v] = kClipped;
      ++next;
    } else if (!sides.uncutInside(v)) {
      sizes[v] = 0;
    } else {
      // Under three distinct corners (a sliver, or cocircular sites): nothing to draw.
      const std::uint32_t corners = d.cornerCount(v);
      sizes[v] = corners >= 3 ? corners + 1 : 0;
    }
  }
  return sizes;
}

}  // namespace

std::int32_t ClippedCells::find(std::uint32_t v) const {
  const auto at = std::lower_bound(vertices.begin(), vertices.end(), v);
  return at != vertices.end() && *at == v ? static_cast<std::int32_t>(at - vertices.begin()) : -1;
}

void writeEmptyCells(std::size_t sites, VoronoiCells& out) {
  out.coords.clear();
  out.ringOffsets.assign(1, 0);
  out.polygonOffsets.assign(1, 0);
  out.siteOffsets.assign(sites + 1, 0);
}

// Sizes in vertex order; offsets in input order, where the first of equal sites claims the
// cell and each cell's place among the points is noted; then the points in vertex order, each
// cell written at its place.
void writeCells(const SiteDiagram& d, const CellSides& sides, const ClippedCells& clipped,
                VoronoiCells& out) {
  const std::size_t sites = d.siteVertices().size();
  const CellPolygons& p = clipped.polygons;
  const std::vector<std::uint32_t> sizes = cellSizes(d, sides, clipped);
  std::vector<std::uint32_t> placed(d.vertexCount(), kNone);
  out.siteOffsets.assign(1, 0);
  out.siteOffsets.reserve(sites + 1);
  out.polygonOffsets.assign(1, 0);
  out.ringOffsets.assign(1, 0);
  std::uint32_t points = 0;
  for (std::size_t i = 0; i < sites; ++i) {
    const std::uint32_t v = d.siteVertices()[i];
    const std::uint32_t size = sizes[v];
    if (size != 0 && placed[v] == kNone) {
      placed[v] = points;
      if (size != kClipped) {
        points += size;
        out.ringOffsets.push_back(points);
        out.polygonOffsets.push_back(static_cast<std::uint32_t>(out.ringOffsets.size() - 1));
      } else {
        const auto k = static_cast<std::uint32_t>(clipped.find(v));
        for (std::uint32_t j = clipped.polygonStarts[k]; j < clipped.polygonStarts[k + 1]; ++j) {
          for (std::uint32_t r = polygonBegin(p, j); r < p.polygonEnds[j]; ++r) {
            points += p.ringEnds[r] - ringBegin(p, r);
            out.ringOffsets.push_back(points);
          }
          out.polygonOffsets.push_back(static_cast<std::uint32_t>(out.ringOffsets.size() - 1));
        }
      }
    }
    out.siteOffsets.push_back(static_cast<std::uint32_t>(out.polygonOffsets.size() - 1));
  }
  out.coords.resize(2 * static_cast<std::size_t>(points));
  double* coords = out.coords.data();
  std::size_t next = 0;
  for (std::uint32_t v = 0; v < d.vertexCount(); ++v) {
    const bool isClipped = next < clipped.vertices.size() && clipped.vertices[next] == v;
    if (isClipped) ++next;
    if (placed[v] == kNone) continue;
    double* at = coords + 2 * static_cast<std::size_t>(placed[v]);
    const auto put = [&at](XY c) {
      at[0] = c.x;
      at[1] = c.y;
      at += 2;
    };
    if (!isClipped) {
      closedCorners(d, v, put);
      continue;
    }
    const std::size_t k = next - 1;
    const std::uint32_t firstRing = polygonBegin(p, clipped.polygonStarts[k]);
    const std::uint32_t lastRing = polygonBegin(p, clipped.polygonStarts[k + 1]);
    for (std::uint32_t q = ringBegin(p, firstRing); q < ringBegin(p, lastRing); ++q)
      put(p.points[q]);
  }
}

}  // namespace geocdt
