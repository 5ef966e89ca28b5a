#include "refine/refinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "exact/power_of_two.h"
#include "geocdt/predicates.h"
#include "labels/slot_windings.h"
#include "mesh/star_boundary.h"
#include "refine/refiner.h"

namespace geocdt {

namespace refinement {

double projection(double ax, double ay, double bx, double by, double px, double py) {
  const double scale = powerOfTwo(-scaleExponent({bx - ax, by - ay, px - ax, py - ay}));
  const double ex = (bx - ax) * scale, ey = (by - ay) * scale;
  const double qx = (px - ax) * scale, qy = (py - ay) * scale;
  return std::clamp((qx * ex + qy * ey) / (ex * ex + ey * ey), 0.0, 1.0);
}

inline Shape Refiner::shape(std::int32_t t) const {
  const std::uint32_t* corner = &topo_.tri[3 * t];
  const double* xy = d_.xy.data();
  const double* a = xy + 2 * corner[0];
  const double* b = xy + 2 * corner[1];
  const double* c = xy + 2 * corner[2];
  double abx = b[0] - a[0], aby = b[1] - a[1], acx = c[0] - a[0], acy = c[1] - a[1];
  double cross = abx * acy - aby * acx;
  Shape s;
  // The area from the differences as they are: coordinates within 1e150 keep the products
  // finite, where the scaled frame below flushes the smaller side to zero when the sides'
  // sizes differ by hundreds of orders of magnitude (fuzz: a subnormal across from 1e58).
  s.area = 0.5 * std::fabs(cross);
  // The angle in a frame scaled by a power of two (exactly) to the triangle's size, so that
  // squares and their products neither overflow nor underflow at any coordinate magnitude;
  // sizes from 2^-200 to 2^200 need no scaling (products of squares stay finite).
  const double size =
      std::max(std::max(std::fabs(abx), std::fabs(aby)), std::max(std::fabs(acx), std::fabs(acy)));
  s.scale = 0;
  if (!(size >= 0x1p-200 && size <= 0x1p200)) {
    s.scale = scaleExponent({abx, aby, acx, acy});
    const double scale = powerOfTwo(-s.scale);
    abx *= scale, aby *= scale, acx *= scale, acy *= scale;
    cross = abx * acy - aby * acx;
  }
  const double bcx = acx - abx, bcy = acy - aby;
  const double lab = abx * abx + aby * aby, lac = acx * acx + acy * acy;
  const double lbc = bcx * bcx + bcy * bcy;
  // The smallest angle faces the shortest edge; its sin is twice the area over the product of
  // the two longer edges, whose squares' product is the largest of the three pairs'.
  s.cross2 = cross * cross;
  s.product = std::max(std::max(lab * lac, lab * lbc), lac * lbc);
  s.shortest2 = std::min(std::min(lab, lac), lbc);
  return s;
}

void Refiner::checkTriangle(std::int32_t t) {
  if (!inRegion(t)) return;
  const Shape s = shape(t);
  const bool skinny = s.skinny(sin2_);
  if (!skinny && !(s.area > maxArea_)) return;
  const std::uint32_t a = topo_.tri[3 * t], b = topo_.tri[3 * t + 1], c = topo_.tri[3 * t + 2];
  const bool boundary = onSubsegment(a) || onSubsegment(b) || onSubsegment(c);
  bad_.push(BadQueue::bucket(boundary, skinny, skinny ? s.sin2() : 0, s.lengthExponent()),
            {t, a, b, c, skinny});
}

std::int32_t Refiner::findEdge(std::uint32_t u, std::uint32_t v) const {
  return topo_.edgeAround(vertexEdge_[u], v);
}

void Refiner::rebuild() {
  winding_ = slotWindings(d_);
  vertexEdge_.assign(d_.vertexCount(), -1);
  onSubsegment_.assign(d_.vertexCount(), 0);
  // One pass: a half-edge out of each vertex (the last one), and the ends of subsegments
  // (the flag first, the corners of the triangle only for the few that have it).
  const std::uint32_t* tri = topo_.tri.data();
  forChunks(0, topo_.tri.size(), [&](std::size_t begin, std::size_t end) {
    for (auto e = static_cast<std::int32_t>(begin); e < static_cast<std::int32_t>(end); ++e) {
      const std::uint32_t v = tri[e];
      if (v == kGhost) continue;  // (then a ghost triangle's edge, on no subsegment)
      vertexEdge_[v] = e;
      if (isSubsegment(e) && !topo_.isGhost(e / 3)) onSubsegment_[v] = 1;
    }
  });
}

// After a vertex was inserted: the triangles around it take their windings from the caller,
// or else from the unchanged triangles beyond them (every triangle the insertion changed has
// it as a corner), tell their corners where they are, and are checked. `from` is a half-edge
// out of it.
void Refiner::afterInsert(std::int32_t from, std::int32_t winding) {
  // Grown by half again when short, not by each insertion's two slots and one vertex: in
  // wasm every resize is a call. Entries past the slots and vertices are not read; run()
  // trims the windings to the slots at its end.
  const auto slots = static_cast<std::size_t>(topo_.slotCount());
  const std::size_t vertices = d_.vertexCount();
  if (winding_.size() < slots) winding_.resize(slots + slots / 2);
  if (vertexEdge_.size() < vertices) vertexEdge_.resize(vertices + vertices / 2, -1);
  if (winding != kUnknownWinding) {
    // Joined to a cavity's border: every triangle takes the cavity's winding; the spokes are
    // new and unconstrained, none on the hull (no ghost was in the cavity), so only the
    // border edges can be subsegments. Nothing here changes the topology: one turn round the
    // vertex does it all, each triangle checked once its winding and corners are set.
    const std::uint32_t* tri = topo_.tri.data();
    const std::int32_t* adj = topo_.adj.data();
    std::int32_t* vertexEdge = vertexEdge_.data();
    vertexEdge[tri[from]] = from;
    std::int32_t h = from;
    do {
      const auto t = static_cast<std::int32_t>(static_cast<std::uint32_t>(h) / 3);
      const std::int32_t k = h - 3 * t, outer = k == 2 ? h - 2 : h + 1;
      winding_[t] = winding;
      if (tri[outer] != kGhost) vertexEdge[tri[outer]] = outer;
      checkTriangle(t);
      if (isSubsegment(outer)) queueIfEncroached(outer);
      h = adj[k == 0 ? h + 2 : h - 1];
    } while (h != from);
    return;
  }
  around_.clear();
  std::int32_t e = from;
  do {
    around_.push_back(e);
    e = topo_.adj[prevEdge(e)];
  } while (e != from);
  // The triangles take their windings from the unchanged triangles beyond them.
  for (const std::int32_t h : around_) {
    const std::int32_t t = h / 3, outer = nextEdge(h);
    if (topo_.isGhost(t)) {
      winding_[t] = 0;
    } else {
      const std::int32_t g = topo_.adj[outer];
      winding_[t] = winding_[g / 3];
      if (topo_.fixed[outer])
        winding_[t] += d_.constraints.windingAcross(topo_.tri[g], topo_.tri[nextEdge(g)]);
    }
    // Every slot the insertion rewrote is one of these, and every vertex that pointed into
    // one is a corner of them: v, or the start of an outer edge.
    if (topo_.tri[outer] != kGhost) vertexEdge_[topo_.tri[outer]] = outer;
  }
  vertexEdge_[topo_.tri[from]] = from;
  for (const std::int32_t h : around_) checkAround(h / 3);
}

void Refiner::noteCorners(std::int32_t t) {
  for (std::int32_t k = 3 * t; k < 3 * t + 3; ++k)
    if (topo_.tri[k] != kGhost) vertexEdge_[topo_.tri[k]] = k;
}

void Refiner::checkAround(std::int32_t t) {
  checkTriangle(t);
  if (topo_.isGhost(t)) return;
  for (std::int32_t k = 3 * t; k < 3 * t + 3; ++k)
    if (isSubsegment(k)) queueIfEncroached(k);
}

// Flips the edges on the stack until each is locally Delaunay, as Delaunay::restoreDelaunay
// does, keeping windings (a flipped edge is unconstrained: both its triangles wind alike),
// corners and checks up to date.
void Refiner::restoreDelaunay(std::vector<std::int32_t>& stack) {
  while (!stack.empty()) {
    const std::int32_t e = stack.back();
    stack.pop_back();
    if (topo_.fixed[e] || d_.isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo_.adj[e];
    topo_.flip(e);
    ++d_.stats.flips;
    winding_[f / 3] = winding_[e / 3];
    for (const std::int32_t t : {e / 3, f / 3}) {
      noteCorners(t);
      checkAround(t);
    }
    stack.push_back(e);
    stack.push_back(nextEdge(e));
    stack.push_back(f);
    stack.push_back(nextEdge(f));
  }
}

// The barycentric weights of (cx, cy) in the triangle of corners `parent`; in a sliver, where
// they miss the point, an edge's ends and weights instead (parent[2] then kNoVertex).
void Refiner::weightsInFace(std::uint32_t (&parent)[3], double (&weight)[3], double cx,
                            double cy) const {
  const double ox = x(parent[0]), oy = y(parent[0]);
  const int e = scaleExponent({x(parent[1]) - ox, y(parent[1]) - oy, x(parent[2]) - ox,
                               y(parent[2]) - oy, cx - ox, cy - oy});
  const double scale = powerOfTwo(-e);
  const auto area2 = [&](std::uint32_t a, std::uint32_t b) {
    const double ax = (x(a) - ox) * scale, ay = (y(a) - oy) * scale;
    const double bx = (x(b) - ox) * scale, by = (y(b) - oy) * scale;
    const double qx = (cx - ox) * scale, qy = (cy - oy) * scale;
    return (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
  };
  const double w0 = area2(parent[1], parent[2]), w1 = area2(parent[2], parent[0]);
  const double w2 = area2(parent[0], parent[1]), sum = w0 + w1 + w2;
  weight[0] = w0 / sum;
  weight[1] = w1 / sum;
  weight[2] = w2 / sum;
  // In a sliver the areas cancel: where they miss the point, it lies next to one of the
  // edges (numerically on it), and the edge's ends with its projection place it better.
  double spread = 0;
  const double wx = weight[0] * x(parent[0]) + weight[1] * x(parent[1]) + weight[2] * x(parent[2]);
  const double wy = weight[0] * y(parent[0]) + weight[1] * y(parent[1]) + weight[2] * y(parent[2]);
  const double missed = std::max(std::fabs(wx - cx), std::fabs(wy - cy));
  for (int k = 0; k < 3; ++k)
    spread = std::max({spread, std::fabs(x(parent[k]) - cx), std::fabs(y(parent[k]) - cy)});
  if (!(missed <= 1e-12 * spread)) {
    double best = INFINITY;
    const std::uint32_t corners[3] = {parent[0], parent[1], parent[2]};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = corners[k], b = corners[(k + 1) % 3];
      const double w = projection(x(a), y(a), x(b), y(b), cx, cy);
      const double dx = (1 - w) * x(a) + w * x(b) - cx, dy = (1 - w) * y(a) + w * y(b) - cy;
      const double d = std::max(std::fabs(dx), std::fabs(dy));
      if (d < best) {
        best = d;
        parent[0] = a, parent[1] = b, parent[2] = kNoVertex;
        weight[0] = 1 - w, weight[1] = w, weight[2] = 0;
      }
    }
  }
}

// Where a bad triangle is split: the circumcentre, or Ungor's off-centre when the triangle is
// skinny and the off-centre is nearer to its shortest edge p q. Both lie on that edge's
// bisector:
//
//              r
//             / \        c  circumcentre
//            /   \       o  off-centre, where p q subtends minAngle (a little nearer)
//           /  c  \      m  the middle of p q
//          /   o   \     (o replaces c when it is nearer to m)
//         p----m----q
//
// False when the triangle is left as it is: skinny between two subsegments at a small input
// angle, or a candidate out of range.
inline bool Refiner::candidate(const BadTriangle& bad, double& cx, double& cy) const {
  const bool skinny = bad.skinny;
  // The shortest edge p -> q, the third corner r on its left.
  std::uint32_t corner[3] = {bad.a, bad.b, bad.c};
  int k0 = 0;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t a = corner[k], b = corner[(k + 1) % 3];
    const double l = (x(b) - x(a)) * (x(b) - x(a)) + (y(b) - y(a)) * (y(b) - y(a));
    if (l < best) best = l, k0 = k;
  }
  const std::uint32_t p = corner[k0], q = corner[(k0 + 1) % 3], r = corner[(k0 + 2) % 3];
  // Most triangles have an end of their shortest edge on no subsegment. One too large (and
  // not skinny) is split wherever it lies: an input angle is no reason to leave it.
  if (skinny && onSubsegment(p) && onSubsegment(q) && smallInputAngle(p, q)) return false;
  const double qx = x(q) - x(p), qy = y(q) - y(p), rx = x(r) - x(p), ry = y(r) - y(p);
  const double twice = 2 * (qx * ry - qy * rx);
  const double q2 = qx * qx + qy * qy, r2 = rx * rx + ry * ry;
  cx = (ry * q2 - qy * r2) / twice, cy = (qx * r2 - rx * q2) / twice;  // from p
  if (skinny && offCentre_ > 0) {
    const double mx = 0.5 * qx, my = 0.5 * qy;
    const double ox = mx - offCentre_ * qy, oy = my + offCentre_ * qx;
    if ((ox - mx) * (ox - mx) + (oy - my) * (oy - my) <
        (cx - mx) * (cx - mx) + (cy - my) * (cy - my)) {
      cx = ox;
      cy = oy;
    }
  }
  cx += x(p);
  cy += y(p);
  return std::isfinite(cx) && std::isfinite(cy);
}

// Walks from slot cur towards the candidate; a subsegment in the way is split if the candidate
// encroaches it (the triangle is then tried again), else the triangle is left. Nothing when
// the walk arrives: cur then holds the candidate, on one of its edges if onEdge.
inline std::optional<Outcome> Refiner::walkToCandidate(double cx, double cy, std::int32_t& cur,
                                                       bool& onEdge) {
  // Each step starts one edge further round (step % 3), so that the walk cannot cycle.
  for (int step = 0, first = 0;; ++step, first = first == 2 ? 0 : first + 1) {
    if (step > 100000) return Outcome::Skipped;
    std::int32_t exit = -1;
    onEdge = false;
    const std::uint32_t* corners = &topo_.tri[3 * cur];
    const double* xy = d_.xy.data();
    for (int i = 0, k = first; i < 3 && exit < 0; ++i) {
      const int next = k == 2 ? 0 : k + 1;
      const double* a = xy + 2 * corners[k];
      const double* b = xy + 2 * corners[next];
      const Sign side = orient2d(a[0], a[1], b[0], b[1], cx, cy);
      if (side == Sign::Negative) exit = 3 * cur + k;
      onEdge |= side == Sign::Zero;
      k = next;
    }
    if (exit < 0) return std::nullopt;
    if (isSubsegment(exit)) {
      const std::uint32_t a = topo_.tri[exit], b = topo_.tri[nextEdge(exit)];
      if (!encroachedBy(x(a), y(a), x(b), y(b), cx, cy)) return Outcome::Skipped;
      const std::size_t before = subsegments_.size();
      queueSubsegment(exit, true);
      return subsegments_.size() > before ? Outcome::Retry : Outcome::Skipped;
    }
    cur = topo_.adj[exit] / 3;
    if (topo_.isGhost(cur)) return Outcome::Skipped;
  }
}

// The cavity (into cavity_, its border's edges into boundary_ for the insertion): the
// triangles whose circumcircles hold the candidate, reached from cur without crossing
// subsegments. A subsegment on its border that the candidate encroaches is queued to be split
// instead; true when one was. Whether a slot is in the cavity is looked up in the list while
// that is short (a few triangles, in the cache), in stamps beyond.
inline bool Refiner::findCavity(std::int32_t cur, double cx, double cy) {
  cavity_.assign(1, cur);
  boundary_.clear();
  bool stamping = false;
  // A bit per slot number modulo 64 for the list: most neighbours looked up are not in it,
  // and their bit, clear, says so without the search.
  const auto bit = [](std::int32_t n) { return std::uint64_t{1} << (n & 63); };
  std::uint64_t listed = bit(cur);
  const auto inCavity = [&](std::int32_t n) {
    if (stamping) return stamp_[n] == epoch_;
    return (listed & bit(n)) != 0 && std::find(cavity_.begin(), cavity_.end(), n) != cavity_.end();
  };
  // The arrays read here do not change during the search: read through local pointers, not
  // reloaded after every store to the lists.
  const std::uint32_t* tri = topo_.tri.data();
  const std::int32_t* adj = topo_.adj.data();
  const std::uint8_t* fixed = topo_.fixed.data();
  const double* xy = d_.xy.data();
  const bool keepAll = keepAll_;
  const std::size_t before = subsegments_.size();
  for (std::size_t i = 0; i < cavity_.size(); ++i) {
    const std::int32_t slot = 3 * cavity_[i];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = slot + k;
      if (fixed[e] || (keepAll && isSubsegment(e))) {
        const double* a = xy + 2 * tri[e];
        const double* b = xy + 2 * tri[k == 2 ? slot : e + 1];
        if (encroachedBy(a[0], a[1], b[0], b[1], cx, cy)) queueSubsegment(e, true);
        boundary_.push_back(e);
        continue;
      }
      const auto n = static_cast<std::int32_t>(static_cast<std::uint32_t>(adj[e]) / 3);
      if (inCavity(n)) continue;
      const std::uint32_t u = tri[3 * n], v = tri[3 * n + 1], w = tri[3 * n + 2];
      if (u == kGhost || v == kGhost || w == kGhost ||
          incircle(xy[2 * u], xy[2 * u + 1], xy[2 * v], xy[2 * v + 1], xy[2 * w], xy[2 * w + 1], cx,
                   cy) != Sign::Positive) {
        boundary_.push_back(e);
        continue;
      }
      cavity_.push_back(n);
      listed |= bit(n);
      if (stamping) {
        stamp_[n] = epoch_;
      } else if (cavity_.size() > kShortCavity) {
        stamping = true;
        ++epoch_;
        stamp_.resize(topo_.slotCount(), 0);
        for (const std::int32_t c : cavity_) stamp_[c] = epoch_;
      }
    }
  }
  return subsegments_.size() > before;
}

// The candidate as a new vertex, its cavity found from slot cur. Strictly inside cur, the
// cavity's border joined to the point is its insertion; on an edge, or where the border does
// not make a star, the point is located and inserted with flips (which repeat the cavity's
// in-circle tests).
inline Outcome Refiner::insertCandidate(std::int32_t cur, bool onEdge, double cx, double cy) {
  if (capReached()) {
    capped_ = true;
    return Outcome::Done;
  }
  const std::uint32_t v = newVertex(cx, cy);
  if (onEdge || !orderStarBoundary(topo_, d_.xy, cavity_.size(), cx, cy, boundary_))
    return insertWithFlips(cur, v, cx, cy);
  std::uint32_t parent[3] = {topo_.tri[3 * cur], topo_.tri[3 * cur + 1], topo_.tri[3 * cur + 2]};
  double weight[3];
  weightsInFace(parent, weight, cx, cy);
  // The cavity is one region, joined across unconstrained edges: one winding for it all.
  const std::int32_t winding = winding_[cur];
  const std::int32_t from = d_.fillStar(v, cavity_, boundary_);
  record(v, parent[0], parent[1], parent[2], weight[0], weight[1], weight[2]);
  afterInsert(from, winding);
  return Outcome::Done;
}

// Vertex v at (cx, cy), located from slot cur and inserted by the Delaunay kernel.
Outcome Refiner::insertWithFlips(std::int32_t cur, std::uint32_t v, double cx, double cy) {
  d_.setLastTriangle(cur);
  const Hit h = d_.locate(cx, cy, false);
  if (h.kind != Hit::Kind::Face && h.kind != Hit::Kind::Edge) {
    d_.xy.resize(d_.xy.size() - 2);
    return h.kind == Hit::Kind::Failed ? Outcome::Failed : Outcome::Skipped;
  }
  // Where the point falls, for interpolation: its triangle's corners or its edge's ends.
  const std::int32_t f = h.edge - h.edge % 3;
  std::uint32_t parent[3] = {topo_.tri[f], topo_.tri[f + 1], topo_.tri[f + 2]};
  double weight[3] = {0, 0, 0};
  if (h.kind == Hit::Kind::Face) {
    weightsInFace(parent, weight, cx, cy);
  } else {
    parent[0] = topo_.tri[h.edge];
    parent[1] = topo_.tri[nextEdge(h.edge)];
    parent[2] = kNoVertex;
    const double w = projection(x(parent[0]), y(parent[0]), x(parent[1]), y(parent[1]), cx, cy);
    weight[0] = 1 - w;
    weight[1] = w;
  }
  if (h.kind == Hit::Kind::Edge && isSubsegment(h.edge)) markOnSubsegment(v);
  if (d_.insertLocated(h, v) != v) {
    d_.xy.resize(d_.xy.size() - 2);
    return Outcome::Failed;
  }
  record(v, parent[0], parent[1], parent[2], weight[0], weight[1], weight[2]);
  const std::int32_t last = d_.lastTriangle();
  std::int32_t from = 3 * last;
  while (topo_.tri[from] != v) ++from;
  afterInsert(from);
  return Outcome::Done;
}

Outcome Refiner::splitTriangle(const BadTriangle& bad) {
  double cx = 0, cy = 0;
  if (!candidate(bad, cx, cy)) return Outcome::Skipped;
  std::int32_t cur = bad.slot;
  bool onEdge = false;
  if (const std::optional<Outcome> stopped = walkToCandidate(cx, cy, cur, onEdge)) return *stopped;
  if (findCavity(cur, cx, cy)) return Outcome::Retry;
  return insertCandidate(cur, onEdge, cx, cy);
}

Refiner::Step Refiner::refineStep(std::vector<BadTriangle>& retry,
                                  std::vector<BadTriangle>& unresolved) {
  if (capped_) return Step::Stop;
  if (!subsegments_.empty()) {
    const Subsegment s = subsegments_.back();
    subsegments_.pop_back();
    const std::int32_t e = findEdge(s.u, s.v);
    if (e < 0) return Step::Go;
    return splitSubsegment(e, s.forced) == Outcome::Failed ? Step::Stop : Step::Go;
  }
  for (const BadTriangle& b : retry) checkTriangle(b.slot);
  retry.clear();
  if (bad_.empty()) return Step::Stop;
  const BadTriangle b = bad_.pop();
  if (!holds(b)) return Step::Go;
  const Outcome o = splitTriangle(b);
  if (o == Outcome::Failed) return Step::Failed;
  if (o == Outcome::Retry) {
    retry.push_back(b);
  } else if (holds(b)) {
    unresolved.push_back(b);  // skipped, or the cap stopped it
  }
  return Step::Go;
}

Refiner::Step Refiner::refineSteps(std::vector<BadTriangle>& retry,
                                   std::vector<BadTriangle>& unresolved) {
  for (std::size_t i = 0; i < kChunk; ++i) {
    const Step step = refineStep(retry, unresolved);
    if (step != Step::Go) return step;
  }
  return Step::Go;
}

Status Refiner::run() {
  if (!d_.built()) return Status::success();
  // Steiner vertices take ids past the constraint store's id-ordered slots (EdgeSlot).
  d_.constraints.scatter();
  rebuild();
  steinerFlag_.assign(d_.vertexCount(), 0);
  for (const SteinerVertex& s : d_.steiner) steinerFlag_[s.vertex] = 1;
  if (cap_ == 0) {
    cap_ = std::numeric_limits<std::uint64_t>::max();
    if (minAngle_ > kProvenAngle) {
      double domainArea = 0;
      for (std::int32_t t = 0; std::isfinite(maxArea_) && t < topo_.slotCount(); ++t) {
        if (!inRegion(t)) continue;
        domainArea += shape(t).area;
      }
      const double byArea = std::isfinite(maxArea_) ? 4 * domainArea / maxArea_ : 0;
      cap_ = 64 * static_cast<std::uint64_t>(d_.vertexCount()) + 1024 +
             static_cast<std::uint64_t>(std::min(byArea, 1e18));
    }
  }
  for (std::int32_t e = 0; keepAll_ && e < static_cast<std::int32_t>(topo_.tri.size()); ++e) {
    if (topo_.isGhost(e / 3) || !topo_.isGhost(topo_.adj[e] / 3) || topo_.fixed[e]) continue;
    const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
    hullOf_[ConstraintStore::key(a, b)] = static_cast<std::uint32_t>(hull_.size());
    hull_.push_back({x(a), y(a), x(b), y(b)});
  }
  // The scan and the loop's steps in chunks (chunks.h): run() is called once, and with both
  // inlined a first call ran it in baseline code throughout (bench/EXPERIMENTS.md, F21).
  forChunks(
      0, static_cast<std::size_t>(topo_.slotCount()), [&](std::size_t begin, std::size_t end) {
        for (auto t = static_cast<std::int32_t>(begin); t < static_cast<std::int32_t>(end); ++t) {
          checkTriangle(t);
          if (topo_.isGhost(t)) continue;
          for (int k = 0; k < 3; ++k) {
            const std::int32_t e = 3 * t + k, twin = topo_.adj[e];
            if (isSubsegment(e) && (topo_.isGhost(twin / 3) || e < twin)) queueIfEncroached(e);
          }
        }
      });
  std::vector<BadTriangle> retry;
  std::vector<BadTriangle> unresolved;  // taken from the queue and left as they were
  Step step = Step::Go;
  while (step == Step::Go) step = refineSteps(retry, unresolved);
  if (step == Step::Failed) return d_.lastError();
  // What is left bad: every triangle was checked when it was made, and a bad one queued; a
  // queued one was split (then it is gone, or it is among these), skipped, or is still
  // waiting. A pass over all the slots instead missed the cache for every one of them.
  unresolved.insert(unresolved.end(), retry.begin(), retry.end());
  bad_.drainInto(unresolved);
  std::uint64_t left = 0;
  ++epoch_;
  stamp_.resize(topo_.slotCount(), 0);
  forChunks(0, unresolved.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const BadTriangle& b = unresolved[i];
      if (stamp_[b.slot] == epoch_ || !holds(b) || !inRegion(b.slot)) continue;
      stamp_[b.slot] = epoch_;
      const Shape s = shape(b.slot);
      left += s.skinny(sin2_) || s.area > maxArea_;
    }
  });
  winding_.resize(topo_.slotCount());
  d_.stats.steinerPoints += added_;
  d_.stats.refineSkipped = left;
  d_.stats.refineCapped = capped_;
  return Status::success();
}

}  // namespace refinement

std::string refineOptionsError(const RefineOptions& o) {
  if (!(o.minAngle >= 0 && o.minAngle < 60))
    return "refine: minAngle must be a number of degrees from 0 to less than 60";
  if (!(o.maxArea >= 0)) return "refine: maxArea must be a positive number of squared units";
  return "";
}

Status refineTriangulation(Delaunay& d, const RefineOptions& options,
                           std::vector<std::int32_t>* windings) {
  refinement::Refiner refiner(d, options);
  const Status s = refiner.run();
  if (s.ok() && windings) refiner.takeWindings(*windings);
  return s;
}

}  // namespace geocdt
