// Insertion of one point: split its triangle or edge, then Lawson flips until every edge
// around it is (constrained) Delaunay, with the ghost triangles' in-circle rule at the hull.
#include "delaunay/delaunay.h"

#include <algorithm>
#include <array>
#include <utility>

#include "exact/orient_by_index.h"
#include "geocdt/predicates.h"

namespace geocdt {

Delaunay& Delaunay::operator=(Delaunay&& other) noexcept {
  xy = std::move(other.xy);
  topo = std::move(other.topo);
  constraints = std::move(other.constraints);
  stats = other.stats;
  steiner = std::move(other.steiner);
  cocircular = other.cocircular;
  options_ = other.options_;
  grid_ = std::move(other.grid_);
  gridStale_ = other.gridStale_;
  built_ = other.built_;
  batchStart_ = other.batchStart_;
  smallBatch_ = other.smallBatch_;
  inBatch_ = other.inBatch_;
  splits_ = std::move(other.splits_);
  last_ = other.last_;
  runSlots_ = other.runSlots_;
  firstSlot_ = other.firstSlot_;
  batch_ = other.batch_;
  touch_ = other.touch_;
  pending_ = std::move(other.pending_);
  stack_ = std::move(other.stack_);
  star_ = std::move(other.star_);
  lawson_ = std::move(other.lawson_);
  lawsonTop_ = other.lawsonTop_;
  ring_ = std::move(other.ring_);
  spare_[0] = other.spare_[0];
  spare_[1] = other.spare_[1];
  slotsReused_ = other.slotsReused_;
  error_ = std::move(other.error_);
  return *this;
}

void Delaunay::clear() {
  xy.clear();
  topo.clear();
  constraints.clear();
  pending_.clear();
  stack_.clear();
  built_ = false;
  last_ = -1;
  grid_ = PointGrid();
  gridStale_ = false;
  stats = Stats();
  steiner.clear();
  spare_[0] = spare_[1] = -1;
  slotsReused_ = false;
}

std::uint32_t Delaunay::insertVertex(std::uint32_t v) {
  const double x = xy[2 * v], y = xy[2 * v + 1];
  // The first point of a batch has no useful last triangle, nor has any point of a small
  // batch (its points lie far apart): the grid knows better.
  const bool fromGrid = options_.start == LocateStart::Grid || batchStart_ || smallBatch_;
  batchStart_ = false;
  const Hit h = locate(x, y, fromGrid);
  const std::uint32_t r = constrained() ? insertAt<true>(h, v) : insertAt<false>(h, v);
  if (r == v) grid_.grow(stats.inserted);
  return r;
}

std::uint32_t Delaunay::insertLocated(const Hit& h, std::uint32_t v) {
  const std::uint32_t r = constrained() ? insertAt<true>(h, v) : insertAt<false>(h, v);
  if (r == v) grid_.grow(stats.inserted);
  return r;
}

template <bool kConstrained>
std::uint32_t Delaunay::insertAt(const Hit& h, std::uint32_t v) {
  switch (h.kind) {
    case Hit::Kind::Vertex:
      ++stats.duplicates;
      last_ = h.edge / 3;
      return topo.tri[h.edge];
    case Hit::Kind::Face:
    case Hit::Kind::Outside: {
      std::int32_t t1, t2;
      takeSlotPair(t1, t2);
      last_ = splitFace<kConstrained>(h.edge / 3, v, t1, t2);
      break;
    }
    case Hit::Kind::Edge: {
      if (kConstrained && topo.fixed[h.edge]) {
        // On a constrained edge: its halves carry what it carried. Inside a batch, v's id is
        // still a working one, so the store learns of it when the batch ends.
        const std::array<std::uint32_t, 3> split{topo.tri[h.edge], topo.tri[nextEdge(h.edge)], v};
        if (inBatch_) {
          splits_.push_back(split);
        } else {
          constraints.split(split[0], split[1], split[2]);
        }
      }
      std::int32_t t3, t4;
      takeSlotPair(t3, t4);
      last_ = splitEdgeAt<kConstrained>(h.edge, v, t3, t4);
      break;
    }
    case Hit::Kind::Empty:
    case Hit::Kind::Failed:
      error_ = {
          StatusCode::InternalError,
          "point location failed for vertex " + std::to_string(v) + ": a broken triangulation", v};
      return kGhost;
  }
  ++stats.inserted;
  return v;
}

template std::uint32_t Delaunay::insertAt<false>(const Hit&, std::uint32_t);
template std::uint32_t Delaunay::insertAt<true>(const Hit&, std::uint32_t);

std::int32_t Delaunay::splitEdge(std::int32_t e, std::uint32_t v) {
  const std::int32_t t3 = addSlots(2);
  const std::int32_t t =
      constrained() ? splitEdgeAt<true>(e, v, t3, t3 + 1) : splitEdgeAt<false>(e, v, t3, t3 + 1);
  last_ = t;
  return 3 * t + 2;  // v -> the first corner
}

std::int32_t Delaunay::fillStar(std::uint32_t v, const std::vector<std::int32_t>& slots,
                                const std::vector<std::int32_t>& boundary) {
  const std::size_t n = boundary.size();
  // Every boundary edge's twin and flag, read before the slots are rewritten.
  star_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t e = boundary[i];
    star_[i] = {topo.tri[e], topo.adj[e], topo.fixed[e]};
  }
  const std::int32_t extra = addSlots(2);
  std::uint32_t* tri = topo.tri.data();
  std::int32_t* adj = topo.adj.data();
  std::uint8_t* fixed = topo.fixed.data();
  // Slot i becomes (a_i, b_i, v): its first edge is the boundary edge, then b_i -> v, then
  // v -> a_i, twinned with the next slot's and the previous slot's spokes.
  const auto slotOf = [&](std::size_t i) {
    return 3 * (i < slots.size() ? slots[i] : extra + static_cast<std::int32_t>(i - slots.size()));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t s = slotOf(i), next = slotOf(i + 1 < n ? i + 1 : 0);
    tri[s] = star_[i].start;
    tri[s + 1] = star_[i + 1 < n ? i + 1 : 0].start;
    tri[s + 2] = v;
    adj[s] = star_[i].twin;
    adj[star_[i].twin] = s;
    adj[s + 1] = next + 2;
    adj[next + 2] = s + 1;
    fixed[s] = star_[i].fixed;
    fixed[s + 1] = fixed[s + 2] = 0;
  }
  last_ = slotOf(0) / 3;
  ++stats.inserted;
  grid_.grow(stats.inserted);
  return slotOf(0) + 2;
}

std::int32_t Delaunay::addSlots(std::int32_t n) {
  if (runSlots_ >= 0) {  // inside insertRun: the arrays already have room
    const std::int32_t first = runSlots_;
    runSlots_ += n;
    return first;
  }
  const std::int32_t first = topo.slotCount();
  topo.appendSlots(static_cast<std::size_t>(n));
  return first;
}

void Delaunay::takeSlotPair(std::int32_t& t1, std::int32_t& t2) {
  if (spare_[0] < 0) {
    t1 = addSlots(2);
    t2 = t1 + 1;
    return;
  }
  t1 = spare_[0];
  t2 = spare_[1];
  spare_[0] = spare_[1] = -1;
  if (!constrained()) return;            // (every flag is 0 then)
  for (const std::int32_t t : {t1, t2})  // as new slots are: zeroed flags
    topo.fixed[3 * t] = topo.fixed[3 * t + 1] = topo.fixed[3 * t + 2] = 0;
}

// Fills the k slots around p in counter-clockwise order: slot i becomes (ring[i],
// ring[i + 1], p), its first edge twinned with outer[i] and its spokes with its neighbours';
// each goes on the Lawson stack.
template <int k>
void Delaunay::fillFan(std::uint32_t p, const std::uint32_t (&ring)[k],
                       const std::int32_t (&outer)[k], const std::int32_t (&slot)[k]) {
  std::uint32_t* tri = topo.tri.data();
  std::int32_t* adj = topo.adj.data();
  for (int i = 0; i < k; ++i) {
    const std::int32_t s = slot[i], next = slot[i + 1 < k ? i + 1 : 0];
    tri[s] = ring[i];
    tri[s + 1] = ring[i + 1 < k ? i + 1 : 0];
    tri[s + 2] = p;
    adj[s] = outer[i];
    adj[outer[i]] = s;
    adj[s + 1] = next + 2;
    adj[next + 2] = s + 1;
    pushLawson(s);
  }
}

// Triangle t = (a, b, c) becomes (a, b, p); new slots t1 = (b, c, p) and t2 = (c, a, p).
template <bool kConstrained>
std::int32_t Delaunay::splitFace(std::int32_t t, std::uint32_t p, std::int32_t t1,
                                 std::int32_t t2) {
  const std::int32_t A = 3 * t, B = 3 * t1, C = 3 * t2;
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t* adj = topo.adj.data();
  fillFan<3>(p, {tri[A], tri[A + 1], tri[A + 2]}, {adj[A], adj[A + 1], adj[A + 2]}, {A, B, C});
  if (kConstrained) {  // the new slots are zeroed: only the outer edges carry flags
    std::uint8_t* fixed = topo.fixed.data();
    fixed[B] = fixed[A + 1];
    fixed[C] = fixed[A + 2];
    fixed[A + 1] = fixed[A + 2] = 0;
  }
  legalizeAround<kConstrained>(p);
  return t;
}

// e = a->b in (a, b, c) and its twin b->a in (b, a, d) become (c, a, p) and (a, d, p) in
// their slots, (b, c, p) in t3 and (d, b, p) in t4. The spokes to a and b carry e's flag.
template <bool kConstrained>
std::int32_t Delaunay::splitEdgeAt(std::int32_t e, std::uint32_t p, std::int32_t t3,
                                   std::int32_t t4) {
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t* adj = topo.adj.data();
  std::uint8_t* fixed = topo.fixed.data();
  const std::int32_t f = adj[e];
  const std::int32_t e1 = nextEdge(e), e2 = prevEdge(e), f1 = nextEdge(f), f2 = prevEdge(f);
  std::uint8_t fe = 0, fe1 = 0, fe2 = 0, ff1 = 0, ff2 = 0;
  if (kConstrained) {
    fe = fixed[e];
    fe1 = fixed[e1];
    fe2 = fixed[e2];
    ff1 = fixed[f1];
    ff2 = fixed[f2];
  }
  const std::int32_t A = e - e % 3, B = f - f % 3, C = 3 * t3, D = 3 * t4;
  fillFan<4>(p, {tri[e2], tri[e], tri[f2], tri[f]}, {adj[e2], adj[f1], adj[f2], adj[e1]},
             {A, B, D, C});
  if (kConstrained) {
    fixed[A] = fe2;
    fixed[B] = ff1;
    fixed[C] = fe1;
    fixed[D] = ff2;
    fixed[A + 1] = fixed[B + 2] = fixed[C + 2] = fixed[D + 1] = fe;
    fixed[A + 2] = fixed[B + 1] = fixed[C + 1] = fixed[D + 2] = 0;
  }
  legalizeAround<kConstrained>(p);
  return A / 3;
}

// Lawson flips around p: every edge on the stack is the first edge a->b of a triangle
// (a, b, p), and a flip with the triangle (b, a, d) beyond it gives (a, d, p) and (d, b, p),
// whose first edges face p again. So the edge's ends and p need no modulo arithmetic, and
// only the neighbour's corner d does.
template <bool kConstrained>
void Delaunay::legalizeAround(std::uint32_t p) {
  static constexpr std::int32_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
  std::uint32_t* tri = topo.tri.data();
  std::int32_t* adj = topo.adj.data();
  std::uint8_t* fixed = topo.fixed.data();
  const double* q = xy.data();
  const double px = q[2 * p], py = q[2 * p + 1];
  std::int32_t* stack = lawson_.data();
  std::size_t top = lawsonTop_;
  std::uint64_t flips = 0;
  while (top > 0) {
    const std::int32_t e = stack[--top];
    if (kConstrained && fixed[e]) continue;
    const std::int32_t f = adj[e];
    const std::int32_t s = f - static_cast<std::int32_t>(static_cast<std::uint32_t>(f) % 3);
    const std::int32_t fn = s + kNext[f - s], fp = s + kPrev[f - s];
    const std::uint32_t a = tri[e], b = tri[e + 1], d = tri[fp];
    bool flip;
    if (std::max(std::max(a, b), d) != kGhost) {
      const Sign side =
          incircle(q[2 * b], q[2 * b + 1], q[2 * a], q[2 * a + 1], q[2 * d], q[2 * d + 1], px, py);
      flip = side == Sign::Positive || (side == Sign::Zero && cocircular.flipToPd &&
                                        cocircular.flipToPd(cocircular.context, a, b, d, p));
    } else if (d == kGhost) {
      flip = false;  // a->b is a hull edge and p lies inside it
    } else {
      // (a, b, p) is a ghost triangle: flip when p lies beyond the real edge of the ghost
      // triangle (b, a, d), which then is no longer on the hull.
      flip = a == kGhost ? counterClockwise(q, d, b, p) : counterClockwise(q, a, d, p);
    }
    if (!flip) continue;
    const std::int32_t twinAD = adj[fn], twinDB = adj[fp], twinBP = adj[e + 1];
    tri[e + 1] = d;
    tri[s] = d;
    tri[s + 1] = b;
    tri[s + 2] = p;
    adj[e] = twinAD;
    adj[twinAD] = e;
    adj[e + 1] = s + 2;
    adj[s + 2] = e + 1;
    adj[s] = twinDB;
    adj[twinDB] = s;
    adj[s + 1] = twinBP;
    adj[twinBP] = s + 1;
    if (kConstrained) {
      const std::uint8_t fAD = fixed[fn], fDB = fixed[fp], fBP = fixed[e + 1];
      fixed[e] = fAD;
      fixed[e + 1] = 0;
      fixed[s] = fDB;
      fixed[s + 1] = fBP;
      fixed[s + 2] = 0;
    }
    ++flips;
    if (top + 2 > lawson_.size()) {
      lawson_.resize(2 * lawson_.size() + 64);
      stack = lawson_.data();
    }
    stack[top++] = e;
    stack[top++] = s;
  }
  lawsonTop_ = 0;
  stats.flips += flips;
}

bool Delaunay::isLocallyDelaunay(std::int32_t e) const {
  const std::int32_t f = topo.adj[e];
  const std::uint32_t x = topo.tri[e], y = topo.tri[nextEdge(e)];
  const std::uint32_t v = topo.tri[prevEdge(e)], d = topo.tri[prevEdge(f)];
  if (v == kGhost || d == kGhost || x == kGhost || y == kGhost) {
    if (v == kGhost) return true;  // both sides ghost-facing: the hull rule is checked from d
    // The neighbour (y, x, d) is a ghost triangle: v must not lie beyond its real edge.
    const std::int32_t r = d == kGhost ? f : (x == kGhost ? prevEdge(f) : nextEdge(f));
    return !counterClockwise(xy.data(), topo.tri[r], topo.tri[nextEdge(r)], v);
  }
  const double* p = xy.data();
  return incircle(p[2 * y], p[2 * y + 1], p[2 * x], p[2 * x + 1], p[2 * d], p[2 * d + 1], p[2 * v],
                  p[2 * v + 1]) != Sign::Positive;
}

void Delaunay::restoreDelaunay() {
  while (!stack_.empty()) {
    const std::int32_t e = stack_.back();
    stack_.pop_back();
    if (topo.fixed[e] || isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo.adj[e];
    topo.flip(e);
    ++stats.flips;
    stack_.push_back(e);
    stack_.push_back(nextEdge(e));
    stack_.push_back(f);
    stack_.push_back(nextEdge(f));
  }
}

}  // namespace geocdt
