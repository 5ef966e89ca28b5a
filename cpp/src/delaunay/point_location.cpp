// Point location: a visibility walk from the grid's cell hint or the last triangle, with
// an exhaustive scan as the guaranteed answer when a walk gives up.
#include <algorithm>
#include <utility>

#include "delaunay/delaunay.h"
#include "geocdt/predicates.h"

namespace geocdt {

namespace {

// For points known to be collinear with a and b: where q lies along the line.
enum class Along { Before, AtA, Between, AtB, After };

Along alongSegment(const double* a, const double* b, const double* q) {
  const int axis = a[0] != b[0] ? 0 : 1;
  const double lo = a[axis], hi = b[axis], v = q[axis];
  if (v == lo) return Along::AtA;
  if (v == hi) return Along::AtB;
  const bool increasing = lo < hi;
  if (increasing ? v < lo : v > lo) return Along::Before;
  if (increasing ? v > hi : v < hi) return Along::After;
  return Along::Between;
}

}  // namespace
bool Delaunay::startsNear(std::int32_t t, double x, double y) const {
  const std::uint32_t v = topo.tri[3 * t] != kGhost ? topo.tri[3 * t] : topo.tri[3 * t + 1];
  return grid_.near(xy[2 * std::size_t{v}], xy[2 * std::size_t{v} + 1], x, y);
}

std::int32_t Delaunay::startTriangle(double x, double y, bool fromGrid) {
  if (fromGrid) {
    if (gridStale_) {
      refreshGrid();
      gridStale_ = false;
    }
    const std::int32_t t = grid_.cellAt(x, y);
    const bool valid = t >= 0 && t < topo.slotCount();
    if (valid && (!slotsReused_ || startsNear(t, x, y))) return t;
    // After removals a cell may name a slot reused far away, or one past the last: a
    // neighbour cell's then.
    if (slotsReused_) {
      for (const auto& [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
        const std::int32_t n = grid_.neighbour(x, y, di, dj);
        if (n >= 0 && n < topo.slotCount() && startsNear(n, x, y)) return n;
      }
    }
    if (valid) return t;
  }
  if (last_ >= 0 && last_ < topo.slotCount()) return last_;
  return topo.slotCount() > 0 ? 0 : -1;
}

Hit Delaunay::locate(double x, double y, bool fromGrid) {
  if (!built_) return Hit{};
  Hit h = walk(x, y, startTriangle(x, y, fromGrid));
  if (h.kind == Hit::Kind::Failed) {
    ++stats.walkFallbacks;
    h = scan(x, y);
  }
  if (h.kind != Hit::Kind::Failed) {
    const std::int32_t t = h.edge / 3;
    grid_.cellAt(x, y) = t;
    last_ = t;
  }
  return h;
}

// Visibility walk: cross any edge that has the point strictly on its far side. It cannot
// cycle in a Delaunay triangulation; constrained ones get a step bound and a scan.
Hit Delaunay::walk(double x, double y, std::int32_t t) {
  ++stats.locates;
  std::int64_t step = 0;
  const Hit h = walkFrom(x, y, t, step);
  stats.walkSteps += static_cast<std::uint64_t>(step);
  return h;
}

Hit Delaunay::walkFrom(double x, double y, std::int32_t t, std::int64_t& step) const {
  const double* p = xy.data();
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t* adj = topo.adj.data();
  const std::int64_t bound = 64 + 2 * static_cast<std::int64_t>(topo.slotCount());
  std::int32_t entered = -1;
  while (step < bound) {
    ++step;
    const std::int32_t e0 = 3 * t;
    const std::uint32_t a = tri[e0], b = tri[e0 + 1], c = tri[e0 + 2];
    if (a != kGhost && b != kGhost && c != kGhost) {
      const Sign o0 = e0 == entered
                          ? Sign::Positive
                          : orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y);
      if (o0 == Sign::Negative) {
        entered = adj[e0];
        t = entered / 3;
        continue;
      }
      const Sign o1 = e0 + 1 == entered
                          ? Sign::Positive
                          : orient2d(p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], x, y);
      if (o1 == Sign::Negative) {
        entered = adj[e0 + 1];
        t = entered / 3;
        continue;
      }
      const Sign o2 = e0 + 2 == entered
                          ? Sign::Positive
                          : orient2d(p[2 * c], p[2 * c + 1], p[2 * a], p[2 * a + 1], x, y);
      if (o2 == Sign::Negative) {
        entered = adj[e0 + 2];
        t = entered / 3;
        continue;
      }
      const bool z0 = o0 == Sign::Zero, z1 = o1 == Sign::Zero, z2 = o2 == Sign::Zero;
      if (z0 && z1) return {Hit::Kind::Vertex, e0 + 1};
      if (z1 && z2) return {Hit::Kind::Vertex, e0 + 2};
      if (z2 && z0) return {Hit::Kind::Vertex, e0};
      if (z0) return {Hit::Kind::Edge, e0};
      if (z1) return {Hit::Kind::Edge, e0 + 1};
      if (z2) return {Hit::Kind::Edge, e0 + 2};
      return {Hit::Kind::Face, e0};
    }
    // A ghost triangle: only its real edge r = u->w matters.
    const int g = a == kGhost ? 0 : (b == kGhost ? 1 : 2);
    const std::int32_t r = e0 + (g + 1) % 3;
    const std::uint32_t u = tri[r], w = tri[nextEdge(r)];
    const Sign o = r == entered ? Sign::Positive
                                : orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], x, y);
    if (o == Sign::Positive) return {Hit::Kind::Outside, r};
    if (o == Sign::Negative) {
      entered = adj[r];
      t = entered / 3;
      continue;
    }
    const double q[2] = {x, y};
    switch (alongSegment(p + 2 * u, p + 2 * w, q)) {
      case Along::AtA: return {Hit::Kind::Vertex, r};
      case Along::AtB: return {Hit::Kind::Vertex, nextEdge(r)};
      case Along::Between: return {Hit::Kind::Edge, r};
      case Along::After: entered = adj[nextEdge(r)]; break;
      case Along::Before: entered = adj[prevEdge(r)]; break;
    }
    t = entered / 3;
  }
  return {Hit::Kind::Failed, -1};
}

// Exhaustive location: the guaranteed answer when a walk gives up.
Hit Delaunay::scan(double x, double y) const {
  const double* p = xy.data();
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t slots = runSlots_ >= 0 ? runSlots_ : topo.slotCount();
  const std::int32_t first = std::max(firstSlot_, 0);  // a strip worker's own slots only
  for (std::int32_t t = first; t < slots; ++t) {
    if (topo.isGhost(t)) continue;
    const std::int32_t e0 = 3 * t;
    Sign o[3];
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const std::uint32_t a = tri[e0 + k], b = tri[nextEdge(e0 + k)];
      o[k] = orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y);
      inside = o[k] != Sign::Negative;
    }
    if (!inside) continue;
    for (int k = 0; k < 3; ++k)
      if (o[k] == Sign::Zero && o[(k + 2) % 3] == Sign::Zero) return {Hit::Kind::Vertex, e0 + k};
    for (int k = 0; k < 3; ++k)
      if (o[k] == Sign::Zero) return {Hit::Kind::Edge, e0 + k};
    return {Hit::Kind::Face, e0};
  }
  for (std::int32_t t = first; t < slots; ++t) {
    if (!topo.isGhost(t)) continue;
    const std::int32_t e0 = 3 * t;
    const int g = tri[e0] == kGhost ? 0 : (tri[e0 + 1] == kGhost ? 1 : 2);
    const std::int32_t r = e0 + (g + 1) % 3;
    const std::uint32_t u = tri[r], w = tri[nextEdge(r)];
    if (orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], x, y) == Sign::Positive)
      return {Hit::Kind::Outside, r};
  }
  return {Hit::Kind::Failed, -1};
}

}  // namespace geocdt
