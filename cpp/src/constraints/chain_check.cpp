#include "constraints/chain_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "base/chunks.h"
#include "exact/euclidean_norm.h"
#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"
#include "mesh/edge_map.h"

namespace geocdt {

namespace {

// How two input segments meet: not at all, in one point inside both, or otherwise (at an
// end, or overlapping), where a crossing of their chains means nothing.
enum class Meeting { Apart, Crossing, Touching };

Meeting meeting(const InputSegment& s, const InputSegment& t) {
  const int o1 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.ax, t.ay));
  const int o2 = int(orient2d(s.ax, s.ay, s.bx, s.by, t.bx, t.by));
  const int o3 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.ax, s.ay));
  const int o4 = int(orient2d(t.ax, t.ay, t.bx, t.by, s.bx, s.by));
  if (o1 * o2 < 0 && o3 * o4 < 0) return Meeting::Crossing;
  if (o1 * o2 > 0 || o3 * o4 > 0) return Meeting::Apart;
  // An end on the other's line meets the other when it lies within its box.
  const auto inBox = [](const InputSegment& g, double x, double y) {
    return std::min(g.ax, g.bx) <= x && x <= std::max(g.ax, g.bx) && std::min(g.ay, g.by) <= y &&
           y <= std::max(g.ay, g.by);
  };
  if ((o1 == 0 && inBox(s, t.ax, t.ay)) || (o2 == 0 && inBox(s, t.bx, t.by)) ||
      (o3 == 0 && inBox(t, s.ax, s.ay)) || (o4 == 0 && inBox(t, s.bx, s.by)))
    return Meeting::Touching;
  return Meeting::Apart;
}

// Whether an end of one segment lies within the bound of the other: a crossing there may
// be kept as a touch at that end.
bool crossingNearAnEnd(const InputSegment& s, const InputSegment& t) {
  const int es = chainBoundExponent(s), et = chainBoundExponent(t);
  return withinDistance(t, s.ax, s.ay, et) || withinDistance(t, s.bx, s.by, et) ||
         withinDistance(s, t.ax, t.ay, es) || withinDistance(s, t.bx, t.by, es);
}

// The chains of the segments checked, found on demand. Maps keyed by vertex or segment, not
// arrays over all vertices: a call into a large triangulation checks a few chains.
class Chains {
 public:
  Chains(Delaunay& d, VertexEdges& ends) : d_(d), ends_(ends) {}

  // The chain of segment i, empty when it has none; cached.
  const std::vector<std::uint32_t>& of(std::uint32_t i) {
    if (const std::uint32_t* k = index_.find(i)) return chains_[*k];
    index_.insert(i, static_cast<std::uint32_t>(chains_.size()));
    chains_.emplace_back();
    search(i, chains_.back());
    return chains_.back();
  }

  // A half-edge out of each vertex of the chains found so far.
  std::int32_t edgeOutOf(std::uint32_t v) { return *out_.find(v); }

 private:
  struct Step {
    double cost;  // the most a chain to here strays
    std::uint32_t at, before;
    std::int32_t out;  // a half-edge out of `at`
  };

  // Whether edge u-v holds segment i: a segment's chain is the route its insertion took,
  // not any chain of its polyline's edges within the bound (in a tangle there can be
  // thousands, and one that keeps apart from another segment's says nothing of the route).
  bool holds(std::uint32_t u, std::uint32_t v, std::uint32_t i) const {
    const EdgeSource* src = d_.constraints.find(u, v);
    if (!src) return false;
    bool found = false;
    d_.constraints.forEachSegment(*src, [&](std::uint32_t k) { found = found || k == i; });
    return found;
  }

  // The segment's chain: the edges that hold it, from its first vertex to its last, each
  // within the bound and further along (a search by the most any vertex so far strays, in
  // units of the spacing of doubles on each axis, which on one route finds that route).
  GEOCDT_NOINLINE void search(std::uint32_t i, std::vector<std::uint32_t>& chain) {
    const InputSegment s = d_.constraints.geometry(i, d_.xy);
    const int bound = chainBoundExponent(s);
    const std::uint32_t first = d_.constraints.segments[i].a, last = d_.constraints.segments[i].b;
    const std::int32_t out = ends_.find(d_, first);
    if (out < 0) return;
    // Spacings are powers of two: dividing by them is exact.
    const double gx = spacingAt(std::fmax(std::fabs(s.ax), std::fabs(s.bx)));
    const double gy = spacingAt(std::fmax(std::fabs(s.ay), std::fabs(s.by)));
    const double dx = (s.bx - s.ax) / gx, dy = (s.by - s.ay) / gy;
    const double length2 = dx * dx + dy * dy;
    const double* p = d_.xy.data();
    const auto stray = [&](std::uint32_t v) {
      const double wx = (p[2 * v] - s.ax) / gx, wy = (p[2 * v + 1] - s.ay) / gy;
      const double t = std::clamp((wx * dx + wy * dy) / length2, 0.0, 1.0);
      return euclideanNorm(wx - t * dx, wy - t * dy);
    };
    EdgeMap<std::uint32_t> settled;  // vertex -> the one before it on the chain
    std::vector<Step> queue(1, {0, first, first, out});
    // Ties go to the lower vertex ids, as in the test checker: both pick the same chain.
    const auto later = [](const Step& x, const Step& y) {
      return std::tie(x.cost, x.at, x.before) > std::tie(y.cost, y.at, y.before);
    };
    const Topology& topo = d_.topo;
    while (!queue.empty()) {
      std::pop_heap(queue.begin(), queue.end(), later);
      const Step step = queue.back();
      queue.pop_back();
      if (!settled.insert(step.at, step.before).second) continue;
      out_.insert(step.at, step.out);
      if (step.at == last) {
        for (std::uint32_t v = last; v != first; v = *settled.find(v)) chain.push_back(v);
        chain.push_back(first);
        std::reverse(chain.begin(), chain.end());
        return;
      }
      std::int32_t e = step.out;
      do {
        const std::uint32_t n = topo.tri[nextEdge(e)];
        if (topo.fixed[e] && n != kGhost && !settled.find(n) && holds(step.at, n, i) &&
            withinDistance(s, p[2 * n], p[2 * n + 1], bound) &&
            signAlong(s, p[2 * step.at], p[2 * step.at + 1], p[2 * n], p[2 * n + 1]) > 0) {
          queue.push_back({std::max(step.cost, stray(n)), n, step.at, topo.adj[e]});
          std::push_heap(queue.begin(), queue.end(), later);
        }
        e = topo.adj[prevEdge(e)];
      } while (e != step.out);
    }
  }

  Delaunay& d_;
  VertexEdges& ends_;
  EdgeMap<std::int32_t> out_;
  EdgeMap<std::uint32_t> index_;  // segment -> its chain in chains_
  std::vector<std::vector<std::uint32_t>> chains_;
};

// Whether ray a->w lies strictly inside the counter-clockwise sector from ray a->u to a->v.
bool inSector(const double* p, std::uint32_t a, std::uint32_t u, std::uint32_t v, std::uint32_t w) {
  const auto turn = [&](std::uint32_t from, std::uint32_t to) {
    return int(
        orient2d(p[2 * a], p[2 * a + 1], p[2 * from], p[2 * from + 1], p[2 * to], p[2 * to + 1]));
  };
  const int uv = turn(u, v);
  if (uv > 0) return turn(u, w) > 0 && turn(w, v) > 0;
  if (uv < 0) return !(turn(v, w) >= 0 && turn(w, u) >= 0);
  return turn(u, w) > 0;  // u and v opposite: a half-plane
}

// How often chain Q crosses chain P over the stretches they share; `undefined` tells whether
// a stretch holds an end of either (where crossing and touching are the same).
GEOCDT_NOINLINE int crossings(const double* p, const std::vector<std::uint32_t>& P,
                              const std::vector<std::uint32_t>& Q, bool& undefined) {
  const std::size_t m = P.size(), n = Q.size();
  const auto indexInQ = [&](std::uint32_t v) {
    return static_cast<std::size_t>(std::find(Q.begin(), Q.end(), v) - Q.begin());
  };
  int count = 0;
  undefined = false;
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t k = indexInQ(P[i]);
    if (k == n) continue;
    // The shared stretch P[i..j] = Q[k..l], Q running forward or backward along it.
    int step = 0;
    if (i + 1 < m && k + 1 < n && P[i + 1] == Q[k + 1]) step = 1;
    if (i + 1 < m && k >= 1 && P[i + 1] == Q[k - 1]) step = -1;
    std::size_t j = i, l = k;
    while (step != 0 && j + 1 < m && l + step < n && P[j + 1] == Q[l + step]) {
      ++j;
      l += step;
    }
    if (i == 0 || j + 1 == m || std::min(k, l) == 0 || std::max(k, l) + 1 == n) {
      undefined = true;
    } else {
      // Q's neighbours off the stretch at its two ends, each on the left or right of P.
      const std::uint32_t qi = step >= 0 ? Q[k - 1] : Q[k + 1];
      const std::uint32_t qj = step >= 0 ? Q[l + 1] : Q[l - 1];
      count +=
          inSector(p, P[i], P[i + 1], P[i - 1], qi) != inSector(p, P[j], P[j + 1], P[j - 1], qj);
    }
    i = j;
  }
  return count;
}

// Whether every constrained edge naming segment i that can be reached from its first vertex
// through such edges lies within i's bound, on its chain or not: a piece bent through a
// vertex off its segment and later routed another way leaves its first route behind, named
// and straying, where the chain search (which keeps to vertices within the bound) never looks
// (fuzz: a lattice around (16000001, 16000001), a route 2.3 spacings off its segment).
GEOCDT_NOINLINE bool namedEdgesStayNear(Delaunay& d, VertexEdges& ends, std::uint32_t i) {
  const ConstraintStore& store = d.constraints;
  const InputSegment s = store.geometry(i, d.xy);
  const int bound = chainBoundExponent(s);
  std::vector<std::uint32_t> stack(1, store.segments[i].a);
  EdgeMap<std::uint8_t> seen;
  seen.insert(stack[0], 1);
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    const std::int32_t out = ends.find(d, v);
    if (out < 0) return false;
    std::int32_t e = out;
    do {
      const std::uint32_t n = d.topo.tri[nextEdge(e)];
      if (d.topo.fixed[e] && n != kGhost) {
        bool names = false;
        if (const EdgeSource* src = store.find(v, n))
          store.forEachSegment(*src, [&](std::uint32_t j) { names = names || j == i; });
        if (names && seen.insert(n, 1).second) {
          if (!withinDistance(s, d.xy[2 * n], d.xy[2 * n + 1], bound)) return false;
          stack.push_back(n);
        }
      }
      e = d.topo.adj[prevEdge(e)];
    } while (e != out);
  }
  return true;
}

// Whether segment i's chain keeps the guarantee with every chain it meets; others: scratch.
// It and the searches it calls are kept apart (GEOCDT_NOINLINE): one function of them all
// was optimised late in a first call, which ran it in baseline code meanwhile (F21).
bool segmentKeepsTheGuarantee(Delaunay& d, VertexEdges& ends, Chains& chains, std::uint32_t i,
                              std::vector<std::uint32_t>& others) {
  const ConstraintStore& store = d.constraints;
  const std::vector<std::uint32_t> P = chains.of(i);
  if (P.empty() || !namedEdgesStayNear(d, ends, i)) return false;
  // The segments whose constrained edges meet this chain's vertices.
  others.clear();
  for (const std::uint32_t v : P) {
    const std::int32_t out = chains.edgeOutOf(v);
    std::int32_t e = out;
    do {
      if (d.topo.fixed[e]) {
        const EdgeSource* src = store.find(v, d.topo.tri[nextEdge(e)]);
        if (src)
          store.forEachSegment(*src, [&](std::uint32_t j) {
            if (j != i) others.push_back(j);
          });
      }
      e = d.topo.adj[prevEdge(e)];
    } while (e != out);
  }
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  const InputSegment s = store.geometry(i, d.xy);
  for (const std::uint32_t j : others) {
    const InputSegment t = store.geometry(j, d.xy);
    const Meeting how = meeting(s, t);
    if (how == Meeting::Touching || (how == Meeting::Crossing && crossingNearAnEnd(s, t))) continue;
    const std::vector<std::uint32_t>& Q = chains.of(j);
    if (Q.empty()) return false;
    bool undefined = false;
    const int count = crossings(d.xy.data(), P, Q, undefined);
    if (how == Meeting::Apart ? count > 0 : count > 1 || (!undefined && count != 1)) return false;
  }
  return true;
}

}  // namespace

bool chainsKeepTheGuarantee(Delaunay& d, std::vector<std::uint32_t> segments, VertexEdges& ends) {
  if (segments.empty()) return true;
  std::sort(segments.begin(), segments.end());
  segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
  Chains chains(d, ends);
  std::vector<std::uint32_t> others;
  bool keeps = true;
  // A call per segment (a chunk of 1), so that this function, which runs once a call, never
  // spends the engine's budget for optimised code (chunks.h; bench/EXPERIMENTS.md, F21).
  forChunks(
      0, segments.size(),
      [&](std::size_t first, std::size_t last) {
        for (std::size_t at = first; at < last && keeps; ++at)
          keeps = segmentKeepsTheGuarantee(d, ends, chains, segments[at], others);
      },
      1);
  return keeps;
}

}  // namespace geocdt
