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

// What each site's cell holds, in input order; the same decisions in both passes.
class CellSizes {
 public:
  CellSizes(const SiteDiagram& d, const std::vector<std::int8_t>& windings,
            const ClippedCells& clipped)
      : d_(d), windings_(windings), clipped_(clipped), claimed_(d.vertexCount(), 0) {}

  enum class Kind { Empty, Clipped, Whole };
  // The kind of site i's cell; the first of equal sites claims it.
  Kind kind(std::size_t i) {
    const std::uint32_t v = d_.siteVertices()[i];
    if (claimed_[v]) return Kind::Empty;
    claimed_[v] = 1;
    if (clipped_.first[v] >= 0) return Kind::Clipped;
    if (windings_[d_.outEdge(v) / 3] == 0) return Kind::Empty;
    return closedCorners(d_, v, [](XY) {}) >= 4 ? Kind::Whole : Kind::Empty;
  }

 private:
  const SiteDiagram& d_;
  const std::vector<std::int8_t>& windings_;
  const ClippedCells& clipped_;
  std::vector<std::uint8_t> claimed_;
};

}  // namespace

void writeEmptyCells(std::size_t sites, VoronoiCells& out) {
  out.coords.clear();
  out.ringOffsets.assign(1, 0);
  out.polygonOffsets.assign(1, 0);
  out.siteOffsets.assign(sites + 1, 0);
}

void writeCells(const SiteDiagram& d, const std::vector<std::int8_t>& windings,
                const ClippedCells& clipped, VoronoiCells& out) {
  const std::size_t sites = d.siteVertices().size();
  const CellPolygons& p = clipped.polygons;
  std::size_t points = 0, rings = 0, polygons = 0;
  {
    CellSizes sizes(d, windings, clipped);
    for (std::size_t i = 0; i < sites; ++i) {
      const std::uint32_t v = d.siteVertices()[i];
      switch (sizes.kind(i)) {
        case CellSizes::Kind::Whole:
          points += closedCorners(d, v, [](XY) {});
          ++rings;
          ++polygons;
          break;
        case CellSizes::Kind::Clipped: {
          const auto first = static_cast<std::uint32_t>(clipped.first[v]);
          const auto last = static_cast<std::uint32_t>(clipped.last[v]);
          const std::uint32_t firstRing = polygonBegin(p, first);
          const std::uint32_t lastRing = polygonBegin(p, last);
          points += ringBegin(p, lastRing) - ringBegin(p, firstRing);
          rings += lastRing - firstRing;
          polygons += last - first;
          break;
        }
        case CellSizes::Kind::Empty: break;
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
  CellSizes sizes(d, windings, clipped);
  for (std::size_t i = 0; i < sites; ++i) {
    const std::uint32_t v = d.siteVertices()[i];
    switch (sizes.kind(i)) {
      case CellSizes::Kind::Whole:
        closedCorners(d, v, put);
        out.ringOffsets[++ring] = point;
        out.polygonOffsets[++polygon] = ring;
        break;
      case CellSizes::Kind::Clipped:
        for (auto j = static_cast<std::uint32_t>(clipped.first[v]);
             j < static_cast<std::uint32_t>(clipped.last[v]); ++j) {
          for (std::uint32_t r = polygonBegin(p, j); r < p.polygonEnds[j]; ++r) {
            for (std::uint32_t k = ringBegin(p, r); k < p.ringEnds[r]; ++k) put(p.points[k]);
            out.ringOffsets[++ring] = point;
          }
          out.polygonOffsets[++polygon] = ring;
        }
        break;
      case CellSizes::Kind::Empty: break;
    }
    out.siteOffsets[i + 1] = polygon;
  }
}

}  // namespace geocdt
