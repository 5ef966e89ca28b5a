#include "constraints/overlapping_segments.h"

#include <cmath>
#include <limits>

#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"

namespace geocdt {

bool runsAlongAnotherSegment(const Delaunay& d, const std::vector<std::int32_t>& vertexEdge,
                             std::uint32_t a, std::uint32_t b, std::uint64_t segment,
                             const InputSegment& s, unsigned splitEnds) {
  const Topology& topo = d.topo;
  const ConstraintStore& store = d.constraints;
  const double* p = d.xy.data();
  // (An end of s is on its line: no need for the exact predicate's slow path there.)
  const auto onLine = [&](double qx, double qy) {
    return (qx == s.ax && qy == s.ay) || (qx == s.bx && qy == s.by) ||
           orient2d(s.ax, s.ay, s.bx, s.by, qx, qy) == Sign::Zero;
  };
  const double ex = p[2 * b] - p[2 * a], ey = p[2 * b + 1] - p[2 * a + 1];
  bool along = false;
  const auto check = [&](std::uint32_t j) {
    if (along || j == segment) return;
    const InputSegment t = store.geometry(j, d.xy);
    // With both ends within t's bound B (two spacings of doubles at its largest coordinate
    // m, at most 2^-50 m), the edge strays at most 2B across t: most neighbours fail that in
    // double (2^-48 m, and the products' rounding, for room).
    const double tx = t.bx - t.ax, ty = t.by - t.ay;
    const double across = std::fabs(ex * ty - ey * tx);
    const double rounding =
        4 * std::numeric_limits<double>::epsilon() * (std::fabs(ex * ty) + std::fabs(ey * tx));
    const double m = std::fmax(std::fmax(std::fabs(t.ax), std::fabs(t.ay)),
                               std::fmax(std::fabs(t.bx), std::fabs(t.by)));
    const double room = 0x1p-48 * m * (std::fabs(tx) + std::fabs(ty));
    if (room > 0x1p-1000 && across > room + rounding) return;  // (not where it underflows)
    if (onLine(t.ax, t.ay) && onLine(t.bx, t.by)) return;
    const int bound = chainBoundExponent(t);
    along = withinDistance(t, p[2 * a], p[2 * a + 1], bound) &&
            withinDistance(t, p[2 * b], p[2 * b + 1], bound);
  };
  if (splitEnds != 0)
    if (const EdgeSource* src = store.find(a, b)) store.forEachSegment(*src, check);
  for (const std::uint32_t u : {a, b}) {
    if (splitEnds & (u == a ? 1u : 2u)) continue;
    const std::int32_t start = vertexEdge[u];
    std::int32_t h = start;
    do {
      if (topo.fixed[h])
        if (const EdgeSource* src = store.find(u, topo.tri[nextEdge(h)]))
          store.forEachSegment(*src, check);
      h = topo.adj[prevEdge(h)];
    } while (h != start && !along);
  }
  return along;
}

}  // namespace geocdt
