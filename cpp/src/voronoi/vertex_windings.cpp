#include "voronoi/vertex_windings.h"

namespace geocdt {

std::vector<std::int8_t> vertexWindings(const SiteDiagram& diagram, const BoundaryWalk& walk) {
  const Topology& topo = diagram.topo();
  const std::int32_t slots = topo.slotCount();
  constexpr std::int8_t kUnseen = -128;
  std::vector<std::int8_t> winding(slots, kUnseen);
  std::vector<std::int32_t> queue;
  for (std::int32_t t = 0; t < slots; ++t)
    if (topo.isGhost(t)) {
      winding[t] = 0;
      queue.push_back(t);
    }
  const std::int32_t* adj = topo.adj.data();
  const std::uint8_t* step = walk.windingStep.data();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t t = queue[head];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t twin = adj[3 * t + k], n = twin / 3;
      if (winding[n] != kUnseen) continue;
      winding[n] = static_cast<std::int8_t>(winding[t] + static_cast<std::int8_t>(step[twin]));
      queue.push_back(n);
    }
  }
  return winding;
}

}  // namespace geocdt
