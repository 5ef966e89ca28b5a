// Batches of points: their insertion order, the triangulation's first triangle once three
// points are not collinear, and the renumbering that closes up the places of duplicates.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "delaunay/delaunay.h"
#include "delaunay/first_triangle.h"
#include "delaunay/insertion_order.h"
#include "delaunay/vertex_edges.h"
#include "exact/orient_by_index.h"
#include "geocdt/predicates.h"

namespace geocdt {

bool Delaunay::build(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const double* p = xy.data();
  const Sign o = orientByIndex(p, a, b, c);
  if (o == Sign::Zero) return false;
  if (o == Sign::Negative) std::swap(b, c);
  const std::int32_t t = addSlots(4), g0 = t + 1, g1 = t + 2, g2 = t + 3;
  topo.setTriangle(t, a, b, c);
  topo.setTriangle(g0, b, a, kGhost);
  topo.setTriangle(g1, c, b, kGhost);
  topo.setTriangle(g2, a, c, kGhost);
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
  if (xy.empty() && wantsStrips(count)) {
    xy.assign(input, input + 2 * static_cast<std::size_t>(count));
    bool handled = false;
    const Status s = insertInStrips(count, ids, handled);
    if (!s.ok() || handled) return s;
    xy.clear();
  }
  const std::uint32_t base = vertexCount();
  stats.threads = 1;
  options_.progress(Phase::Sort, 0, count);
  std::vector<std::uint32_t> order = insertionOrder(input, count, options_.order);
  options_.progress(Phase::Sort, count, count);
  // Points the caller keeps are stored in insertion order while a run inserts them, so that
  // the walk and the flips find neighbours next to each other in memory, then put back in
  // input order from the input: faster than keeping input order and reading ahead
  // (bench/EXPERIMENTS.md, P9). A buffer taken over has no copy to restore from.
  const bool sorted = isLarge(count, base) && options_.start == LocateStart::LastTriangle;
  xy.resize(2 * (static_cast<std::size_t>(base) + count));
  double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  const std::uint32_t* o = order.data();
  forChunks(0, count, [=](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = sorted ? o[k] : k;
      p[2 * k] = input[2 * i];
      p[2 * k + 1] = input[2 * i + 1];
    }
  });
  return insertStored(count, ids, std::move(order), sorted ? input : nullptr);
}

Status Delaunay::insertBatch(std::vector<double>&& buffer, std::uint32_t* ids) {
  const auto count = static_cast<std::uint32_t>(buffer.size() / 2);
  if (count == 0) return Status::success();
  if (xy.empty()) {
    xy = std::move(buffer);
    xy.resize(2 * static_cast<std::size_t>(count));
  } else {
    xy.insert(xy.end(), buffer.begin(), buffer.begin() + 2 * static_cast<std::ptrdiff_t>(count));
    std::vector<double>().swap(buffer);
  }
  const std::size_t base = xy.size() / 2 - count;
  if (base == 0 && wantsStrips(count)) {
    bool handled = false;
    const Status s = insertInStrips(count, ids, handled);
    if (!s.ok() || handled) return s;
  }
  stats.threads = 1;
  options_.progress(Phase::Sort, 0, count);
  std::vector<std::uint32_t> order = insertionOrder(xy.data() + 2 * base, count, options_.order);
  options_.progress(Phase::Sort, count, count);
  return insertStored(count, ids, std::move(order), nullptr);
}

// The batch's points are the last count vertices of xy: in input order, or, when input is
// given, in insertion order (point order[k] at base + k) until the batch ends.
Status Delaunay::insertStored(std::uint32_t count, std::uint32_t* ids,
                              std::vector<std::uint32_t> order, const double* input) {
  const std::uint32_t base = vertexCount() - count;
  const double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  const bool large = isLarge(count, base);
  if (grid_.empty()) {
    const Bounds b = boundsOf(p, count);
    grid_.reset(b.minX, b.minY, b.maxX, b.maxY, options_.gridDensity);
  }
  // In a large batch ids[i] stays kGhost while point i is vertex base + i of its own, and
  // names the vertex it equals when it is a duplicate; a small batch sets every entry.
  if (large) std::fill(ids, ids + count, kGhost);
  batchStart_ = true;
  smallBatch_ = !large;
  inBatch_ = true;
  splits_.clear();
  batch_ = {base, ids, input ? order.data() : nullptr};
  const std::uint64_t duplicatesBefore = stats.duplicates;
  std::array<std::uint32_t, 3> built{kGhost, kGhost, kGhost};  // the batch's first triangle
  Status s;
  if (!built_) s = insertPending(order, built);
  if (s.ok() && built_) {
    if (large && options_.start == LocateStart::LastTriangle) {
      s = insertRun(order.data(), count, built);
    } else {
      topo.reserve(topo.tri.size() / 3 + 2 * static_cast<std::size_t>(count) + 8);
      for (std::uint32_t k = 0; k < count && s.ok(); ++k) {
        if ((k & 4095) == 0) options_.progress(Phase::Points, k, count);
        const std::uint32_t v = base + order[k];
        if (v == built[0] || v == built[1] || v == built[2]) continue;
        const std::uint32_t r = insertVertex(v);
        if (r == kGhost) s = error_;
        if (r != v || !large) recordDuplicate(v, r);
      }
    }
  }
  if (!s.ok()) {
    inBatch_ = false;
    return s;
  }
  if (input) restoreInputOrder(count, input);
  std::vector<std::uint32_t> newId;
  const bool duplicates = stats.duplicates != duplicatesBefore;
  if (large) {
    if (duplicates) {
      newId = compactLargeBatch(base, count, ids, std::move(order));
    } else {
      forChunks(0, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) ids[i] = base + static_cast<std::uint32_t>(i);
      });
    }
    // The cells' hints would point at the batch's first triangles: the next locate() or
    // batch sizes and fills the grid anew, and a one-shot call that has none never pays.
    gridStale_ = built_;
  } else if (duplicates) {
    newId = compactSmallBatch(base, count, ids);
  }
  inBatch_ = false;
  for (std::array<std::uint32_t, 3> split : splits_) {
    for (std::uint32_t& v : split)
      if (v >= base && !newId.empty()) v = newId[v - base];
    constraints.split(split[0], split[1], split[2]);
  }
  splits_.clear();
  options_.progress(Phase::Points, count, count);
  return Status::success();
}

Status Delaunay::insertRun(const std::uint32_t* order, std::uint32_t count,
                           std::array<std::uint32_t, 3> skip) {
  const std::uint32_t base = batch_.base;
  const bool sorted = batch_.order != nullptr;
  const auto vertex = [&](std::uint32_t k) { return base + (sorted ? k : order[k]); };
  // The first point starts from the grid, before the arrays grow past the used slots.
  const std::size_t first = vertex(0);
  last_ = startTriangle(xy[2 * first], xy[2 * first + 1], true);
  batchStart_ = false;
  // Each insertion adds two slots: with them all in place, a split writes without checks.
  // A strip worker's are in place already, from runSlots_ on.
  const bool worker = firstSlot_ >= 0;
  if (!worker) {
    const std::int32_t used = topo.slotCount();
    topo.resizeSlots(static_cast<std::size_t>(used) + 2 * static_cast<std::size_t>(count));
    runSlots_ = used;
  }
  const bool withFlags = constrained();
  Status s;
  // In chunks, so that this function, which runs once a batch, never spends the engine's
  // budget for optimised code: in a first call its long compile only took a core from the
  // call (bench/EXPERIMENTS.md, F21).
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    for (std::uint32_t k = static_cast<std::uint32_t>(begin); k < end && s.ok(); ++k) {
      // Points in input order lie each in a cache line of its own: read the next block's
      // coordinates ahead, so that their cache misses overlap one another instead of each
      // stalling its own insertion (bench/EXPERIMENTS.md, P9).
      if ((k & 4095) == 0) options_.progress(Phase::Points, k, count);
      if (!sorted && k % kRunBlock == 0 && k + kRunBlock < count)
        touch_ +=
            touchPoints(base, order + k + kRunBlock, std::min(kRunBlock, count - k - kRunBlock));
      const std::uint32_t v = vertex(k);
      if (v == skip[0] || v == skip[1] || v == skip[2]) continue;
      const std::uint32_t r = withFlags ? insertRunVertex<true>(v) : insertRunVertex<false>(v);
      if (r == kGhost) s = error_;
      if (r != v) recordDuplicate(v, r);
    }
  });
  if (!worker) {
    topo.resizeSlots(static_cast<std::size_t>(runSlots_));
    runSlots_ = -1;
  }
  return s;
}

// Back from insertion order (vertex base + k is input point order[k]) to input order: the
// triangles and the lists renamed, the coordinates copied from the input.
void Delaunay::restoreInputOrder(std::uint32_t count, const double* input) {
  const std::uint32_t base = batch_.base;
  const std::uint32_t* order = batch_.order;
  const auto rename = [&](std::uint32_t& v) {
    if (v >= base && v != kGhost) v = base + order[v - base];
  };
  std::uint32_t* tri = topo.tri.data();
  forChunks(0, topo.tri.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) rename(tri[i]);
  });
  for (std::uint32_t& v : pending_) rename(v);
  for (std::array<std::uint32_t, 3>& split : splits_)
    for (std::uint32_t& v : split) rename(v);
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) rename(batch_.ids[i]);
  });
  std::copy(input, input + 2 * static_cast<std::size_t>(count),
            xy.begin() + 2 * static_cast<std::ptrdiff_t>(base));
  batch_.order = nullptr;
}

void Delaunay::recordDuplicate(std::uint32_t v, std::uint32_t r) {
  const std::uint32_t k = v - batch_.base;
  batch_.ids[batch_.order ? batch_.order[k] : k] = r;
}

GEOCDT_NOINLINE double Delaunay::touchPoints(std::uint32_t base, const std::uint32_t* order,
                                             std::uint32_t n) const {
  const double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  double sum = 0;
  for (std::uint32_t k = 0; k < n; ++k) sum += p[2 * static_cast<std::size_t>(order[k])];
  return sum;
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

// After a large batch with duplicates: ids[i] is kGhost when point i became vertex base + i,
// else the vertex it equals. Each new vertex takes the place of its first appearance in the
// input, the duplicates' places close up, and triangles, ids and the pending list follow.
// One pass in input order; only the duplicates are looked up elsewhere.
std::vector<std::uint32_t> Delaunay::compactLargeBatch(std::uint32_t base, std::uint32_t count,
                                                       std::uint32_t* ids,
                                                       std::vector<std::uint32_t>&& scratch) {
  // first[j]: the first input point equal to vertex base + j (kGhost: not a vertex).
  std::vector<std::uint32_t> first(std::move(scratch));
  std::uint32_t* f = first.data();
  forChunks(0, count, [=](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j)
      f[j] = ids[j] == kGhost ? static_cast<std::uint32_t>(j) : kGhost;
  });
  forChunks(0, count, [=](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (ids[i] != kGhost && ids[i] >= base)
        f[ids[i] - base] = std::min(f[ids[i] - base], static_cast<std::uint32_t>(i));
  });
  // In input order, a vertex's first appearance gives it the next id, which replaces first[j]:
  // an id is never above the index that gave it, so it cannot pass for a later first one.
  std::uint32_t next = 0;
  double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (ids[i] != kGhost && ids[i] < base) continue;  // equals an older vertex
      const std::size_t j = ids[i] == kGhost ? i : ids[i] - base;
      if (f[j] == i) {
        p[2 * static_cast<std::size_t>(next)] = p[2 * i];
        p[2 * static_cast<std::size_t>(next) + 1] = p[2 * i + 1];
        f[j] = next++;
      }
      ids[i] = base + f[j];
    }
  });
  forChunks(0, count, [=](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j)
      if (f[j] != kGhost) f[j] += base;
  });
  std::uint32_t* tri = topo.tri.data();
  forChunks(0, topo.tri.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (tri[i] >= base && tri[i] != kGhost) tri[i] = first[tri[i] - base];
  });
  for (std::uint32_t& v : pending_)
    if (v >= base) v = first[v - base];
  xy.resize(2 * (static_cast<std::size_t>(base) + next));
  return first;
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
  grid_.resizeFor(stats.inserted);
  const std::uint32_t* tri = topo.tri.data();
  const double* p = xy.data();
  // About four triangles fall in a cell: every third is plenty, and a third of the writes.
  grid_.rebuild((topo.slotCount() + 2) / 3,
                [&](std::uint32_t k, double& x, double& y) {
                  const std::int32_t t = static_cast<std::int32_t>(3 * k);
                  const std::uint32_t v = tri[3 * t];
                  if (v == kGhost)
                    return -1;  // a ghost triangle with the ghost at its first corner
                  x = p[2 * v];
                  y = p[2 * v + 1];
                  return t;
                },
                last_);
}

void Delaunay::refreshStaleGrid(const VertexEdges& edges) {
  if (!gridStale_) return;
  gridStale_ = false;
  grid_.resizeFor(stats.inserted);
  const double* p = xy.data();
  const std::int32_t halfEdges = 3 * topo.slotCount();
  grid_.rebuild(
      vertexCount(),
      [&](std::uint32_t v, double& x, double& y) {
        const std::int32_t e = edges.peek(v);
        x = p[2 * std::size_t{v}];
        y = p[2 * std::size_t{v} + 1];
        // (A removed vertex's coordinates are NaN, and its hint may be gone.)
        if (e < 0 || e >= halfEdges || std::isnan(x)) return -1;
        return e / 3;
      },
      last_);
}

Status Delaunay::insertPending(const std::vector<std::uint32_t>& order,
                               std::array<std::uint32_t, 3>& built) {
  // The vertices waiting, then the batch's in insertion order (so that wherever they are
  // stored, the same triangle starts the same triangulation): indexed, not copied.
  const std::uint32_t base = batch_.base;
  const std::size_t waiting = pending_.size(), n = waiting + order.size();
  const auto at = [&](std::size_t i) {
    if (i < waiting) return pending_[i];
    const auto k = static_cast<std::uint32_t>(i - waiting);
    return base + (batch_.order ? k : order[k]);
  };
  const double* p = xy.data();
  std::size_t i1 = 0, i2 = 0;
  if (!findFirstTriangle(p, at, n, i1, i2)) {
    // Still all collinear: no triangles yet; keep the vertices, without duplicates.
    for (std::uint32_t k = 0; k < order.size(); ++k) pending_.push_back(base + k);
    dedupCollinear(base);
    return Status::success();
  }
  const std::uint32_t a = at(0), b = at(i1), c = at(i2);
  build(a, b, c);
  Bounds box{p[2 * a], p[2 * a + 1], p[2 * a], p[2 * a + 1]};
  forChunks(0, n, [&](std::size_t begin, std::size_t end) {
    Bounds c = box;
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t v = at(i);
      c.minX = std::min(c.minX, p[2 * v]);
      c.maxX = std::max(c.maxX, p[2 * v]);
      c.minY = std::min(c.minY, p[2 * v + 1]);
      c.maxY = std::max(c.maxY, p[2 * v + 1]);
    }
    box = c;
  });
  grid_.reset(box.minX, box.minY, box.maxX, box.maxY, options_.gridDensity);
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

void Delaunay::dedupCollinear(std::uint32_t base) {
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
    if (v >= base) recordDuplicate(v, pending_.back());
  }
  std::sort(pending_.begin(), pending_.end());
}

}  // namespace geocdt
