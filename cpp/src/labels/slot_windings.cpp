#include "labels/slot_windings.h"

#include <algorithm>

#include "base/chunks.h"

namespace geocdt {

std::vector<std::int32_t> slotWindings(const Delaunay& d) {
  const Topology& topo = d.topo;
  const std::int32_t slots = topo.slotCount();
  std::vector<std::int32_t> winding(slots, 0);
  std::vector<std::uint8_t> seen(slots, 0);
  std::vector<std::int32_t> queue;
  // Both loops in chunks, the flood's over its queue as it grows (chunks.h: run once a call,
  // they had the function optimised during a first call, for nothing).
  forChunks(0, static_cast<std::size_t>(slots), [&](std::size_t begin, std::size_t end) {
    for (auto t = static_cast<std::int32_t>(begin); t < static_cast<std::int32_t>(end); ++t)
      if (topo.isGhost(t)) {
        seen[t] = 1;
        queue.push_back(t);
      }
  });
  const auto flood = [&](std::size_t begin, std::size_t end) {
    for (std::size_t head = begin; head < end; ++head) {
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
  };
  for (std::size_t head = 0; head < queue.size();) {
    const std::size_t end = std::min(queue.size(), head + kChunk);
    runChunk(flood, head, end);
    head = end;
  }
  return winding;
}

}  // namespace geocdt
