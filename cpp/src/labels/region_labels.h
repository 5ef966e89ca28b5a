#pragma once
// Region labels: which input polygon holds each triangle (MeshOptions::regions says the rule).
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"

namespace geocdt {

// The region of every slot, or -1 (ghost slots, and triangles outside every polygon).
// polylinePolygons maps polyline ids to polygon ids as MeshOptions::polylinePolygons does.
std::vector<std::int32_t> regionSlots(const Delaunay& d,
                                      const std::vector<std::int32_t>& polylinePolygons,
                                      FillRule fill);

}  // namespace geocdt
