#pragma once
// A half-edge out of each vertex, so that a constraint segment starts from its end vertices
// instead of locating their coordinates, a long walk each where the previous segment's end
// is no hint (bench/EXPERIMENTS.md, C16). Built in one pass over the triangles when a call
// inserts many segments. The entries are hints: flips and splits move half-edges between slots, so
// each one is checked when read and, when stale, found again around the triangle it names
// (a flip leaves the vertex in that triangle or a neighbour), or by a walk from there.
#include <cstdint>
#include <vector>

#include "base/chunks.h"
#include "delaunay/delaunay.h"

namespace geocdt {

class VertexEdges {
 public:
  // One half-edge out of each vertex of d, real or ghost triangle alike.
  void build(const Delaunay& d) {
    const std::vector<std::uint32_t>& tri = d.topo.tri;
    // Room for the crossings to come (a few per thousand vertices on real data), so that the
    // first of them does not double the table.
    out_.reserve(d.vertexCount() + d.vertexCount() / 64 + 64);
    out_.assign(d.vertexCount(), -1);
    std::int32_t* out = out_.data();
    forChunks(0, tri.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e)
        if (tri[e] != kGhost) out[tri[e]] = static_cast<std::int32_t>(e);
    });
  }

  bool built() const { return !out_.empty(); }
  // For a table kept across calls (editing): a hint that has gone far (its slot was reused
  // elsewhere) is replaced by a location from the grid, not a walk from the hint.
  void locateFromGrid() { fromGrid_ = true; }

  // Remembers half-edge e out of vertex v (once built: a call that inserts a few segments
  // into a large triangulation locates their ends instead of paying for a table).
  void set(std::uint32_t v, std::int32_t e) {
    if (out_.empty()) return;
    if (v >= out_.size()) out_.resize(v + 1, -1);
    out_[v] = e;
  }
  // v's hint as it is, unchecked (-1 for none).
  std::int32_t peek(std::uint32_t v) const { return v < out_.size() ? out_[v] : -1; }
  // Remembers the half-edge out of v in triangle t, if v is a corner of it.
  void setFromTriangle(const Topology& topo, std::uint32_t v, std::int32_t t) {
    for (int k = 0; k < 3; ++k)
      if (topo.tri[3 * t + k] == v) set(v, 3 * t + k);
  }

  // A half-edge out of vertex v, or -1 when no triangle has it (the triangulation is broken,
  // or v is not in it yet).
  std::int32_t find(Delaunay& d, std::uint32_t v) {
    const Topology& topo = d.topo;
    const std::int32_t hint = v < out_.size() ? out_[v] : -1;
    const std::int32_t slots = topo.slotCount();
    if (hint >= 0 && hint < 3 * slots) {
      if (topo.tri[hint] == v) return hint;
      const std::int32_t t = hint / 3;
      if (const std::int32_t found = cornerOf(topo, v, t); found >= 0) return remember(v, found);
      for (int k = 0; k < 3; ++k) {  // around the hint's triangle
        const std::int32_t n = topo.adj[3 * t + k];
        const std::int32_t found = n >= 0 ? cornerOf(topo, v, n / 3) : -1;
        if (found >= 0) return remember(v, found);
      }
      if (!fromGrid_) d.setLastTriangle(t);
    }
    // From the hint's triangle when there is one, else from the grid (the last triangle may
    // lie anywhere: an edit's vertices come in no order).
    const Hit h =
        d.locate(d.xy[2 * v], d.xy[2 * v + 1], fromGrid_ || !(hint >= 0 && hint < 3 * slots));
    if (h.kind != Hit::Kind::Vertex || topo.tri[h.edge] != v) return -1;
    return remember(v, h.edge);
  }

 private:
  static std::int32_t cornerOf(const Topology& topo, std::uint32_t v, std::int32_t t) {
    for (int k = 0; k < 3; ++k)
      if (topo.tri[3 * t + k] == v) return 3 * t + k;
    return -1;
  }
  std::int32_t remember(std::uint32_t v, std::int32_t e) {
    set(v, e);
    return e;
  }

  std::vector<std::int32_t> out_;
  bool fromGrid_ = false;
};

}  // namespace geocdt
