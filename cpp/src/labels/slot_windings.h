#pragma once
// The winding number of every slot: how the rings wind around it, spread from the ghost
// triangles (outside every ring) across edges, adding each constrained edge's net ring
// traversals when crossing it. Inside and outside read it through a fill rule.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"

namespace geocdt {

std::vector<std::int32_t> slotWindings(const Delaunay& d);

inline bool insideByRule(std::int32_t winding, FillRule fill) {
  return fill == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0;
}

}  // namespace geocdt
