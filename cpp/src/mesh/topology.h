#pragma once
// Triangles as flat arrays in delaunator's layout, closed by a ghost vertex at infinity so
// that every half-edge has a twin. Insertions split and flips rewrite triangles in their own
// slots. Removing a vertex frees two slots: the last triangles move into them (dropSlot), so
// the slots stay dense and every loop over them sees only triangles. Whatever remembers a
// slot (the grid's cells, the last triangle, vertex-to-edge tables) holds hints that are
// checked when read.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace geocdt {

inline constexpr std::uint32_t kGhost = 0xFFFFFFFFu;  // the vertex at infinity

inline std::int32_t nextEdge(std::int32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::int32_t prevEdge(std::int32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

struct Topology {
  std::vector<std::uint32_t> tri;   // 3 vertex ids per slot
  std::vector<std::int32_t> adj;    // twin of each half-edge
  std::vector<std::uint8_t> fixed;  // 1 when the half-edge is constrained

  std::int32_t slotCount() const { return static_cast<std::int32_t>(tri.size() / 3); }
  bool isGhost(std::int32_t t) const {
    return tri[3 * t] == kGhost || tri[3 * t + 1] == kGhost || tri[3 * t + 2] == kGhost;
  }

  // Room for `slots` triangles. Grows at least geometrically: an exact reserve per small
  // batch would copy every array on every call.
  void reserve(std::size_t slots) {
    if (3 * slots <= tri.capacity()) return;
    const std::size_t capacity = std::max(3 * slots, 2 * tri.capacity());
    tri.reserve(capacity);
    adj.reserve(capacity);
    fixed.reserve(capacity);
  }

  void clear() {
    tri.clear();
    adj.clear();
    fixed.clear();
  }

  // n more slots, zeroed. An insertion adds two at a time: element by element, cheaper than
  // resize's general path for so few (bench/EXPERIMENTS.md, R8).
  void appendSlots(std::size_t n) {
    for (std::size_t k = 0; k < 3 * n; ++k) {
      tri.push_back(0);
      adj.push_back(0);
      fixed.push_back(0);
    }
  }

  // Exactly `slots` slots: new ones zeroed, removed ones' memory kept for later growth.
  void resizeSlots(std::size_t slots) {
    tri.resize(3 * slots);
    adj.resize(3 * slots);
    fixed.resize(3 * slots);
  }

  void setTriangle(std::int32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    tri[3 * t] = a;
    tri[3 * t + 1] = b;
    tri[3 * t + 2] = c;
  }

  // Turning around the vertex that half-edge start leaves: the half-edge from it to v, or -1.
  std::int32_t edgeAround(std::int32_t start, std::uint32_t v) const {
    if (start < 0) return -1;
    std::int32_t e = start;
    do {
      if (tri[nextEdge(e)] == v) return e;
      e = adj[prevEdge(e)];
    } while (e != start);
    return -1;
  }

  // Frees slot t: the last slot's triangle moves into it (its twins told where it went) and
  // the arrays shrink by one slot. Returns the slot the moved triangle came from (t itself
  // when t was the last). Without flags (no edge is constrained: every flag 0) they stay.
  std::int32_t dropSlot(std::int32_t t, bool withFlags = true) {
    const std::int32_t last = slotCount() - 1;
    if (t != last) {
      for (int k = 0; k < 3; ++k) {
        const std::int32_t from = 3 * last + k, to = 3 * t + k;
        tri[to] = tri[from];
        if (withFlags) fixed[to] = fixed[from];
        adj[to] = adj[from];
        adj[adj[to]] = to;
      }
    }
    resizeSlots(static_cast<std::size_t>(last));
    return last;
  }

  void link(std::int32_t e, std::int32_t f) {
    adj[e] = f;
    if (f >= 0) adj[f] = e;
  }

  // Replaces the diagonal of the quad formed by the triangles of e and its twin.
  // Before: e = x->y in (x, y, v), f = y->x in (y, x, d). After: (d, y, v) and (v, x, d);
  // the new diagonal is prevEdge(e) = v->d and prevEdge(f) = d->v.
  void flip(std::int32_t e) {
    const std::int32_t f = adj[e];
    const std::int32_t e2 = prevEdge(e), f2 = prevEdge(f);
    const std::uint32_t v = tri[e2], d = tri[f2];
    const std::int32_t twinE2 = adj[e2], twinF2 = adj[f2];
    const std::uint8_t fixedE2 = fixed[e2], fixedF2 = fixed[f2];
    tri[e] = d;
    tri[f] = v;
    link(e, twinF2);
    fixed[e] = fixedF2;
    link(f, twinE2);
    fixed[f] = fixedE2;
    link(e2, f2);
    fixed[e2] = fixed[f2] = 0;
  }
};

}  // namespace geocdt
