// Batches of points: their insertion order, the triangulation's first triangle once three
// points are not collinear, and the renumbering that gives new vertices their input order.
#include <algorithm>
#include <array>
#include <numeric>

#include "delaunay.h"
#include "geocdt/predicates.h"
#include "insertion_order.h"

namespace geocdt {

bool Delaunay::build(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const double* p = xy.data();
  const Sign o = orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1]);
  if (o == Sign::Zero) return false;
  if (o == Sign::Negative) std::swap(b, c);
  const std::int32_t t = topo.addTriangle(a, b, c);
  const std::int32_t g0 = topo.addTriangle(b, a, kGhost);
  const std::int32_t g1 = topo.addTriangle(c, b, kGhost);
  const std::int32_t g2 = topo.addTriangle(a, c, kGhost);
  topo.link(3 * t, 3 * g0);
  topo.link(3 * t + 1, 3 * g1);
  topo.link(3 * t + 2, 3 * g2);
  topo.link(3 * g0 + 1, 3 * g2 + 2);
  topo.link(3 * g1 + 1, 3 * g0 + 2);
  topo.link(3 * g2 + 1, 3 * g1 + 2);
  built_ = true;
  last_ = t;
  stats.inserted += 3;
  return true;
}

Status Delaunay::insertBatch(const double* input, std::uint32_t count, std::uint32_t* ids) {
  if (count == 0) return Status::success();
  const std::uint32_t base = vertexCount();
  std::vector<std::uint32_t> order = insertionOrder(input, count, options_.order);
  // A large batch is stored in insertion order while it is inserted, so that the walk and
  // the flips read coordinates that sit next to each other in memory; it costs one pass
  // over all triangles at the end, which a small batch (a click, a polyline) must not pay.
  const bool large = !built_ || 8 * static_cast<std::uint64_t>(count) > base;
  xy.resize(2 * (static_cast<std::size_t>(base) + count));
  double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  double minX = input[0], maxX = minX, minY = input[1], maxY = minY;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t i = large ? order[k] : k;
    const double x = input[2 * static_cast<std::size_t>(i)],
                 y = input[2 * static_cast<std::size_t>(i) + 1];
    p[2 * k] = x;
    p[2 * k + 1] = y;
    minX = std::min(minX, x);
    maxX = std::max(maxX, x);
    minY = std::min(minY, y);
    maxY = std::max(maxY, y);
  }
  // A large batch's ids[i] stays kGhost while point i is a vertex of its own, and names the
  // vertex it equals when it is a duplicate.
  if (large) std::fill(ids, ids + count, kGhost);
  if (grid_.empty()) grid_.reset(minX, minY, maxX, maxY, options_.gridDensity);
  batchStart_ = true;
  smallBatch_ = !large;
  inBatch_ = true;
  splits_.clear();
  const std::uint64_t duplicatesBefore = stats.duplicates;
  std::array<std::uint32_t, 3> built{kGhost, kGhost, kGhost};  // the batch's first triangle
  Status s;
  if (!built_) s = insertPending(base, count, order, ids, built);
  if (s.ok() && built_) {
    if (large && options_.start == LocateStart::LastTriangle) {
      s = insertRun(base, count, order, ids, built);
    } else {
      topo.reserve(topo.tri.size() / 3 + 2 * static_cast<std::size_t>(count) + 8);
      for (std::uint32_t k = 0; k < count && s.ok(); ++k) {
        const std::uint32_t v = base + (large ? k : order[k]);
        if (v == built[0] || v == built[1] || v == built[2]) continue;
        const std::uint32_t r = insertVertex(v);
        if (r == kGhost) s = error_;
        if (r != v || !large) ids[order[k]] = r;
      }
    }
  }
  if (!s.ok()) {
    inBatch_ = false;
    return s;
  }
  std::vector<std::uint32_t> newId;
  if (large) {
    newId = renumberBatch(input, base, count, order, ids, stats.duplicates != duplicatesBefore);
    if (built_) {
      // The cells' hints would point at the batch's first triangles: the next locate()
      // or batch rebuilds them, and a one-shot call that has none never pays for it.
      grid_.resizeFor(stats.inserted);
      gridStale_ = true;
    }
  } else if (stats.duplicates != duplicatesBefore) {
    newId = compactSmallBatch(base, count, ids);
  }
  inBatch_ = false;
  for (std::array<std::uint32_t, 3> split : splits_) {
    for (std::uint32_t& v : split)
      if (v >= base && !newId.empty()) v = newId[v - base];
    constraints.split(split[0], split[1], split[2]);
  }
  splits_.clear();
  return Status::success();
}

Status Delaunay::insertRun(std::uint32_t base, std::uint32_t count,
                           const std::vector<std::uint32_t>& order, std::uint32_t* ids,
                           std::array<std::uint32_t, 3> skip) {
  // The first point starts from the grid, before the arrays grow past the used slots.
  last_ = startTriangle(xy[2 * static_cast<std::size_t>(base)],
                        xy[2 * static_cast<std::size_t>(base) + 1], true);
  batchStart_ = false;
  const std::int32_t used = topo.slotCount();
  // Each insertion adds two slots: with them all in place, a split writes without checks.
  topo.resizeSlots(static_cast<std::size_t>(used) + 2 * static_cast<std::size_t>(count));
  runSlots_ = used;
  const bool withFlags = constrained();
  Status s;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t v = base + k;
    if (v == skip[0] || v == skip[1] || v == skip[2]) continue;
    const std::uint32_t r = withFlags ? insertRunVertex<true>(v) : insertRunVertex<false>(v);
    if (r == v) continue;
    if (r == kGhost) {
      s = error_;
      break;
    }
    ids[order[k]] = r;
  }
  topo.resizeSlots(static_cast<std::size_t>(runSlots_));
  runSlots_ = -1;
  return s;
}

// One vertex of insertRun, in a function of its own: WebAssembly engines optimise a function
// once it has run often, and a loop inlined whole into one long call would never be.
template <bool kConstrained>
GEOCDT_NOINLINE std::uint32_t Delaunay::insertRunVertex(std::uint32_t v) {
  const double x = xy[2 * static_cast<std::size_t>(v)], y = xy[2 * static_cast<std::size_t>(v) + 1];
  Hit h = walk(x, y, last_);
  if (h.kind == Hit::Kind::Failed) {
    ++stats.walkFallbacks;
    h = scan(x, y);
  }
  return insertAt<kConstrained>(h, v);
}

// A small batch kept its input numbering; duplicates left holes in it. Each surviving new
// vertex moves down to its place in first-appearance order, renamed in the triangles around
// it, which a turn around the vertex finds. New ids never exceed old ones, and going up in
// new ids means a target id is free by the time it is taken.
std::vector<std::uint32_t> Delaunay::compactSmallBatch(std::uint32_t base, std::uint32_t count,
                                                       std::uint32_t* ids) {
  std::vector<std::uint32_t> newId(count, kGhost);
  std::uint32_t next = base;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t v = ids[i];
    if (v < base) continue;
    if (newId[v - base] == kGhost) newId[v - base] = next++;
    ids[i] = newId[v - base];
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> moves;  // (new, old)
  for (std::uint32_t k = 0; k < count; ++k)
    if (newId[k] != kGhost && newId[k] != base + k) moves.push_back({newId[k], base + k});
  std::sort(moves.begin(), moves.end());
  for (const auto& [to, from] : moves) {
    const Hit h = locate(xy[2 * static_cast<std::size_t>(from)],
                         xy[2 * static_cast<std::size_t>(from) + 1], true);
    xy[2 * static_cast<std::size_t>(to)] = xy[2 * static_cast<std::size_t>(from)];
    xy[2 * static_cast<std::size_t>(to) + 1] = xy[2 * static_cast<std::size_t>(from) + 1];
    if (h.kind != Hit::Kind::Vertex) continue;
    std::int32_t e = h.edge;
    do {
      topo.tri[e] = to;
      e = topo.adj[prevEdge(e)];
    } while (e != h.edge);
  }
  xy.resize(2 * static_cast<std::size_t>(next));
  return newId;
}

void Delaunay::refreshGrid() {
  const std::uint32_t* tri = topo.tri.data();
  const double* p = xy.data();
  grid_.rebuild(
      topo.slotCount(),
      [&](std::int32_t t, double& x, double& y) {
        const std::uint32_t v = tri[3 * t];
        if (v == kGhost) return false;  // a ghost triangle with the ghost at its first corner
        x = p[2 * v];
        y = p[2 * v + 1];
        return true;
      },
      last_);
}

// Gives the batch's new vertices ids in input order, duplicates removed, and rewrites the
// triangles, the pending list and the coordinates to match. On entry ids[i] is kGhost for
// a point that became a vertex of its own, else the vertex it equals.
std::vector<std::uint32_t> Delaunay::renumberBatch(const double* input, std::uint32_t base,
                                                   std::uint32_t count,
                                                   std::vector<std::uint32_t>& order,
                                                   std::uint32_t* ids, bool duplicates) {
  // The insertion numbering is no longer needed: reuse its memory for the new ids.
  std::vector<std::uint32_t> newId(std::move(order));
  std::uint32_t next = base + count;
  if (!duplicates) {
    // Every point is a vertex: the k-th inserted is input point newId[k]. All sequential.
    for (std::uint32_t& v : newId) v += base;
    for (std::uint32_t i = 0; i < count; ++i) ids[i] = base + i;
    std::copy(input, input + 2 * static_cast<std::size_t>(count),
              xy.begin() + 2 * static_cast<std::ptrdiff_t>(base));
  } else {
    for (std::uint32_t k = 0; k < count; ++k)
      if (ids[newId[k]] == kGhost) ids[newId[k]] = base + k;
    // New ids follow the first appearance of each vertex in the input.
    std::fill(newId.begin(), newId.end(), kGhost);
    next = base;
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t v = ids[i];
      if (v < base) continue;
      if (newId[v - base] == kGhost) {
        newId[v - base] = next++;
        // Coordinates back in input order, taken from the input itself.
        xy[2 * static_cast<std::size_t>(newId[v - base])] = input[2 * static_cast<std::size_t>(i)];
        xy[2 * static_cast<std::size_t>(newId[v - base]) + 1] =
            input[2 * static_cast<std::size_t>(i) + 1];
      }
      ids[i] = newId[v - base];
    }
  }
  for (std::uint32_t& v : topo.tri)
    if (v >= base && v != kGhost) v = newId[v - base];
  for (std::uint32_t& v : pending_)
    if (v >= base) v = newId[v - base];
  xy.resize(2 * static_cast<std::size_t>(next));
  return newId;
}

Status Delaunay::insertPending(std::uint32_t base, std::uint32_t count,
                               const std::vector<std::uint32_t>& order, std::uint32_t* ids,
                               std::array<std::uint32_t, 3>& built) {
  // The vertices waiting, then the batch's: indexed, not copied (4 bytes a point saved).
  const std::size_t waiting = pending_.size(), n = waiting + count;
  const auto at = [&](std::size_t i) {
    return i < waiting ? pending_[i] : base + static_cast<std::uint32_t>(i - waiting);
  };
  const double* p = xy.data();
  const auto same = [p](std::uint32_t u, std::uint32_t v) {
    return p[2 * u] == p[2 * v] && p[2 * u + 1] == p[2 * v + 1];
  };
  std::size_t i1 = 1;
  while (i1 < n && same(at(0), at(i1))) ++i1;
  std::size_t i2 = i1 + 1;
  if (i1 < n) {
    const std::uint32_t a = at(0), b = at(i1);
    while (i2 < n && orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * at(i2)],
                              p[2 * at(i2) + 1]) == Sign::Zero)
      ++i2;
  }
  if (i1 >= n || i2 >= n) {
    // Still all collinear: no triangles yet; keep the vertices, without duplicates.
    for (std::uint32_t k = 0; k < count; ++k) pending_.push_back(base + k);
    dedupCollinear(base, order, ids);
    return Status::success();
  }
  const std::uint32_t a = at(0), b = at(i1), c = at(i2);
  build(a, b, c);
  double minX = p[2 * a], maxX = minX, minY = p[2 * a + 1], maxY = minY;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t v = at(i);
    minX = std::min(minX, p[2 * v]);
    maxX = std::max(maxX, p[2 * v]);
    minY = std::min(minY, p[2 * v + 1]);
    maxY = std::max(maxY, p[2 * v + 1]);
  }
  grid_.reset(minX, minY, maxX, maxY, options_.gridDensity);
  grid_.fill(last_);
  built = {a, b, c};
  // The vertices that waited; the batch's own follow in the caller's loop.
  for (std::size_t i = 1; i < waiting; ++i) {
    if (i == i1 || i == i2) continue;
    if (insertVertex(at(i)) == kGhost) return error_;
  }
  pending_.clear();
  return Status::success();
}

void Delaunay::dedupCollinear(std::uint32_t base, const std::vector<std::uint32_t>& order,
                              std::uint32_t* ids) {
  const double* p = xy.data();
  std::vector<std::uint32_t> sorted(pending_);
  std::sort(sorted.begin(), sorted.end(), [p](std::uint32_t u, std::uint32_t v) {
    if (p[2 * u] != p[2 * v]) return p[2 * u] < p[2 * v];
    if (p[2 * u + 1] != p[2 * v + 1]) return p[2 * u + 1] < p[2 * v + 1];
    return u < v;
  });
  pending_.clear();
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const std::uint32_t v = sorted[k];
    const bool repeat =
        k > 0 && p[2 * v] == p[2 * sorted[k - 1]] && p[2 * v + 1] == p[2 * sorted[k - 1] + 1];
    if (!repeat) {
      pending_.push_back(v);
      continue;
    }
    ++stats.duplicates;
    if (v >= base) ids[order[v - base]] = pending_.back();
  }
  std::sort(pending_.begin(), pending_.end());
}

}  // namespace geocdt
