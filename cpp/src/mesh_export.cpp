// From internal slots to the caller's arrays: ghost and free slots dropped, optionally the
// outside triangles too, with provenance and inside flags.
#include <algorithm>

#include "triangulation_state.h"

namespace geocdt {

namespace {

// Winding number of every slot, spreading from the ghost triangles (outside every ring)
// across edges; crossing a constrained edge adds the net ring traversals along it.
std::vector<std::uint8_t> insideSlots(const Delaunay& d, FillRule fill) {
  const Topology& topo = d.topo;
  const std::int32_t slots = topo.slotCount();
  std::vector<std::int32_t> winding(slots, 0);
  std::vector<std::uint8_t> seen(slots, 0);
  std::vector<std::int32_t> queue;
  for (std::int32_t t = 0; t < slots; ++t)
    if (!topo.isFree(t) && topo.isGhost(t)) {
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
      if (topo.fixed[e]) winding[next] += d.constraints.windingAcross(topo.tri[e], topo.tri[nextEdge(e)]);
      queue.push_back(next);
    }
  }
  std::vector<std::uint8_t> inside(slots, 0);
  for (std::int32_t t = 0; t < slots; ++t)
    inside[t] = fill == FillRule::EvenOdd ? (winding[t] & 1) != 0 : winding[t] != 0;
  return inside;
}

}  // namespace

std::vector<std::int32_t> slotIndices(const Topology& topo) {
  std::vector<std::int32_t> index(topo.slotCount(), -1);
  std::int32_t n = 0;
  for (std::int32_t t = 0; t < topo.slotCount(); ++t)
    if (!topo.isFree(t) && !topo.isGhost(t)) index[t] = n++;
  return index;
}

Mesh exportMesh(const Delaunay& d, const MeshOptions& options) {
  const Topology& topo = d.topo;
  const bool classify = options.insideFlags || options.keep == Keep::Inside;
  std::vector<std::uint8_t> inside;
  if (classify) inside = insideSlots(d, options.fill);

  std::vector<std::int32_t> index(topo.slotCount(), -1);
  std::int32_t count = 0;
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (topo.isFree(t) || topo.isGhost(t)) continue;
    if (options.keep == Keep::Inside && !inside[t]) continue;
    index[t] = count++;
  }

  Mesh m;
  m.points = d.xy;
  const std::size_t halfedges = 3 * static_cast<std::size_t>(count);
  m.triangles.resize(halfedges);
  m.halfedges.resize(halfedges);
  m.constrained.resize(halfedges);
  if (options.insideFlags) m.inside.resize(count);
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    const std::int32_t n = index[t];
    if (n < 0) continue;
    if (options.insideFlags) m.inside[n] = inside[t];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = 3 * t + k, out = 3 * n + k;
      m.triangles[out] = topo.tri[e];
      const std::int32_t twin = topo.adj[e];
      const std::int32_t twinTriangle = index[twin / 3];
      m.halfedges[out] = twinTriangle < 0 ? -1 : 3 * twinTriangle + twin % 3;
      m.constrained[out] = topo.fixed[e];
    }
  }

  // Provenance: one half-edge per constrained edge, with the polylines it came from.
  if (d.constraints.edgeCount() > 0) {
    m.sourceOffsets.push_back(0);
    for (std::size_t e = 0; e < halfedges; ++e) {
      if (!m.constrained[e]) continue;
      const std::int32_t twin = m.halfedges[e];
      if (twin >= 0 && static_cast<std::size_t>(twin) < e) continue;  // listed from its twin
      const std::uint32_t u = m.triangles[e];
      const std::uint32_t v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
      const EdgeSource* src = d.constraints.find(u, v);
      if (!src) continue;
      m.constraintEdges.push_back(static_cast<std::uint32_t>(e));
      d.constraints.forEachPolyline(*src, [&m](std::uint32_t p) { m.sources.push_back(p); });
      m.sourceOffsets.push_back(static_cast<std::uint32_t>(m.sources.size()));
    }
  }
  return m;
}

}  // namespace geocdt
