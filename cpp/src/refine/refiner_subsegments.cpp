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
  const double dx = x(v) - x(u), dy = y(v) - y(u);
  if (dx * dx + dy * dy < shortestSplit2_) return;
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

Refiner::SplitSite Refiner::splitSite(std::int32_t e) const {
  SplitSite site;
  site.e = e;
  site.a = topo_.tri[e];
  site.b = topo_.tri[nextEdge(e)];
  site.c = topo_.tri[prevEdge(e)];
  site.dv = topo_.tri[prevEdge(topo_.adj[e])];
  site.s = segmentOf(e, site.id, &site.sources);
  site.input = site.id < (std::uint64_t{1} << 32);
  site.hull = topo_.isGhost(topo_.adj[e] / 3);
  // A segment with s's ends (a border two rings share) answers as s does: skipped.
  site.shared = site.input && site.sources && site.sources->extra >= 0;
  return site;
}

// The point is placed on the segment, from the segment's own ends, so that it stays within
// the chains' bound of it however often it is split: halfway, or on concentric shells next
// to an input vertex where constraints meet (a power of two from it), so that the splits on
// its segments line up instead of chasing each other.
void Refiner::splitPoint(const SplitSite& site, double& px, double& py) const {
  const std::uint32_t a = site.a, b = site.b;
  const InputSegment& s = site.s;
  const double dx = s.bx - s.ax, dy = s.by - s.ay, length2 = dx * dx + dy * dy;
  const double ta = ((x(a) - s.ax) * dx + (y(a) - s.ay) * dy) / length2;
  const double tb = ((x(b) - s.ax) * dx + (y(b) - s.ay) * dy) / length2;
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
  px = (1 - t) * s.ax + t * s.bx;
  py = (1 - t) * s.ay + t * s.by;
  // On a segment along a grid line (a coordinate the same at both ends) the point keeps that
  // coordinate exactly, where the sum above may round it off by an ulp: a raster's boundary
  // stays on its grid line, and its pixels on it (terrain meshes).
  if (s.ax == s.bx) px = s.ax;
  if (s.ay == s.by) py = s.ay;
}

bool Refiner::strictlyBetween(const SplitSite& site, const InputSegment& on, double qx,
                              double qy) const {
  const std::uint32_t a = site.a, b = site.b;
  const int along = signAlong(on, x(a), y(a), x(b), y(b));
  return along != 0 && signAlong(on, x(a), y(a), qx, qy) == along &&
         signAlong(on, qx, qy, x(b), y(b)) == along;
}

// The other input segments whose chains hold the edge (segments that overlap, or pass within
// their bound of the same vertices): the point goes into their chains too. Placed from s's
// ends, it can fall behind an end along one of them where s and it part at an end ulps away
// (a subnormal y from a segment 1e67 long).
bool Refiner::fitsOthers(const SplitSite& site, double qx, double qy) const {
  const InputSegment& s = site.s;
  bool fit = true;
  d_.constraints.forEachSegment(*site.sources, [&](std::uint32_t other) {
    if (!fit || other == site.id) return;
    const InputSegment o = d_.constraints.geometry(other, d_.xy);
    const bool same = (o.ax == s.ax && o.ay == s.ay && o.bx == s.bx && o.by == s.by) ||
                      (o.ax == s.bx && o.ay == s.by && o.bx == s.ax && o.by == s.ay);
    if (!same)
      fit = strictlyBetween(site, o, qx, qy) && withinDistance(o, qx, qy, chainBoundExponent(o));
  });
  return fit;
}

// The four triangles around the point must be counter-clockwise, and a constrained edge's
// point within the bound of its segments, strictly between the ends along each.
//
//          c
//        /   \         e runs from a to b; c and dv are the apexes of its two
//       a--p--b        triangles (no dv on the hull); p must see c a, b c, a dv
//        \   /         and dv b on its left.
//          dv
bool Refiner::fitsAt(const SplitSite& site, double qx, double qy) const {
  const std::uint32_t a = site.a, b = site.b, c = site.c, dv = site.dv;
  if (!ccw(c, a, qx, qy) || !ccw(b, c, qx, qy) || !strictlyBetween(site, site.s, qx, qy))
    return false;
  if (!site.hull && !(ccw(a, dv, qx, qy) && ccw(dv, b, qx, qy))) return false;
  if (!site.input) return true;
  return withinDistance(site.s, qx, qy, chainBoundExponent(site.s)) &&
         (!site.shared || fitsOthers(site, qx, qy));
}

// On the hull the point must neither fall inside (the hull would turn reflex) nor beyond the
// hull's next edges (the hull would wrap round it, and the vertices it wraps would encroach
// the new hull edges ulps away from them): it and its neighbouring doubles are tried, and
// (px, py) is left at the last one tried.
bool Refiner::fitsOnHull(const SplitSite& site, double& px, double& py) const {
  const std::uint32_t a = site.a, b = site.b;
  const std::int32_t f = topo_.adj[site.e];
  const std::uint32_t before = topo_.tri[prevEdge(topo_.adj[nextEdge(f)])];
  const std::uint32_t after = topo_.tri[prevEdge(topo_.adj[prevEdge(f)])];
  const double x0 = px, y0 = py;
  bool fits = false;
  for (int k = 0; k < 9 && !fits; ++k) {
    px = k % 3 == 0 ? x0 : std::nextafter(x0, k % 3 == 1 ? -INFINITY : INFINITY);
    py = k / 3 == 0 ? y0 : std::nextafter(y0, k / 3 == 1 ? -INFINITY : INFINITY);
    fits = !ccw(a, b, px, py) && !ccw(a, before, px, py) && !ccw(after, b, px, py) &&
           fitsAt(site, px, py);
  }
  return fits;
}

// The new vertex p splits the edge, its constraint and its hull entry in two.
void Refiner::insertSplitPoint(const SplitSite& site, double px, double py) {
  const std::uint32_t a = site.a, b = site.b;
  const std::uint32_t p = newVertex(px, py);
  markOnSubsegment(p);
  if (site.input) noteSegment(p, static_cast<std::uint32_t>(site.id));
  if (topo_.fixed[site.e]) d_.constraints.split(a, b, p);
  const auto hullEdge = hullOf_.find(ConstraintStore::key(a, b));
  if (hullEdge != hullOf_.end()) {
    const std::uint32_t original = hullEdge->second;
    hullOf_.erase(hullEdge);
    hullOf_[ConstraintStore::key(a, p)] = original;
    hullOf_[ConstraintStore::key(p, b)] = original;
  }
  const std::int32_t spoke = d_.splitEdge(site.e, p);
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
}

Outcome Refiner::splitSubsegment(std::int32_t e, bool forced) {
  if (topo_.isGhost(e / 3)) e = topo_.adj[e];
  if (!forced && !encroached(e)) return Outcome::Done;
  const SplitSite site = splitSite(e);
  double px = 0, py = 0;
  splitPoint(site, px, py);
  bool fits = site.hull ? fitsOnHull(site, px, py) : fitsAt(site, px, py);
  // Left whole where another input segment runs along it ulps away (overlapping_segments.h),
  // on the hull too.
  const unsigned splitEnds =
      (segmentAt(site.a) != kNoSegment ? 1u : 0u) | (segmentAt(site.b) != kNoSegment ? 2u : 0u);
  if (fits && site.input &&
      runsAlongAnotherSegment(d_, vertexEdge_, site.a, site.b, site.id, site.s, splitEnds))
    fits = false;
  if (!fits) {
    unsplittable_.insert(ConstraintStore::key(site.a, site.b));
    return Outcome::Skipped;
  }
  if (capReached()) {
    capped_ = true;
    return Outcome::Done;
  }
  insertSplitPoint(site, px, py);
  return Outcome::Done;
}

}  // namespace geocdt::refinement
