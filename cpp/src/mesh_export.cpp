// From internal slots to the caller's arrays: ghost triangles dropped, optionally the
// outside triangles too, with provenance, inside flags and region labels.
#include <algorithm>

#include "region_labels.h"
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
  std::vector<std::uint8_t> inside(slots, 0);
  for (std::int32_t t = 0; t < slots; ++t)
    inside[t] = fill == FillRule::EvenOdd ? (winding[t] & 1) != 0 : winding[t] != 0;
  return inside;
}

}  // namespace

namespace {

// The order in which compaction fills holes: the last kept slot moves into the first
// dropped one, until they meet. Calls move(from, to) for each move; returns the count kept.
template <typename Move>
std::int32_t planCompaction(std::vector<std::uint8_t>& kept, Move move) {
  const std::int32_t slots = static_cast<std::int32_t>(kept.size());
  std::int32_t front = 0, back = slots - 1;
  for (;;) {
    while (front < slots && kept[front]) ++front;
    while (back >= 0 && !kept[back]) --back;
    if (front >= back) break;
    move(back, front);
    kept[front] = 1;
    kept[back] = 0;
  }
  std::int32_t count = 0;
  while (count < slots && kept[count]) ++count;
  return count;
}

std::vector<std::uint8_t> realSlots(const std::vector<std::uint32_t>& tri) {
  std::vector<std::uint8_t> kept(tri.size() / 3);
  for (std::size_t t = 0; t < kept.size(); ++t)
    kept[t] = tri[3 * t] != kGhost && tri[3 * t + 1] != kGhost && tri[3 * t + 2] != kGhost;
  return kept;
}

// Drops the slots not kept, in place: twins pointing at a dropped slot become -1, then
// kept triangles from the end fill the holes, their twins told where they went. Only the
// few dropped slots (ghosts, mostly) cost anything beyond one pass. flags and labels, when
// given, hold one value per slot and move with their triangles.
void compact(Mesh& m, std::vector<std::uint8_t>* flags, std::vector<std::int32_t>* labels,
             std::vector<std::uint8_t> kept) {
  std::vector<std::uint32_t>& tri = m.triangles;
  std::vector<std::int32_t>& adj = m.halfedges;
  std::vector<std::uint8_t>& fixed = m.constrained;
  for (std::size_t t = 0; t < kept.size(); ++t) {
    if (!kept[t]) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t twin = adj[3 * t + k];
      if (twin >= 0 && !kept[twin / 3]) adj[3 * t + k] = -1;
    }
  }
  const std::int32_t count = planCompaction(kept, [&](std::int32_t back, std::int32_t front) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t from = 3 * back + k, to = 3 * front + k;
      tri[to] = tri[from];
      fixed[to] = fixed[from];
      adj[to] = adj[from];
      if (adj[to] >= 0) adj[adj[to]] = to;
    }
    if (flags) (*flags)[front] = (*flags)[back];
    if (labels) (*labels)[front] = (*labels)[back];
  });
  tri.resize(3 * static_cast<std::size_t>(count));
  adj.resize(3 * static_cast<std::size_t>(count));
  fixed.resize(3 * static_cast<std::size_t>(count));
  if (flags) flags->resize(count);
  if (labels) labels->resize(count);
}

void addProvenance(const Delaunay& d, Mesh& m) {
  if (d.constraints.edgeCount() == 0) return;
  m.sourceOffsets.push_back(0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
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

}  // namespace

std::vector<std::int32_t> slotIndices(const Topology& topo) {
  std::vector<std::uint8_t> kept = realSlots(topo.tri);
  std::vector<std::int32_t> index(kept.size(), -1);
  for (std::size_t t = 0; t < kept.size(); ++t)
    if (kept[t]) index[t] = static_cast<std::int32_t>(t);
  planCompaction(kept, [&](std::int32_t back, std::int32_t front) { index[back] = front; });
  return index;
}

Mesh exportMesh(Delaunay& d, const MeshOptions& options, bool consume) {
  const Progress& progress = d.options().progress;
  progress(Phase::Export, 0, 3);
  const bool classify = options.insideFlags || options.keep == Keep::Inside;
  std::vector<std::uint8_t> inside;
  if (classify) inside = insideSlots(d, options.fill);
  std::vector<std::int32_t> regions;
  if (options.regions) regions = regionSlots(d, options.polylinePolygons, options.fill);
  Mesh m;
  Topology& topo = d.topo;
  if (consume) {
    m.points = std::move(d.xy);
    m.triangles = std::move(topo.tri);
    m.halfedges = std::move(topo.adj);
    m.constrained = std::move(topo.fixed);
  } else {
    m.points = d.xy;
    m.triangles = topo.tri;
    m.halfedges = topo.adj;
    m.constrained = topo.fixed;
  }
  std::vector<std::uint8_t> kept = realSlots(m.triangles);
  if (options.keep == Keep::Inside)
    for (std::size_t t = 0; t < kept.size(); ++t) kept[t] &= inside[t];
  progress(Phase::Export, 1, 3);
  compact(m, classify ? &inside : nullptr, options.regions ? &regions : nullptr, std::move(kept));
  if (options.insideFlags) m.inside = std::move(inside);
  if (options.regions) m.regions = std::move(regions);
  progress(Phase::Export, 2, 3);
  addProvenance(d, m);
  progress(Phase::Export, 3, 3);
  return m;
}

}  // namespace geocdt
