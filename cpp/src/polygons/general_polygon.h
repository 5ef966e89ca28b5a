#pragma once
// One polygon through the general engine (geocdt::Triangulation, keep inside), for what the
// small path refuses: rings that cross (their crossings become extra points), vertices on
// other segments, very large polygons. Its output is mapped back onto the input's points.
#include <cstdint>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt {

class GeneralPolygon {
 public:
  // The polygon's points are xy[0 .. 2n), its rings the local offsets ringStarts[0 ..
  // ringCount]. Appends its inside triangles to out as indices base + (local index of the
  // first input point at a vertex), or extraBase + i for a vertex that is no input point,
  // whose x, y are appended to extras as extra point i (extras.size() / 2 before the call
  // is the first i).
  Status triangulate(const double* xy, std::uint32_t n, const std::uint32_t* ringStarts,
                     std::uint32_t ringCount, FillRule fill, std::uint32_t base,
                     std::uint32_t extraBase, std::vector<std::uint32_t>& out,
                     std::vector<double>& extras);

 private:
  std::vector<double> closed_;          // the rings' coordinates, each ring closed
  std::vector<std::uint32_t> pointOf_;  // local point of each entry of closed_
  std::vector<PolylineView> views_;
  std::vector<std::uint32_t> ids_;      // vertex of each entry of closed_
  std::vector<std::uint32_t> indexOf_;  // vertex -> output index
};

}  // namespace geocdt
