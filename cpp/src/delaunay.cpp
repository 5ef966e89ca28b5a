#include "delaunay.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "geocdt/predicates.h"
#include "insertion_order.h"

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

void Delaunay::clear() {
  xy.clear();
  topo.clear();
  constraints.clear();
  pending_.clear();
  stack_.clear();
  built_ = false;
  last_ = -1;
  grid_ = PointGrid();
  stats = Stats();
}

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
  // Reserved after the sort's buffers are gone, to keep the peak low: about 2 triangles a point.
  topo.reserve(topo.tri.size() / 3 + 2 * static_cast<std::size_t>(count) + 8);
  // A large batch is stored in insertion order while it is inserted, so that the walk and
  // the flips read coordinates that sit next to each other in memory; it costs one pass
  // over all triangles at the end, which a small batch (a click, a polyline) must not pay.
  const bool large = !built_ || 8 * static_cast<std::uint64_t>(count) > base;
  xy.resize(2 * (static_cast<std::size_t>(base) + count));
  double* p = xy.data() + 2 * static_cast<std::size_t>(base);
  double minX = input[0], maxX = minX, minY = input[1], maxY = minY;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t i = large ? order[k] : k;
    const double x = input[2 * static_cast<std::size_t>(i)], y = input[2 * static_cast<std::size_t>(i) + 1];
    p[2 * k] = x;
    p[2 * k + 1] = y;
    minX = std::min(minX, x);
    maxX = std::max(maxX, x);
    minY = std::min(minY, y);
    maxY = std::max(maxY, y);
  }
  if (grid_.empty()) grid_.reset(minX, minY, maxX, maxY, options_.gridDensity);
  // ids[input index] = the vertex (in the batch's working numbering) it became or equals.
  batchStart_ = true;
  smallBatch_ = !large;
  inBatch_ = true;
  splits_.clear();
  const std::uint64_t duplicatesBefore = stats.duplicates;
  if (!built_) {
    Status s = insertPending(base, count, order, ids);
    if (!s.ok()) {
      inBatch_ = false;
      return s;
    }
  } else {
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t v = base + (large ? k : order[k]);
      const std::uint32_t r = insertVertex(v);
      if (r == kGhost) {
        inBatch_ = false;
        return error_;
      }
      ids[order[k]] = r;
    }
  }
  std::vector<std::uint32_t> newId;
  if (large) {
    newId = renumberBatch(input, base, count, order, ids);
    if (built_) refreshGrid();
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
    const Hit h = locate(xy[2 * static_cast<std::size_t>(from)], xy[2 * static_cast<std::size_t>(from) + 1], true);
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
  grid_.rebuild(topo.slotCount(), [&](std::int32_t t, double& x, double& y) {
    const std::uint32_t v = tri[3 * t];
    if (v >= kFreeSlot) return false;  // a ghost (at its first corner) or a free slot
    x = p[2 * v];
    y = p[2 * v + 1];
    return true;
  }, last_);
}

// Gives the batch's new vertices ids in input order, duplicates removed, and rewrites the
// triangles, the pending list and the coordinates to match.
std::vector<std::uint32_t> Delaunay::renumberBatch(const double* input, std::uint32_t base,
                                                   std::uint32_t count, std::vector<std::uint32_t>& order,
                                                   std::uint32_t* ids) {
  // The insertion numbering is no longer needed: reuse its memory for the new ids, which
  // follow the first appearance of each vertex in the input.
  std::vector<std::uint32_t> newId(std::move(order));
  std::fill(newId.begin(), newId.end(), kGhost);
  std::uint32_t next = base;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t v = ids[i];
    if (v < base) continue;
    if (newId[v - base] == kGhost) {
      newId[v - base] = next++;
      // Coordinates back in input order, taken from the input itself.
      xy[2 * static_cast<std::size_t>(newId[v - base])] = input[2 * static_cast<std::size_t>(i)];
      xy[2 * static_cast<std::size_t>(newId[v - base]) + 1] = input[2 * static_cast<std::size_t>(i) + 1];
    }
    ids[i] = newId[v - base];
  }
  for (std::uint32_t& v : topo.tri)
    if (v >= base && v < kFreeSlot) v = newId[v - base];
  for (std::uint32_t& v : pending_)
    if (v >= base) v = newId[v - base];
  xy.resize(2 * static_cast<std::size_t>(next));
  return newId;
}

Status Delaunay::insertPending(std::uint32_t base, std::uint32_t count,
                               const std::vector<std::uint32_t>& order, std::uint32_t* ids) {
  std::vector<std::uint32_t> seq(pending_);
  for (std::uint32_t k = 0; k < count; ++k) seq.push_back(base + k);
  const double* p = xy.data();
  const auto same = [p](std::uint32_t u, std::uint32_t v) {
    return p[2 * u] == p[2 * v] && p[2 * u + 1] == p[2 * v + 1];
  };
  std::size_t i1 = 1;
  while (i1 < seq.size() && same(seq[0], seq[i1])) ++i1;
  std::size_t i2 = i1 + 1;
  if (i1 < seq.size()) {
    const std::uint32_t a = seq[0], b = seq[i1];
    while (i2 < seq.size() && orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1],
                                       p[2 * seq[i2]], p[2 * seq[i2] + 1]) == Sign::Zero)
      ++i2;
  }
  if (i1 >= seq.size() || i2 >= seq.size()) {
    // Still all collinear: no triangles yet; keep the vertices, without duplicates.
    for (std::uint32_t k = 0; k < count; ++k) ids[order[k]] = base + k;
    pending_.swap(seq);
    dedupCollinear(base, order, ids);
    return Status::success();
  }
  pending_.clear();
  const std::uint32_t a = seq[0], b = seq[i1], c = seq[i2];
  build(a, b, c);
  double minX = p[2 * a], maxX = minX, minY = p[2 * a + 1], maxY = minY;
  for (const std::uint32_t v : seq) {
    minX = std::min(minX, p[2 * v]);
    maxX = std::max(maxX, p[2 * v]);
    minY = std::min(minY, p[2 * v + 1]);
    maxY = std::max(maxY, p[2 * v + 1]);
  }
  grid_.reset(minX, minY, maxX, maxY, options_.gridDensity);
  grid_.fill(last_);
  for (const std::uint32_t v : {a, b, c})
    if (v >= base) ids[order[v - base]] = v;
  for (std::size_t k = 1; k < seq.size(); ++k) {
    if (k == i1 || k == i2) continue;
    const std::uint32_t r = insertVertex(seq[k]);
    if (r == kGhost) return error_;
    if (seq[k] >= base) ids[order[seq[k] - base]] = r;
  }
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
    const bool repeat = k > 0 && p[2 * v] == p[2 * sorted[k - 1]] &&
                        p[2 * v + 1] == p[2 * sorted[k - 1] + 1];
    if (!repeat) {
      pending_.push_back(v);
      continue;
    }
    ++stats.duplicates;
    if (v >= base) ids[order[v - base]] = pending_.back();
  }
  std::sort(pending_.begin(), pending_.end());
}

std::int32_t Delaunay::startTriangle(double x, double y, bool fromGrid) {
  if (fromGrid) {
    const std::int32_t t = grid_.cellAt(x, y);
    if (t >= 0 && t < topo.slotCount() && !topo.isFree(t)) return t;
  }
  if (last_ >= 0 && last_ < topo.slotCount() && !topo.isFree(last_)) return last_;
  for (std::int32_t t = 0; t < topo.slotCount(); ++t)
    if (!topo.isFree(t)) return t;
  return -1;
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
  const double* p = xy.data();
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t* adj = topo.adj.data();
  const std::int64_t bound = 64 + 2 * static_cast<std::int64_t>(topo.slotCount());
  std::int32_t entered = -1;
  for (std::int64_t step = 0; step < bound; ++step) {
    ++stats.walkSteps;
    const std::int32_t e0 = 3 * t;
    const std::uint32_t a = tri[e0], b = tri[e0 + 1], c = tri[e0 + 2];
    if (a != kGhost && b != kGhost && c != kGhost) {
      const Sign o0 = e0 == entered ? Sign::Positive
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
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (topo.isFree(t) || topo.isGhost(t)) continue;
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
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (topo.isFree(t) || !topo.isGhost(t)) continue;
    const std::int32_t e0 = 3 * t;
    const int g = tri[e0] == kGhost ? 0 : (tri[e0 + 1] == kGhost ? 1 : 2);
    const std::int32_t r = e0 + (g + 1) % 3;
    const std::uint32_t u = tri[r], w = tri[nextEdge(r)];
    if (orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], x, y) == Sign::Positive)
      return {Hit::Kind::Outside, r};
  }
  return {Hit::Kind::Failed, -1};
}

std::uint32_t Delaunay::insertVertex(std::uint32_t v) {
  const double x = xy[2 * v], y = xy[2 * v + 1];
  // The first point of a batch has no useful last triangle, nor has any point of a small
  // batch (its points lie far apart): the grid knows better.
  const bool fromGrid = options_.start == LocateStart::Grid || batchStart_ || smallBatch_;
  batchStart_ = false;
  const Hit h = locate(x, y, fromGrid);
  switch (h.kind) {
    case Hit::Kind::Vertex:
      ++stats.duplicates;
      return topo.tri[h.edge];
    case Hit::Kind::Face:
    case Hit::Kind::Outside:
      insertInFace(h.edge / 3, v);
      break;
    case Hit::Kind::Edge:
      if (topo.fixed[h.edge]) {
        // On a constrained edge: its halves carry what it carried. Inside a batch, v's id is
        // still a working one, so the store learns of it when the batch ends.
        const std::array<std::uint32_t, 3> split{topo.tri[h.edge], topo.tri[nextEdge(h.edge)], v};
        if (inBatch_) {
          splits_.push_back(split);
        } else {
          constraints.split(split[0], split[1], split[2]);
        }
      }
      splitEdge(h.edge, v);
      break;
    case Hit::Kind::Empty:
    case Hit::Kind::Failed:
      error_ = {StatusCode::InternalError,
                "point location failed for vertex " + std::to_string(v) + ": a broken triangulation",
                v};
      return kGhost;
  }
  ++stats.inserted;
  grid_.grow(stats.inserted);
  return v;
}

std::int32_t Delaunay::insertInFace(std::int32_t t, std::uint32_t v) {
  const std::int32_t e0 = 3 * t;
  const std::uint32_t a = topo.tri[e0], b = topo.tri[e0 + 1], c = topo.tri[e0 + 2];
  const std::int32_t n1 = topo.adj[e0 + 1], n2 = topo.adj[e0 + 2];
  const std::uint8_t f1 = topo.fixed[e0 + 1], f2 = topo.fixed[e0 + 2];
  const std::int32_t t1 = topo.addTriangle(b, c, v);
  const std::int32_t t2 = topo.addTriangle(c, a, v);
  topo.setTriangle(t, a, b, v);
  topo.link(3 * t1, n1);
  topo.fixed[3 * t1] = f1;
  topo.link(3 * t2, n2);
  topo.fixed[3 * t2] = f2;
  topo.link(e0 + 1, 3 * t1 + 2);
  topo.link(3 * t1 + 1, 3 * t2 + 2);
  topo.link(3 * t2 + 1, e0 + 2);
  topo.fixed[e0 + 1] = topo.fixed[e0 + 2] = 0;
  last_ = t;
  stack_.push_back(e0);
  stack_.push_back(3 * t1);
  stack_.push_back(3 * t2);
  legalize(v);
  return edgeFrom(t, v);
}

std::int32_t Delaunay::splitEdge(std::int32_t e, std::uint32_t v) {
  // e = a->b in (a, b, c); f = b->a in (b, a, d).
  const std::int32_t f = topo.adj[e];
  const std::int32_t e1 = nextEdge(e), e2 = prevEdge(e), f1 = nextEdge(f), f2 = prevEdge(f);
  const std::uint32_t a = topo.tri[e], b = topo.tri[f], c = topo.tri[e2], d = topo.tri[f2];
  const std::int32_t ne1 = topo.adj[e1], ne2 = topo.adj[e2], nf1 = topo.adj[f1], nf2 = topo.adj[f2];
  const std::uint8_t fe = topo.fixed[e], fe1 = topo.fixed[e1], fe2 = topo.fixed[e2];
  const std::uint8_t ff1 = topo.fixed[f1], ff2 = topo.fixed[f2];
  const std::int32_t tA = e / 3, tB = f / 3;
  // (c, a, v) and (a, d, v) keep the old slots; (b, c, v) and (d, b, v) are new.
  topo.setTriangle(tA, c, a, v);
  topo.setTriangle(tB, a, d, v);
  const std::int32_t tC = topo.addTriangle(b, c, v);
  const std::int32_t tD = topo.addTriangle(d, b, v);
  const std::int32_t A = 3 * tA, B = 3 * tB, C = 3 * tC, D = 3 * tD;
  topo.link(A, ne2);
  topo.fixed[A] = fe2;
  topo.link(B, nf1);
  topo.fixed[B] = ff1;
  topo.link(C, ne1);
  topo.fixed[C] = fe1;
  topo.link(D, nf2);
  topo.fixed[D] = ff2;
  topo.link(A + 1, B + 2);  // a->v with v->a
  topo.link(A + 2, C + 1);  // v->c with c->v
  topo.link(C + 2, D + 1);  // v->b with b->v
  topo.link(D + 2, B + 1);  // v->d with d->v
  topo.fixed[A + 1] = topo.fixed[B + 2] = fe;
  topo.fixed[C + 2] = topo.fixed[D + 1] = fe;
  topo.fixed[A + 2] = topo.fixed[C + 1] = topo.fixed[D + 2] = topo.fixed[B + 1] = 0;
  last_ = tA;
  stack_.push_back(A);
  stack_.push_back(B);
  stack_.push_back(C);
  stack_.push_back(D);
  legalize(v);
  return edgeFrom(tA, v);
}

std::int32_t Delaunay::edgeFrom(std::int32_t t, std::uint32_t v) const {
  for (int k = 0; k < 3; ++k)
    if (topo.tri[3 * t + k] == v) return 3 * t + k;
  return -1;
}

bool Delaunay::beyondGhostEdge(std::int32_t r, std::uint32_t v) const {
  const double* p = xy.data();
  const std::uint32_t u = topo.tri[r], w = topo.tri[nextEdge(r)];
  return orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], p[2 * v], p[2 * v + 1]) ==
         Sign::Positive;
}

bool Delaunay::isLocallyDelaunay(std::int32_t e) const {
  const std::int32_t f = topo.adj[e];
  const std::uint32_t x = topo.tri[e], y = topo.tri[nextEdge(e)];
  const std::uint32_t v = topo.tri[prevEdge(e)], d = topo.tri[prevEdge(f)];
  if (v == kGhost || d == kGhost || x == kGhost || y == kGhost) {
    if (v == kGhost) return true;  // both sides ghost-facing: the hull rule is checked from d
    // The neighbour (y, x, d) is a ghost triangle: v must not lie beyond its real edge.
    const std::int32_t r = d == kGhost ? f : (x == kGhost ? prevEdge(f) : nextEdge(f));
    return !beyondGhostEdge(r, v);
  }
  const double* p = xy.data();
  return incircle(p[2 * y], p[2 * y + 1], p[2 * x], p[2 * x + 1], p[2 * d], p[2 * d + 1],
                  p[2 * v], p[2 * v + 1]) != Sign::Positive;
}

void Delaunay::legalize(std::uint32_t v) {
  (void)v;
  while (!stack_.empty()) {
    const std::int32_t e = stack_.back();
    stack_.pop_back();
    if (topo.fixed[e] || isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo.adj[e];
    topo.flip(e);
    ++stats.flips;
    stack_.push_back(e);
    stack_.push_back(nextEdge(f));
  }
}

}  // namespace geocdt
