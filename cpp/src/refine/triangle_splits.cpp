// A bad triangle split: where (its circumcentre or Ungor's off-centre), the walk there, the
// cavity of triangles whose circumcircles hold the point, and the point's insertion with the
// weights that interpolate its values.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "exact/power_of_two.h"
#include "geocdt/predicates.h"
#include "mesh/star_boundary.h"
#include "refine/refiner.h"

namespace geocdt::refinement {

// The weights of (cx, cy) on the edge from parent[0] to parent[1], by its projection;
// parent[2] becomes kNoVertex.
void Refiner::edgeWeights(std::uint32_t (&parent)[3], double (&weight)[3], double cx,
                          double cy) const {
  parent[2] = kNoVertex;
  const double w = projection(x(parent[0]), y(parent[0]), x(parent[1]), y(parent[1]), cx, cy);
  weight[0] = 1 - w;
  weight[1] = w;
  weight[2] = 0;
}

// (cx, cy) on an edge of the triangle of corners `parent` (exactly): that edge's ends and
// weights, as a point located on the edge gets them.
void Refiner::weightsOnEdge(std::uint32_t (&parent)[3], double (&weight)[3], double cx,
                            double cy) const {
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t a = parent[k], b = parent[k == 2 ? 0 : k + 1];
    if (orient2d(x(a), y(a), x(b), y(b), cx, cy) != Sign::Zero) continue;
    parent[0] = a;
    parent[1] = b;
    edgeWeights(parent, weight, cx, cy);
    return;
  }
  weightsInFace(parent, weight, cx, cy);
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
// angle, or a candidate out of range. large: the triangle exceeds maxArea.
inline bool Refiner::candidate(const BadTriangle& bad, double& cx, double& cy, bool& large) const {
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
  const double qx = x(q) - x(p), qy = y(q) - y(p), rx = x(r) - x(p), ry = y(r) - y(p);
  // maxArea holds on every triangle, as Triangle's -a does: one too large is split even where
  // its angle is left (below) or its candidate cannot go (then at its centroid).
  large = 0.5 * std::fabs(qx * ry - qy * rx) > maxArea_;
  // A skinny triangle whose shortest edge joins two subsegments meeting at a small input
  // angle is left: its angle cannot be mended there. Most triangles have an end of their
  // shortest edge on no subsegment.
  if (skinny && !large && onSubsegment(p) && onSubsegment(q) && smallInputAngle(p, q)) return false;
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

// The candidate as a new vertex, its cavity found from slot cur: the cavity's border joined to
// the point is its insertion. Where the border does not make a star (the point on it: on a
// subsegment, or on a vertex), the point is located and inserted with flips (which repeat
// the cavity's in-circle tests). A point on an edge inside the cavity, which lattice meshes
// (terrain) give often, takes the border too (bench/EXPERIMENTS.md, TN37).
inline Outcome Refiner::insertCandidate(std::int32_t cur, bool onEdge, double cx, double cy) {
  if (capReached()) {
    capped_ = true;
    return Outcome::Done;
  }
  const std::uint32_t v = newVertex(cx, cy);
  if (!orderStarBoundary(topo_, d_.xy, cavity_.size(), cx, cy, boundary_))
    return insertWithFlips(cur, v, cx, cy);
  std::uint32_t parent[3] = {topo_.tri[3 * cur], topo_.tri[3 * cur + 1], topo_.tri[3 * cur + 2]};
  double weight[3];
  if (onEdge) {
    weightsOnEdge(parent, weight, cx, cy);
  } else {
    weightsInFace(parent, weight, cx, cy);
  }
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
    edgeWeights(parent, weight, cx, cy);
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
  bool large = false;
  if (!candidate(bad, cx, cy, large)) return Outcome::Skipped;
  std::int32_t cur = bad.slot;
  bool onEdge = false;
  std::optional<Outcome> stopped = walkToCandidate(cx, cy, cur, onEdge);
  if (large && stopped == Outcome::Skipped) {
    // Too large, and its candidate cannot go in: its centroid, which lies inside it.
    cx = (x(bad.a) + x(bad.b) + x(bad.c)) / 3;
    cy = (y(bad.a) + y(bad.b) + y(bad.c)) / 3;
    cur = bad.slot;
    stopped = walkToCandidate(cx, cy, cur, onEdge);
  }
  if (stopped) return *stopped;
  if (findCavity(cur, cx, cy)) return Outcome::Retry;
  return insertCandidate(cur, onEdge, cx, cy);
}

}  // namespace geocdt::refinement
