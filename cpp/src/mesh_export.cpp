#include <algorithm>

#include "triangulation_state.h"

namespace geocdt {

std::vector<std::int32_t> slotIndices(const Topology& topo) {
  std::vector<std::int32_t> index(topo.slotCount(), -1);
  std::int32_t n = 0;
  for (std::int32_t t = 0; t < topo.slotCount(); ++t)
    if (!topo.isFree(t) && !topo.isGhost(t)) index[t] = n++;
  return index;
}

Mesh exportMesh(const Delaunay& delaunay, const ConstraintStore& constraints,
                const MeshOptions& options) {
  const Topology& topo = delaunay.topo;
  const std::vector<std::int32_t> index = slotIndices(topo);
  std::int32_t count = 0;
  for (const std::int32_t i : index) count = std::max(count, i + 1);

  Mesh m;
  m.points = delaunay.xy;
  m.triangles.resize(3 * static_cast<std::size_t>(count));
  m.halfedges.resize(3 * static_cast<std::size_t>(count));
  m.constrained.resize(3 * static_cast<std::size_t>(count));
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    const std::int32_t n = index[t];
    if (n < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = 3 * t + k, out = 3 * n + k;
      m.triangles[out] = topo.tri[e];
      const std::int32_t twin = topo.adj[e];
      const std::int32_t twinTriangle = index[twin / 3];
      m.halfedges[out] = twinTriangle < 0 ? -1 : 3 * twinTriangle + twin % 3;
      m.constrained[out] = topo.fixed[e];
    }
  }
  (void)constraints;
  (void)options;
  return m;
}

}  // namespace geocdt
