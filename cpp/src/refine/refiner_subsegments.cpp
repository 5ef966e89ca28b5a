// The refiner's subsegments: which are encroached, which input segment each lies on, where
// one is split (on concentric shells next to input vertices where constraints meet), and the
// small input angles that leave a triangle as it is.
#include <cmath>
#include <cstdint>

#include "constraints/overlapping_segments.h"
#include "exact/euclidean_norm.h"
#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"
#include "refine/refiner.h"

namespace geocdt::refinement {

bool Refiner::encroached(std::int32_t e) const {
  const std::uint32_t u = topo_.tri[e], v = topo_.tri[nextEdge(e)];
  for (const std::int32_t h : {e, topo_.adj[e]}) {
    if (!inRegion(h / 3)) continue;
    const std::uint32_t w = topo_.tri[prevEdge(h)];
    if (encroachedBy(x(u), y(u), x(v), y(v), x(w), y(w))) return true;
  }
  return false;
}

void Refiner::queueSubsegment(std::int32_t e, bool forced) {
  const std::uint32_t u = topo_.tri[e], v = topo_.tri[nextEdge(e)];
  if (unsplittable_.count(ConstraintStore::key(u, v))) return;
  subsegments_.push_back({u, v, forced});
}

InputSegment Refiner::segmentOf(std::int32_t e, std::uint64_t& id,
                                const EdgeSource** source) const {
  const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
  if (topo_.fixed[e]) {
    const EdgeSource* src = d_.constraints.find(a, b);
    if (src) {
      id = src->segment;
      if (source) *source = src;
      return d_.constraints.geometry(src->segment, d_.xy);
    }
  }
  const auto hull = hullOf_.find(ConstraintStore::key(a, b));
  if (hull != hullOf_.end()) {
    id = (std::uint64_t{1} << 32) + hull->second;
    return hull_[hull->second];
  }
  id = (std::uint64_t{1} << 33) + ConstraintStore::key(a, b);  // a hull edge made by flips
  return {x(a), y(a), x(b), y(b)};
}

int Refiner::constrainedDegree(std::uint32_t u) const {
  const std::int32_t start = vertexEdge_[u];
  std::int32_t e = start;
  int degree = 0;
  do {
    degree += topo_.tri[nextEdge(e)] != kGhost && isSubsegment(e);
    e = topo_.adj[prevEdge(e)];
  } while (e != start);
  return degree;
}

// Whether a triangle's shortest edge p, q (both on subsegments) joins two points on two input
// segments that meet at a vertex, at equal distances from it: the concentric shells put them
// there, and the angle between the segments is then the triangle's. Splitting it would go on for
// ever. The segments meet at a shared end, or where one ends on the other (a breakline ending
// on a raster's border) or crosses it: there the vertex is their lines' rounded crossing,
// within both chains' bound of both segments.
bool Refiner::smallInputAngle(std::uint32_t p, std::uint32_t q) const {
  // The segments through a vertex, from its subsegments (a few).
  struct Through {
    InputSegment s;
    std::uint64_t id;
  };
  const auto segmentsAt = [&](std::uint32_t u, Through* out) {
    if (const std::uint32_t segment = segmentAt(u); segment != kNoSegment) {
      out[0] = {d_.constraints.geometry(segment, d_.xy), segment};
      return 1;
    }
    int n = 0;
    const std::int32_t start = vertexEdge_[u];
    std::int32_t e = start;
    do {
      if (n < 8 && topo_.tri[nextEdge(e)] != kGhost && isSubsegment(e)) {
        out[n].s = segmentOf(e, out[n].id);
        ++n;
      }
      e = topo_.adj[prevEdge(e)];
    } while (e != start);
    return n;
  };
  const auto equallyFar = [&](double zx, double zy) {
    const double dp = euclideanNorm(x(p) - zx, y(p) - zy);
    const double dq = euclideanNorm(x(q) - zx, y(q) - zy);
    return dp < 1.001 * dq && dq < 1.001 * dp;
  };
  Through sp[8], sq[8];
  const int np = segmentsAt(p, sp);
  const int nq = segmentsAt(q, sq);
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < nq; ++j) {
      if (sp[i].id == sq[j].id) continue;
      const InputSegment& a = sp[i].s;
      const InputSegment& b = sq[j].s;
      const double ends[2][2] = {{a.ax, a.ay}, {a.bx, a.by}};
      bool sharedEnd = false;
      for (const auto& z : ends) {
        const bool shared = (z[0] == b.ax && z[1] == b.ay) || (z[0] == b.bx && z[1] == b.by);
        if (!shared) continue;
        sharedEnd = true;
        if (equallyFar(z[0], z[1])) return true;
      }
      double zx, zy;
      if (!sharedEnd && roundedLineCrossing(a, b, zx, zy) &&
          withinDistance(a, zx, zy, chainBoundExponent(a)) &&
          withinDistance(b, zx, zy, chainBoundExponent(b)) && equallyFar(zx, zy))
        return true;
    }
  return false;
}

Outcome Refiner::splitSubsegment(std::int32_t e, bool forced) {
  if (topo_.isGhost(e / 3)) e = topo_.adj[e];
  const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
  const std::uint32_t c = topo_.tri[prevEdge(e)], dv = topo_.tri[prevEdge(topo_.adj[e])];
  if (!forced && !encroached(e)) return Outcome::Done;
  // The point is placed on the segment, from the segment's own ends, so that it stays within
  // the chains' bound of it however often it is split.
  std::uint64_t id;
  const EdgeSource* sources = nullptr;
  const InputSegment s = segmentOf(e, id, &sources);
  const bool input = id < (std::uint64_t{1} << 32);
  const double dx = s.bx - s.ax, dy = s.by - s.ay, length2 = dx * dx + dy * dy;
  const double ta = ((x(a) - s.ax) * dx + (y(a) - s.ay) * dy) / length2;
  const double tb = ((x(b) - s.ax) * dx + (y(b) - s.ay) * dy) / length2;
  // Concentric shells: next to an input vertex where constraints meet, split at a power of
  // two from it, so that the splits on its segments line up instead of chasing each other.
  const bool acuteA = !(a < steinerFlag_.size() && steinerFlag_[a]) && constrainedDegree(a) > 1;
  const bool acuteB = !(b < steinerFlag_.size() && steinerFlag_[b]) && constrainedDegree(b) > 1;
  double f = 0.5;
  if (acuteA != acuteB) {
    const double length = euclideanNorm(x(b) - x(a), y(b) - y(a));
    int exponent;
    std::frexp(length, &exponent);
    double n = std::ldexp(1.0, exponent);
    while (length > 3 * n) n *= 2;
    while (length < 1.5 * n) n *= 0.5;
    f = acuteA ? n / length : 1 - n / length;
  }
  const double t = ta + (tb - ta) * f;
  double px = (1 - t) * s.ax + t * s.bx, py = (1 - t) * s.ay + t * s.by;
  // On a segment along a grid line (a coordinate the same at both ends) the point keeps that
  // coordinate exactly, where the sum above may round it off by an ulp: a raster's boundary
  // stays on its grid line, and its pixels on it (terrain meshes).
  if (s.ax == s.bx) px = s.ax;
  if (s.ay == s.by) py = s.ay;
  const bool hull = topo_.isGhost(topo_.adj[e] / 3);
  const auto strictlyBetween = [&](const InputSegment& on, double qx, double qy) {
    const int along = signAlong(on, x(a), y(a), x(b), y(b));
    return along != 0 && signAlong(on, x(a), y(a), qx, qy) == along &&
           signAlong(on, qx, qy, x(b), y(b)) == along;
  };
  // The other input segments whose chains hold the edge (segments that overlap, or pass
  // within their bound of the same vertices): the point goes into their chains too. Placed
  // from s's ends, it can fall behind an end along one of them where s and it part at an end
  // ulps away (a subnormal y from a segment 1e67 long).
  // A segment with s's ends (a border two rings share) answers as s does: skipped.
  const bool shared = input && sources && sources->extra >= 0;
  const auto fitsOthers = [&](double qx, double qy) {
    bool fit = true;
    d_.constraints.forEachSegment(*sources, [&](std::uint32_t other) {
      if (!fit || other == id) return;
      const InputSegment o = d_.constraints.geometry(other, d_.xy);
      const bool same = (o.ax == s.ax && o.ay == s.ay && o.bx == s.bx && o.by == s.by) ||
                        (o.ax == s.bx && o.ay == s.by && o.bx == s.ax && o.by == s.ay);
      if (!same)
        fit = strictlyBetween(o, qx, qy) && withinDistance(o, qx, qy, chainBoundExponent(o));
    });
    return fit;
  };
  // The four triangles around the point must be counter-clockwise, and a constrained
  // edge's point within the bound of its segments, strictly between the ends along each.
  const auto fitsAt = [&](double qx, double qy) {
    if (!ccw(c, a, qx, qy) || !ccw(b, c, qx, qy) || !strictlyBetween(s, qx, qy)) return false;
    if (!hull && !(ccw(a, dv, qx, qy) && ccw(dv, b, qx, qy))) return false;
    if (!input) return true;
    return withinDistance(s, qx, qy, chainBoundExponent(s)) && (!shared || fitsOthers(qx, qy));
  };
  bool fits = fitsAt(px, py);
  // Left whole where another input segment runs along it ulps away (overlapping_segments.h).
  const unsigned splitEnds =
      (segmentAt(a) != kNoSegment ? 1u : 0u) | (segmentAt(b) != kNoSegment ? 2u : 0u);
  if (fits && input && runsAlongAnotherSegment(d_, vertexEdge_, a, b, id, s, splitEnds))
    fits = false;
  if (hull) {
    // On the hull the point must neither fall inside (the hull would turn reflex) nor
    // beyond the hull's next edges (the hull would wrap round it, and the vertices it wraps
    // would encroach the new hull edges ulps away from them): try it and its neighbouring
    // doubles.
    const std::int32_t f = topo_.adj[e];
    const std::uint32_t before = topo_.tri[prevEdge(topo_.adj[nextEdge(f)])];
    const std::uint32_t after = topo_.tri[prevEdge(topo_.adj[prevEdge(f)])];
    const double x0 = px, y0 = py;
    fits = false;
    for (int k = 0; k < 9 && !fits; ++k) {
      px = k % 3 == 0 ? x0 : std::nextafter(x0, k % 3 == 1 ? -INFINITY : INFINITY);
      py = k / 3 == 0 ? y0 : std::nextafter(y0, k / 3 == 1 ? -INFINITY : INFINITY);
      fits =
          !ccw(a, b, px, py) && !ccw(a, before, px, py) && !ccw(after, b, px, py) && fitsAt(px, py);
    }
  }
  if (!fits) {
    unsplittable_.insert(ConstraintStore::key(a, b));
    return Outcome::Skipped;
  }
  if (capReached()) {
    capped_ = true;
    return Outcome::Done;
  }
  const std::uint32_t p = newVertex(px, py);
  markOnSubsegment(p);
  if (input) noteSegment(p, static_cast<std::uint32_t>(id));
  if (topo_.fixed[e]) d_.constraints.split(a, b, p);
  const auto hullEdge = hullOf_.find(ConstraintStore::key(a, b));
  if (hullEdge != hullOf_.end()) {
    const std::uint32_t original = hullEdge->second;
    hullOf_.erase(hullEdge);
    hullOf_[ConstraintStore::key(a, p)] = original;
    hullOf_[ConstraintStore::key(p, b)] = original;
  }
  const std::int32_t spoke = d_.splitEdge(e, p);
  // The weight from where the point landed, projected on the edge it split: accurate to the
  // edge's length, where the segment's parameters are accurate to the segment's.
  const double w = projection(x(a), y(a), x(b), y(b), px, py);
  record(p, a, b, kNoVertex, 1 - w, w, 0);
  afterInsert(spoke);
  // The point is near the edge, not on it: the spokes to the apexes may need flips that a
  // point on the edge would not.
  std::vector<std::int32_t>& stack = d_.flipStack();
  for (std::int32_t h = spoke;;) {
    stack.push_back(h);
    h = topo_.adj[prevEdge(h)];
    if (h == spoke) break;
  }
  restoreDelaunay(stack);
  return Outcome::Done;
}

}  // namespace geocdt::refinement
