// Removing a vertex: the border of its star is a polygon, which is cut into triangles again
// and made (constrained) Delaunay by Lawson flips. Only the new edges can be non-Delaunay:
// every triangle outside the star keeps an empty circumcircle when a vertex goes.
//
// The polygon is star-shaped from the removed vertex x, its vertices in strictly increasing
// angle around x. An ear (a, b, c) whose corner b is convex and whose new edge a -> c has x on
// its left (or on it) holds no other polygon vertex: the ear lies in the wedge from a to c
// seen from x, beyond a-c, where no other vertex lies. Cutting it leaves the rest star-shaped
// from x, and one such ear always exists (two ears that do not overlap cannot both hold x),
// so an ear is found by orientation tests alone, no test against the other vertices. Inside
// the hull the ears go in Devillers' order (earKey), which makes the flips afterwards rare.
//
// On the hull, the ghost is one of the ring's vertices and x lies outside what is left. The
// real vertices v1 .. vk of the ring are in angular order around x over at most half a turn:
// a Graham scan from v1 to vk pops each vertex that turns left, cutting it off as an ear (the
// same wedge argument), and what stays is the new hull from v1 to vk, closed by one ghost
// triangle per new hull edge.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "delaunay/delaunay.h"
#include "delaunay/vertex_edges.h"
#include "geocdt/predicates.h"

namespace geocdt {

class VertexRemoval {
 public:
  VertexRemoval(Delaunay& d, VertexEdges* hints)
      : d_(d), topo_(d.topo), ring_(d.ring_), hints_(hints), flags_(d.constrained()) {}

  Status run(std::uint32_t v, std::int32_t out, bool moving, bool freed);
  bool plan(std::int32_t out, std::vector<std::uint32_t>& corners);
  Status reinsert(std::uint32_t v, std::int32_t near);

 private:
  Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const double* p = d_.xy.data();
    return orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1]);
  }
  std::uint32_t at(std::int32_t node) const { return ring_.vertex[node]; }
  // Whether the ring's real vertices (all but node g) lie on one line.
  bool realRingCollinear(std::int32_t g) const;
  // False when an edge out of the vertex is constrained.
  bool gather(std::int32_t out);
  // Triangle (a, b, c) of nodes a, b = next[a], c = next[b] in the next free slot; b leaves
  // the polygon. Returns the slot.
  std::int32_t cut(std::int32_t a, std::int32_t b, std::int32_t c, std::uint32_t third);
  bool isStarEar(std::int32_t b, double x, double y) const;
  double earKey(std::int32_t b, double x, double y) const;
  bool cutInterior(double x, double y);
  bool isEarAnyway(std::int32_t b) const;  // the full test, for a polygon that finds no ear
  void cutHull(std::int32_t g);
  void freeSlots(std::size_t count);  // the star's `count` highest slots
  bool isSpare(std::int32_t t) const { return t == d_.spare_[0] || t == d_.spare_[1]; }
  // Lawson flips of the new edges, which stay inside the polygon: its border edges are
  // Delaunay already (each outer triangle's circumcircle is empty), so only edges between two
  // new triangles are tested, before and after each flip.
  void flipInside();
  bool isNew(std::int32_t t) const {
    for (std::size_t k = 0; k < ring_.used; ++k)
      if (ring_.slot[k] == t) return true;
    return false;
  }
  void collapse(std::uint32_t v, bool moving);
  void markRemoved(std::uint32_t v, bool moving);
  Status broken(std::uint32_t v, const char* what) {
    return {StatusCode::InternalError,
            "removing vertex " + std::to_string(v) + ": " + what + " (a broken triangulation)", v};
  }

  Delaunay& d_;
  Topology& topo_;
  StarRing& ring_;
  VertexEdges* hints_;
  // Whether edges may be constrained. Without, every flag is 0 and stays so: the flags are
  // neither read nor written, a cache miss less per triangle touched.
  bool flags_;
  void setFixed(std::int32_t e, std::uint8_t flag) {
    if (flags_) topo_.fixed[e] = flag;
  }
};

Status Delaunay::removeVertex(std::uint32_t v, std::int32_t out, bool moving, bool freed,
                              VertexEdges* hints) {
  return VertexRemoval(*this, hints).run(v, out, moving, freed);
}

bool Delaunay::plannedRemoval(std::uint32_t v, std::int32_t out,
                              std::vector<std::uint32_t>& corners) {
  if (!built_ || out < 0 || out >= 3 * topo.slotCount() || topo.tri[out] != v) return false;
  return VertexRemoval(*this, nullptr).plan(out, corners);
}

Status Delaunay::reinsertVertex(std::uint32_t v, std::int32_t near) {
  return VertexRemoval(*this, nullptr).reinsert(v, near);
}

void VertexRemoval::markRemoved(std::uint32_t v, bool moving) {
  d_.xy[2 * static_cast<std::size_t>(v)] = std::numeric_limits<double>::quiet_NaN();
  d_.xy[2 * static_cast<std::size_t>(v) + 1] = std::numeric_limits<double>::quiet_NaN();
  if (!moving) ++d_.stats.removed;
}

bool VertexRemoval::plan(std::int32_t out, std::vector<std::uint32_t>& corners) {
  corners.clear();
  if (!gather(out)) return false;
  for (const std::uint32_t r : ring_.vertex)
    if (r == kGhost) return false;
  const std::uint32_t v = topo_.tri[out];
  ring_.plan = &corners;
  const bool cut = cutInterior(d_.xy[2 * std::size_t{v}], d_.xy[2 * std::size_t{v} + 1]);
  ring_.plan = nullptr;
  return cut;
}

Status VertexRemoval::run(std::uint32_t v, std::int32_t out, bool moving, bool freed) {
  if (!d_.built_) {  // a vertex waiting for the triangulation to have triangles
    std::vector<std::uint32_t>& waiting = d_.pending_;
    const auto it = std::find(waiting.begin(), waiting.end(), v);
    if (it == waiting.end()) return broken(v, "not among the waiting vertices");
    waiting.erase(it);
    markRemoved(v, moving);
    return Status::success();
  }
  const double x = d_.xy[2 * static_cast<std::size_t>(v)];
  const double y = d_.xy[2 * static_cast<std::size_t>(v) + 1];
  if (out < 0 || out >= 3 * topo_.slotCount() || topo_.tri[out] != v) {
    const Hit h = d_.locate(x, y, true);
    if (h.kind != Hit::Kind::Vertex || topo_.tri[h.edge] != v) return broken(v, "not found");
    out = h.edge;
  }
  if (!gather(out)) return broken(v, "a constrained edge still ends there");
  const auto degree = static_cast<std::int32_t>(ring_.vertex.size());
  std::int32_t g = -1;
  for (std::int32_t i = 0; i < degree && g < 0; ++i)
    if (at(i) == kGhost) g = i;
  // With the ghost closing the hull, n vertices make 2n - 2 slots.
  const std::int32_t vertices = topo_.slotCount() / 2 + 1;
  if (g >= 0 && degree - 1 == vertices - 1 && realRingCollinear(g)) {
    collapse(v, moving);
    return Status::success();
  }
  if (g < 0 ? !cutInterior(x, y) : (cutHull(g), false))
    return broken(v, "no ear in the border of its star");
  if (ring_.used != ring_.slot.size() - 2) return broken(v, "the star was not filled");
  // The border's edges by their half-edges inside (in new triangles, which do not move).
  for (std::int32_t& e : ring_.border) e = topo_.adj[e];
  const std::int32_t kept = ring_.slot[0];
  ring_.made.assign(ring_.slot.begin(),
                    ring_.slot.begin() + static_cast<std::ptrdiff_t>(ring_.used));
  if (moving) {  // the insertion that follows takes them
    d_.spare_[0] = ring_.slot[ring_.slot.size() - 2];
    d_.spare_[1] = ring_.slot.back();
  } else {
    freeSlots(2);
  }
  if (freed) {  // what the freed edges hid may show across the border: flips may spread
    std::vector<std::int32_t>& stack = d_.flipStack();
    stack.insert(stack.end(), ring_.diagonals.begin(), ring_.diagonals.end());
    stack.insert(stack.end(), ring_.border.begin(), ring_.border.end());
    d_.restoreDelaunay();
  } else {
    flipInside();
  }
  // The grid's cells around here may name the freed slots, which now hold triangles from
  // elsewhere (or, spare, will at the moved vertex's new place): they name a new triangle.
  d_.grid_.cellAt(x, y) = kept;
  for (const std::uint32_t r : ring_.vertex)
    if (r != kGhost)
      d_.grid_.cellAt(d_.xy[2 * std::size_t{r}], d_.xy[2 * std::size_t{r} + 1]) = kept;
  d_.last_ = kept;
  d_.slotsReused_ = true;
  markRemoved(v, moving);
  return Status::success();
}

// The ring around v from half-edge out, counter-clockwise: each star triangle (v, r, s)
// gives its slot, r, and the half-edge beyond its far edge r -> s.
bool VertexRemoval::gather(std::int32_t out) {
  ring_.clear();
  std::int32_t e = out;
  do {
    if (flags_ && topo_.fixed[e]) return false;
    const std::int32_t far = nextEdge(e);
    ring_.vertex.push_back(topo_.tri[far]);
    ring_.slot.push_back(e / 3);
    ring_.carrier.push_back(topo_.adj[far]);
    ring_.border.push_back(topo_.adj[far]);  // (outside; turned inside once filled)
    ring_.fixed.push_back(flags_ ? topo_.fixed[far] : 0);
    e = topo_.adj[prevEdge(e)];
  } while (e != out);
  const auto n = static_cast<std::int32_t>(ring_.vertex.size());
  ring_.next.resize(n);
  ring_.prev.resize(n);
  for (std::int32_t i = 0; i < n; ++i) {
    ring_.next[i] = i + 1 < n ? i + 1 : 0;
    ring_.prev[i] = i > 0 ? i - 1 : n - 1;
  }
  // The new triangles go into the lowest slots; the two highest are freed, so that the
  // triangles that move into them are never new ones.
  std::sort(ring_.slot.begin(), ring_.slot.end());
  return true;
}

bool VertexRemoval::realRingCollinear(std::int32_t g) const {
  const auto n = static_cast<std::int32_t>(ring_.vertex.size());
  if (n <= 3) return true;
  const std::uint32_t a = at(ring_.next[g]), b = at(ring_.prev[g]);
  for (std::int32_t i = 0; i < n; ++i)
    if (i != g && orient(a, b, at(i)) != Sign::Zero) return false;
  return true;
}

std::int32_t VertexRemoval::cut(std::int32_t a, std::int32_t b, std::int32_t c,
                                std::uint32_t third) {
  const std::int32_t s = ring_.slot[ring_.used++];
  const std::int32_t e = 3 * s;
  if (ring_.plan) {  // only the corners, and the polygon without b
    ring_.plan->insert(ring_.plan->end(), {at(a), at(b), third});
    ring_.next[a] = c;
    ring_.prev[c] = a;
    return s;
  }
  topo_.setTriangle(s, at(a), at(b), third);
  topo_.link(e, ring_.carrier[a]);
  setFixed(e, ring_.fixed[a]);
  if (c >= 0) {
    topo_.link(e + 1, ring_.carrier[b]);
    setFixed(e + 1, ring_.fixed[b]);
    setFixed(e + 2, 0);
    // The polygon's new edge a -> c is twinned with this triangle's c -> a.
    ring_.carrier[a] = e + 2;
    ring_.fixed[a] = 0;
    ring_.next[a] = c;
    ring_.prev[c] = a;
    ring_.diagonals.push_back(e + 2);
  }
  return s;
}

// How well ear (prev[b], b, next[b]) suits a Delaunay triangulation of the hole, after
// Devillers: the power of x with respect to the ear's circumcircle (the in-circle determinant
// over the orientation, negated), in floating point. The ear with the largest power, x the
// least deep inside its circle, is Delaunay: cut in that order, the new edges need no flips
// but where rounding swapped two ears. A corner that is not convex in floating point gets
// -infinity.
// The exact test: corner b convex, x on the left of (or on) the new edge a -> c.
bool VertexRemoval::isStarEar(std::int32_t b, double x, double y) const {
  const double* p = d_.xy.data();
  const std::uint32_t va = at(ring_.prev[b]), vc = at(ring_.next[b]);
  return orient(va, at(b), vc) == Sign::Positive &&
         orient2d(p[2 * va], p[2 * va + 1], p[2 * vc], p[2 * vc + 1], x, y) != Sign::Negative;
}

double VertexRemoval::earKey(std::int32_t b, double x, double y) const {
  const double* p = d_.xy.data();
  const std::uint32_t va = at(ring_.prev[b]), vb = at(b), vc = at(ring_.next[b]);
  const double ax = p[2 * va] - x, ay = p[2 * va + 1] - y;
  const double bx = p[2 * vb] - x, by = p[2 * vb + 1] - y;
  const double cx = p[2 * vc] - x, cy = p[2 * vc + 1] - y;
  const double orientation = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  if (!(orientation > 0)) return -std::numeric_limits<double>::infinity();
  const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double inCircle =
      a2 * (bx * cy - by * cx) + b2 * (cx * ay - cy * ax) + c2 * (ax * by - ay * bx);
  return -inCircle / orientation;
}

// Ears by their keys, each checked exactly before it is cut (convex, x on the left of its new
// edge a -> c, so empty: see the top of the file); one that fails drops out until its
// neighbours change.
bool VertexRemoval::cutInterior(double x, double y) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  auto count = static_cast<std::int32_t>(ring_.vertex.size());
  std::vector<double>& key = ring_.key;
  key.resize(static_cast<std::size_t>(count));
  for (std::int32_t b = 0; b < count; ++b) key[b] = earKey(b, x, y);
  std::int32_t start = 0;
  while (count > 3) {
    std::int32_t best = start;
    for (std::int32_t b = ring_.next[start]; b != start; b = ring_.next[b])
      if (key[b] > key[best]) best = b;
    if (key[best] != kNone && !isStarEar(best, x, y)) {
      key[best] = kNone;
      continue;
    }
    if (key[best] == kNone) {  // none left by the keys (rounding): every corner exactly
      best = -1;
      std::int32_t b = start;
      do {
        if (isStarEar(b, x, y)) best = b;
        b = ring_.next[b];
      } while (best < 0 && b != start);
      do {  // the full test, as a safety net
        if (best < 0 && isEarAnyway(b)) best = b;
        b = ring_.next[b];
      } while (best < 0 && b != start);
      if (best < 0) return false;
    }
    const std::int32_t a = ring_.prev[best], c = ring_.next[best];
    cut(a, best, c, at(c));
    --count;
    key[a] = earKey(a, x, y);
    key[c] = earKey(c, x, y);
    start = a;
  }
  const std::int32_t a = start, b = ring_.next[a], c = ring_.next[b];
  if (ring_.plan) {
    ring_.plan->insert(ring_.plan->end(), {at(a), at(b), at(c)});
    return true;
  }
  const std::int32_t s = ring_.slot[ring_.used++];
  topo_.setTriangle(s, at(a), at(b), at(c));
  for (const std::int32_t node : {a, b, c}) {
    const std::int32_t e = 3 * s + (node == a ? 0 : node == b ? 1 : 2);
    topo_.link(e, ring_.carrier[node]);
    setFixed(e, ring_.fixed[node]);
  }
  return true;
}

// A convex corner b whose triangle holds no other polygon vertex, closed: never needed when
// the ring is a star's border, kept as a safety net.
bool VertexRemoval::isEarAnyway(std::int32_t b) const {
  const std::int32_t a = ring_.prev[b], c = ring_.next[b];
  const std::uint32_t va = at(a), vb = at(b), vc = at(c);
  if (orient(va, vb, vc) != Sign::Positive) return false;
  for (std::int32_t n = ring_.next[c]; n != a; n = ring_.next[n]) {
    const std::uint32_t w = at(n);
    if (orient(va, vb, w) != Sign::Negative && orient(vb, vc, w) != Sign::Negative &&
        orient(vc, va, w) != Sign::Negative)
      return false;
  }
  return true;
}

// A hull vertex: a Graham scan over the real vertices pops (cuts off) every left turn; the
// chain left is the new hull, each of its edges closed by a ghost triangle.
void VertexRemoval::cutHull(std::int32_t g) {
  const std::int32_t first = ring_.next[g];
  for (std::int32_t c = ring_.next[first]; c != g; c = ring_.next[c]) {
    while (ring_.prev[c] != first) {
      const std::int32_t b = ring_.prev[c], a = ring_.prev[b];
      if (orient(at(a), at(b), at(c)) != Sign::Positive) break;
      cut(a, b, c, at(c));
    }
  }
  std::int32_t before = -1;  // the slot of the ghost triangle made last
  std::int32_t h = first;
  for (; ring_.next[h] != g; h = ring_.next[h]) {
    const std::int32_t s = cut(h, ring_.next[h], -1, kGhost);
    setFixed(3 * s + 1, 0);
    setFixed(3 * s + 2, 0);
    if (before < 0) {
      topo_.link(3 * s + 2, ring_.carrier[g]);
      setFixed(3 * s + 2, ring_.fixed[g]);
    } else {
      topo_.link(3 * s + 2, 3 * before + 1);
    }
    before = s;
  }
  topo_.link(3 * before + 1, ring_.carrier[h]);
  setFixed(3 * before + 1, ring_.fixed[h]);
}

void VertexRemoval::flipInside() {
  std::vector<std::int32_t>& stack = ring_.diagonals;
  while (!stack.empty()) {
    const std::int32_t e = stack.back();
    stack.pop_back();
    // (A flip rewrites half-edges in place: an entry may now be a border edge.)
    const std::int32_t f = topo_.adj[e];
    if (!isNew(f / 3) || d_.isLocallyDelaunay(e)) continue;
    topo_.flip(e);
    ++d_.stats.flips;
    for (const std::int32_t g : {e, nextEdge(e), f, nextEdge(f)})  // the quad's sides
      if (isNew(topo_.adj[g] / 3)) stack.push_back(g);
  }
}

void VertexRemoval::freeSlots(std::size_t count) {
  const std::size_t n = ring_.slot.size();
  for (std::size_t k = n; k-- > n - count;) {
    const std::int32_t t = ring_.slot[k];
    const std::int32_t moved = topo_.dropSlot(t, flags_);
    if (moved == t) continue;
    ring_.moved.push_back({moved, t});
    // The cells where the moved triangle lies, and its corners' hints, follow it: a hint
    // past the last slot would cost a location.
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = topo_.tri[3 * t + c];
      if (v == kGhost) continue;
      d_.grid_.cellAt(d_.xy[2 * std::size_t{v}], d_.xy[2 * std::size_t{v} + 1]) = t;
      if (hints_) hints_->set(v, 3 * t + c);
    }
  }
}

// What is left is collinear: no triangles, the vertices wait again, and each constrained
// edge becomes a pending segment that carries what it carried.
void VertexRemoval::collapse(std::uint32_t v, bool moving) {
  std::vector<std::uint32_t>& waiting = d_.pending_;
  waiting.clear();
  for (const std::uint32_t r : ring_.vertex)
    if (r != kGhost) waiting.push_back(r);
  std::sort(waiting.begin(), waiting.end());
  topo_.clear();
  d_.built_ = false;
  d_.last_ = -1;
  d_.grid_ = PointGrid();
  d_.gridStale_ = false;
  ConstraintStore& store = d_.constraints;
  store.forEachEdge([&](std::uint32_t a, std::uint32_t b, const EdgeSource& src) {
    store.pending.push_back({a, b, src, src.polyline, 0});
  });
  store.clearEdges();
  markRemoved(v, moving);
}

Status VertexRemoval::reinsert(std::uint32_t v, std::int32_t near) {
  if (d_.built_) {
    // The grid's cells may name a spare slot, whose contents are stale: with spares, the walk
    // starts from near or else from the triangle the removal made last.
    const bool nearValid = near >= 0 && near < topo_.slotCount() && !isSpare(near);
    if (nearValid) d_.last_ = near;
    const bool fromGrid = !nearValid && d_.spare_[0] < 0;
    const Hit h = d_.locate(d_.xy[2 * std::size_t{v}], d_.xy[2 * std::size_t{v} + 1], fromGrid);
    const std::uint32_t r = d_.insertLocated(h, v);
    if (r == kGhost) return d_.error_;
    if (r != v) return broken(v, "moved onto another vertex");
    return Status::success();
  }
  // Waiting (all collinear so far): v joins the waiting vertices, which make the first
  // triangle as soon as they are not all on one line.
  std::vector<std::uint32_t>& waiting = d_.pending_;
  waiting.insert(std::upper_bound(waiting.begin(), waiting.end(), v), v);
  d_.batch_ = {d_.vertexCount(), nullptr, nullptr};  // no batch: nothing is a duplicate
  std::array<std::uint32_t, 3> built{kGhost, kGhost, kGhost};
  return d_.insertPending({}, built);
}

}  // namespace geocdt
