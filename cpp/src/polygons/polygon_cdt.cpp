#include "polygons/polygon_cdt.h"

#include <algorithm>
#include <limits>

#include "delaunay/first_triangle.h"
#include "delaunay/insertion_order.h"
#include "exact/orient_by_index.h"
#include "exact/small_integer_predicates.h"
#include "geocdt/predicates.h"
#include "labels/slot_windings.h"

namespace geocdt {

namespace {

constexpr std::int32_t kUnseen = std::numeric_limits<std::int32_t>::min();

// Polygons of this many points or more are inserted in the core's spatial order
// (bench/EXPERIMENTS.md, PG1).
constexpr std::uint32_t kSortFrom = 64;

}  // namespace

bool PolygonCdt::triangulate(const double* xy, std::uint32_t n, const std::uint32_t* ringStarts,
                             std::uint32_t ringCount, FillRule fill, std::uint32_t base,
                             std::vector<std::uint32_t>& out) {
  p_ = xy;
  n_ = n;
  ringStarts_ = ringStarts;
  ringCount_ = ringCount;
  if (!insertPoints()) return false;
  if (slots_ == 0) return true;  // fewer than three points off one line: nothing inside
  if (!insertSegments()) return false;
  countWindings(fill, base, out);
  return true;
}

bool PolygonCdt::insertPoints() {
  slots_ = 0;
  if (n_ < 3) return true;
  // Ring order keeps the walks and flips short on small rings; a long ring (a coastline)
  // inserted along itself grows a snake of thin triangles that later parts of the ring cut
  // through with many flips: there the core's spatial order (BRIO rounds in Hilbert order).
  integers_ = areSmallIntegers(p_, n_);
  const bool sorted = n_ >= kSortFrom;
  if (sorted) order_ = insertionOrder(p_, n_, InsertionOrder::Brio);
  const std::uint32_t* order = sorted ? order_.data() : nullptr;
  const auto at = [order](std::size_t i) {
    return order ? order[i] : static_cast<std::uint32_t>(i);
  };
  std::size_t i1 = 0, i2 = 0;
  if (!findFirstTriangle(p_, at, n_, i1, i2)) return true;
  // Every insertion adds two slots to the first four.
  const std::size_t most = 2 * static_cast<std::size_t>(n_);
  if (topo_.tri.size() < 3 * most) topo_.resizeSlots(most);
  vertexOf_.resize(n_);
  flips_ = 0;
  // Real rings flip 2 to 3 times a point in either order; 16 a point plus a margin means an
  // order gone quadratic, which the general engine's spatial sort and grid avoid.
  flipBudget_ = 16 * static_cast<std::uint64_t>(n_) + 64;

  std::uint32_t a = at(0), b = at(i1), c = at(i2);
  if (orientByIndex(p_, a, b, c) == Sign::Negative) std::swap(b, c);
  // The first triangle and its three ghosts, as Delaunay::build lays them out.
  topo_.setTriangle(0, a, b, c);
  topo_.setTriangle(1, b, a, kGhost);
  topo_.setTriangle(2, c, b, kGhost);
  topo_.setTriangle(3, a, c, kGhost);
  topo_.link(0, 3);
  topo_.link(1, 6);
  topo_.link(2, 9);
  topo_.link(4, 11);
  topo_.link(7, 5);
  topo_.link(10, 8);
  slots_ = 4;
  last_ = 0;
  vertexOf_[a] = a;
  vertexOf_[b] = b;
  vertexOf_[c] = c;
  for (std::size_t k = 1; k < n_; ++k) {
    if (k == i1 || k == i2) continue;
    if (!insertPoint(at(k))) return false;
  }
  return true;
}

bool PolygonCdt::insertPoint(std::uint32_t k) {
  int kind = 0;
  const std::int32_t e = integers_ ? locate<true>(p_[2 * k], p_[2 * k + 1], kind)
                                   : locate<false>(p_[2 * k], p_[2 * k + 1], kind);
  if (e < 0) return false;
  if (kind == 2) {
    vertexOf_[k] = topo_.tri[e];
    last_ = e / 3;
    return true;
  }
  vertexOf_[k] = k;
  if (kind == 1) {
    splitEdge(e, k);
  } else {
    splitFace(e / 3, k);
  }
  if (integers_) {
    legalize<true>(k);
  } else {
    legalize<false>(k);
  }
  return flips_ <= flipBudget_;
}

template <bool kIntegers>
std::int32_t PolygonCdt::locate(double x, double y, int& kind) const {
  const auto orient2d = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return kIntegers ? orient2dSmallIntegers(ax, ay, bx, by, cx, cy)
                     : geocdt::orient2d(ax, ay, bx, by, cx, cy);
  };
  const double* p = p_;
  const std::uint32_t* tri = topo_.tri.data();
  const std::int32_t* adj = topo_.adj.data();
  std::int32_t t = last_, entered = -1;
  for (std::int32_t step = 0; step < 64 + 2 * slots_; ++step) {
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
      kind = 2;
      if (z0 && z1) return e0 + 1;
      if (z1 && z2) return e0 + 2;
      if (z2 && z0) return e0;
      kind = 1;
      if (z0) return e0;
      if (z1) return e0 + 1;
      if (z2) return e0 + 2;
      kind = 0;
      return e0;
    }
    // A ghost triangle: only its real edge r = u -> w matters.
    const int g = a == kGhost ? 0 : (b == kGhost ? 1 : 2);
    const std::int32_t r = e0 + (g + 1) % 3;
    const std::uint32_t u = tri[r], w = tri[nextEdge(r)];
    const Sign o = r == entered ? Sign::Positive
                                : orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], x, y);
    if (o == Sign::Positive) {
      kind = 0;  // outside the hull, beyond r: the ghost triangle is split like a face
      return r;
    }
    if (o == Sign::Negative) {
      entered = adj[r];
      t = entered / 3;
      continue;
    }
    // On r's line: on r, at an end, or past one (then into the ghost triangle beside).
    const int axis = p[2 * u] != p[2 * w] ? 0 : 1;
    const double lo = p[2 * u + axis], hi = p[2 * w + axis], v = axis == 0 ? x : y;
    if (v == lo || v == hi) {
      kind = 2;
      return v == lo ? r : nextEdge(r);
    }
    const bool increasing = lo < hi;
    if (increasing ? v < lo : v > lo) {
      entered = adj[prevEdge(r)];
    } else if (increasing ? v > hi : v < hi) {
      entered = adj[nextEdge(r)];
    } else {
      kind = 1;
      return r;
    }
    t = entered / 3;
  }
  return -1;
}

void PolygonCdt::pushLawson(std::int32_t e) {
  if (lawsonTop_ == lawson_.size()) lawson_.resize(2 * lawson_.size() + 64);
  lawson_[lawsonTop_++] = e;
}

// Triangle t = (a, b, c) becomes (a, b, p); two new slots (b, c, p) and (c, a, p). As the
// core's splitFace: p ends third in each, so that the edge facing it comes first.
void PolygonCdt::splitFace(std::int32_t t, std::uint32_t p) {
  std::uint32_t* tri = topo_.tri.data();
  std::int32_t* adj = topo_.adj.data();
  const std::int32_t A = 3 * t, B = 3 * slots_, C = B + 3;
  slots_ += 2;
  const std::uint32_t ring[3] = {tri[A], tri[A + 1], tri[A + 2]};
  const std::int32_t outer[3] = {adj[A], adj[A + 1], adj[A + 2]};
  const std::int32_t slot[3] = {A, B, C};
  for (int i = 0; i < 3; ++i) {
    const std::int32_t s = slot[i], next = slot[i < 2 ? i + 1 : 0];
    tri[s] = ring[i];
    tri[s + 1] = ring[i < 2 ? i + 1 : 0];
    tri[s + 2] = p;
    adj[s] = outer[i];
    adj[outer[i]] = s;
    adj[s + 1] = next + 2;
    adj[next + 2] = s + 1;
    pushLawson(s);
  }
  last_ = t;
}

// e = a -> b in (a, b, c) and its twin in (b, a, d) become (c, a, p), (a, d, p), (d, b, p)
// and (b, c, p), as the core's splitEdgeAt.
void PolygonCdt::splitEdge(std::int32_t e, std::uint32_t p) {
  std::uint32_t* tri = topo_.tri.data();
  std::int32_t* adj = topo_.adj.data();
  const std::int32_t f = adj[e];
  const std::int32_t e1 = nextEdge(e), e2 = prevEdge(e), f1 = nextEdge(f), f2 = prevEdge(f);
  const std::int32_t A = e - e % 3, B = f - f % 3, C = 3 * slots_, D = C + 3;
  slots_ += 2;
  const std::uint32_t ring[4] = {tri[e2], tri[e], tri[f2], tri[f]};
  const std::int32_t outer[4] = {adj[e2], adj[f1], adj[f2], adj[e1]};
  const std::int32_t slot[4] = {A, B, D, C};
  for (int i = 0; i < 4; ++i) {
    const std::int32_t s = slot[i], next = slot[i < 3 ? i + 1 : 0];
    tri[s] = ring[i];
    tri[s + 1] = ring[i < 3 ? i + 1 : 0];
    tri[s + 2] = p;
    adj[s] = outer[i];
    adj[outer[i]] = s;
    adj[s + 1] = next + 2;
    adj[next + 2] = s + 1;
    pushLawson(s);
  }
  last_ = A / 3;
}

// Lawson flips around p, as the core's legalizeAround without constraints: each edge on the
// stack is the first edge a -> b of a triangle (a, b, p).
template <bool kIntegers>
void PolygonCdt::legalize(std::uint32_t p) {
  static constexpr std::int32_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
  std::uint32_t* tri = topo_.tri.data();
  std::int32_t* adj = topo_.adj.data();
  const double* q = p_;
  const double px = q[2 * p], py = q[2 * p + 1];
  std::int32_t* stack = lawson_.data();
  std::size_t top = lawsonTop_;
  std::uint64_t flips = 0;
  while (top > 0) {
    const std::int32_t e = stack[--top];
    const std::int32_t f = adj[e];
    const std::int32_t s = f - static_cast<std::int32_t>(static_cast<std::uint32_t>(f) % 3);
    const std::int32_t fp = s + kPrev[f - s];
    const std::uint32_t a = tri[e], b = tri[e + 1], d = tri[fp];
    bool flip;
    if (std::max(std::max(a, b), d) != kGhost) {
      // (Indices as size_t: no zero extension for each of the six loads.)
      const std::size_t ia = a, ib = b, id = d;
      const double bx = q[2 * ib], by = q[2 * ib + 1], ax = q[2 * ia], ay = q[2 * ia + 1];
      const double dx = q[2 * id], dy = q[2 * id + 1];
      flip = (kIntegers ? incircleSmallIntegers(bx, by, ax, ay, dx, dy, px, py)
                        : incircle(bx, by, ax, ay, dx, dy, px, py)) == Sign::Positive;
    } else if (d == kGhost) {
      flip = false;
    } else {
      flip = a == kGhost ? counterClockwise(q, d, b, p) : counterClockwise(q, a, d, p);
    }
    if (!flip) continue;
    const std::int32_t fn = s + kNext[f - s];  // (only now: fewer live registers above)
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
    ++flips;
    if (top + 2 > lawson_.size()) {
      lawson_.resize(2 * lawson_.size() + 64);
      stack = lawson_.data();
    }
    stack[top++] = e;
    stack[top++] = s;
  }
  lawsonTop_ = 0;
  flips_ += flips;
}

bool PolygonCdt::insertSegments() {
  const std::size_t halfEdges = 3 * static_cast<std::size_t>(slots_);
  std::fill(topo_.fixed.begin(), topo_.fixed.begin() + static_cast<std::ptrdiff_t>(halfEdges), 0);
  edgeOut_.resize(n_);
  const std::uint32_t* tri = topo_.tri.data();
  for (std::size_t e = 0; e < halfEdges; ++e)
    if (tri[e] != kGhost) edgeOut_[tri[e]] = static_cast<std::int32_t>(e);
  for (std::uint32_t r = 0; r < ringCount_; ++r) {
    const std::uint32_t first = ringStarts_[r], end = ringStarts_[r + 1];
    if (end - first < 2) continue;
    for (std::uint32_t k = first; k + 1 < end; ++k)
      if (!insertSegment(vertexOf_[k], vertexOf_[k + 1])) return false;
    // An open ring closes from its last point back to its first.
    if (!insertSegment(vertexOf_[end - 1], vertexOf_[first])) return false;
  }
  return true;
}

// A constrained half-edge's fixed byte holds 2w + 1 (as a signed byte) for w ring traversals
// along it, net of those against it; its twin holds -2w + 1. So the flood reads windings
// without a table, and the flips that move fixed bytes move them along.
bool PolygonCdt::traverse(std::int32_t e) {
  std::uint8_t* fixed = topo_.fixed.data();
  const int w = (static_cast<std::int8_t>(fixed[e]) - 1) / 2 + 1;
  if (w > 63) return false;  // a signed byte holds no more: the general engine counts them
  fixed[e] = static_cast<std::uint8_t>(static_cast<std::int8_t>(2 * w + 1));
  fixed[topo_.adj[e]] = static_cast<std::uint8_t>(static_cast<std::int8_t>(1 - 2 * w));
  return true;
}

bool PolygonCdt::insertSegment(std::uint32_t u, std::uint32_t v) {
  while (u != v) {
    const std::int32_t start = edgeOut_[u];
    std::int32_t e = topo_.edgeAround(start, v);
    std::uint32_t w = v;
    if (e < 0) {
      // A vertex exactly on the segment splits it: u -> w first, then w -> v.
      w = walkSegment(u, v, start, e);
      if (w == kGhost) return false;
    }
    if (e >= 0 ? !traverse(e) : !flipIn(u, w)) return false;
    u = w;
  }
  return true;
}

std::uint32_t PolygonCdt::walkSegment(std::uint32_t u, std::uint32_t v, std::int32_t start,
                                      std::int32_t& existing) {
  const double* p = p_;
  const std::uint32_t* tri = topo_.tri.data();
  const std::int32_t* adj = topo_.adj.data();
  const std::uint8_t* fixed = topo_.fixed.data();
  const double ux = p[2 * u], uy = p[2 * u + 1], vx = p[2 * v], vy = p[2 * v + 1];
  const auto side = [&](std::uint32_t x) {
    return orient2d(ux, uy, vx, vy, p[2 * x], p[2 * x + 1]);
  };
  const int axis = ux != vx ? 0 : 1;
  const bool increasing = axis == 0 ? ux < vx : uy < vy;
  const auto ahead = [&](std::uint32_t x) {  // x on u's line through v: on v's side of u?
    const double c = p[2 * x + axis], s = axis == 0 ? ux : uy;
    return increasing ? c > s : c < s;
  };
  crossed_.clear();
  std::int32_t e = start, h = -1;
  do {  // the triangle around u that the segment enters, or an edge along it
    const std::uint32_t x = tri[nextEdge(e)], y = tri[prevEdge(e)];
    if (x != kGhost) {
      const Sign sx = side(x);
      if (sx == Sign::Zero && ahead(x)) {
        existing = e;
        return x;
      }
      if (y != kGhost && sx == Sign::Negative && side(y) == Sign::Positive) {
        h = nextEdge(e);
        break;
      }
    }
    e = adj[prevEdge(e)];
  } while (e != start);
  if (h < 0) return kGhost;
  for (std::int32_t step = 0; step < slots_; ++step) {
    if (fixed[h]) return kGhost;  // another ring segment crosses this one
    crossed_.push_back(h);
    const std::int32_t f = adj[h];
    const std::uint32_t c = tri[prevEdge(f)];
    if (c == v) return v;
    if (c == kGhost) return kGhost;
    const Sign sc = side(c);
    if (sc == Sign::Zero) return c;  // a vertex on the segment: the walk ends there
    h = sc == Sign::Negative ? prevEdge(f) : nextEdge(f);
  }
  return kGhost;
}

void PolygonCdt::flip(std::int32_t e) {
  const std::int32_t f = topo_.adj[e];
  const std::uint32_t x = topo_.tri[e], y = topo_.tri[nextEdge(e)];
  topo_.flip(e);
  // x and y lose e and f (see Topology::flip); the apexes keep theirs.
  edgeOut_[x] = nextEdge(f);
  edgeOut_[y] = nextEdge(e);
  ++flips_;
}

// Sloan's flips, as the core's SegmentInserter::flipIn: a crossed edge in a convex quad is
// flipped, its new diagonal queued again while it still crosses u -> v; FIFO order ends it.
bool PolygonCdt::flipIn(std::uint32_t u, std::uint32_t v) {
  const double* p = p_;
  touched_.clear();
  queue_.clear();
  for (const std::int32_t h : crossed_) queue_.push_back({topo_.tri[h], topo_.tri[nextEdge(h)], h});
  const std::size_t bound = 1000 + 64 * queue_.size() * queue_.size();
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    if (head > bound) return false;
    const Queued q = queue_[head];
    std::int32_t h = q.hint;
    if (topo_.tri[h] != q.u || topo_.tri[nextEdge(h)] != q.v) h = findEdge(q.u, q.v);
    if (h < 0) return false;
    const std::int32_t f = topo_.adj[h];
    const std::uint32_t x = q.u, y = q.v, a = topo_.tri[prevEdge(h)], d = topo_.tri[prevEdge(f)];
    if (!counterClockwise(p, a, x, d) || !counterClockwise(p, d, y, a)) {
      queue_.push_back(q);
      continue;
    }
    flip(h);
    touched_.push_back(h / 3);
    touched_.push_back(f / 3);
    // The new diagonal a-d (now prevEdge(h)) crosses u -> v when a and d lie strictly apart.
    if (a != u && a != v && d != u && d != v) {
      const Sign sa = orientByIndex(p, u, v, a), sd = orientByIndex(p, u, v, d);
      if (sa != Sign::Zero && sd != Sign::Zero && sa != sd) queue_.push_back({a, d, prevEdge(h)});
    }
  }
  const std::int32_t e = findEdge(u, v);
  if (e < 0 || !traverse(e)) return false;
  stack_.clear();
  for (const std::int32_t t : touched_)
    for (int k = 0; k < 3; ++k) stack_.push_back(3 * t + k);
  return restoreDelaunay();
}

bool PolygonCdt::isLocallyDelaunay(std::int32_t e) const {
  const std::uint32_t* tri = topo_.tri.data();
  const std::int32_t f = topo_.adj[e];
  const std::uint32_t x = tri[e], y = tri[nextEdge(e)];
  const std::uint32_t v = tri[prevEdge(e)], d = tri[prevEdge(f)];
  if (v == kGhost || d == kGhost || x == kGhost || y == kGhost) {
    if (v == kGhost) return true;
    const std::int32_t r = d == kGhost ? f : (x == kGhost ? prevEdge(f) : nextEdge(f));
    return !counterClockwise(p_, tri[r], tri[nextEdge(r)], v);
  }
  const double* p = p_;
  return incircle(p[2 * y], p[2 * y + 1], p[2 * x], p[2 * x + 1], p[2 * d], p[2 * d + 1], p[2 * v],
                  p[2 * v + 1]) != Sign::Positive;
}

bool PolygonCdt::restoreDelaunay() {
  while (!stack_.empty()) {
    const std::int32_t e = stack_.back();
    stack_.pop_back();
    if (topo_.fixed[e] || isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo_.adj[e];
    flip(e);
    if (flips_ > flipBudget_) return false;
    stack_.push_back(e);
    stack_.push_back(nextEdge(e));
    stack_.push_back(f);
    stack_.push_back(nextEdge(f));
  }
  return true;
}

// The windings of every slot, from the ghost triangles (0) across edges, each constrained
// edge adding the ring traversals its fixed byte holds; the inside triangles go out as the
// flood meets them. The ghost triangles ring the hull, joined by unconstrained edges: a flood
// from one of them reaches the others at winding 0.
void PolygonCdt::countWindings(FillRule fill, std::uint32_t base, std::vector<std::uint32_t>& out) {
  const std::uint32_t* tri = topo_.tri.data();
  const std::int32_t* adj = topo_.adj.data();
  const std::uint8_t* fixed = topo_.fixed.data();
  winding_.assign(static_cast<std::size_t>(slots_), kUnseen);
  if (flood_.size() < static_cast<std::size_t>(slots_)) flood_.resize(slots_);
  std::int32_t* winding = winding_.data();
  std::int32_t* queue = flood_.data();  // each slot enters once: no bound to check
  std::int32_t ghost = 0;
  while (!topo_.isGhost(ghost)) ++ghost;
  winding[ghost] = 0;
  queue[0] = ghost;
  std::int32_t tail = 1;
  for (std::int32_t head = 0; head < tail; ++head) {
    const std::int32_t t = queue[head];
    const std::int32_t w = winding[t];
    if (w != 0 && insideByRule(w, fill) && !topo_.isGhost(t)) {
      out.push_back(base + tri[3 * t]);
      out.push_back(base + tri[3 * t + 1]);
      out.push_back(base + tri[3 * t + 2]);
    }
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = 3 * t + k, next = adj[e] / 3;
      if (winding[next] != kUnseen) continue;
      winding[next] = w - (static_cast<std::int8_t>(fixed[e]) - 1) / 2;
      queue[tail++] = next;
    }
  }
}

}  // namespace geocdt
