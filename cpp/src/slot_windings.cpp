#include "slot_windings.h"

namespace geocdt {

std::vector<std::int32_t> slotWindings(const Delaunay& d) {
  const Topology& topo = d.topo;
  const std::int32_t slots = topo.slotCount();
  std::vector<std::int32_t> winding(slots, 0);
  std::vector<std::uint8_t> seen(slots, 0);
  std::vector<std::int32_t> queue;
  for (std::int32_t t = 0; t < slots; ++t)
    if (topo.isGhost(t)) {
      seen[t] = 1;
      queue.push_back(t);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t t = queue[head];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = 3 * t + k, next = topo.adj[e] / 3;
      if (seen[next]) continue;
      seen[next] = 1;
      winding[next] = winding[t];
      if (topo.fixed[e])
        winding[next] += d.constraints.windingAcross(topo.tri[e], topo.tri[nextEdge(e)]);
      queue.push_back(next);
    }
  }
  return winding;
}

}  // namespace geocdt
