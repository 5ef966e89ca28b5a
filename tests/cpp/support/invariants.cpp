#include "invariants.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geocdt/predicates.h"

namespace geocdt::testing {

namespace {

std::uint32_t nextOf(std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }

template <typename... Args>
std::string describe(Args&&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}

}  // namespace

std::size_t hullSize(const Mesh& mesh) {
  std::size_t h = 0;
  for (const std::int32_t twin : mesh.halfedges) h += twin < 0;
  return h;
}

std::string checkTriangulation(const Mesh& mesh, const CheckOptions& options) {
  const std::vector<double>& p = mesh.points;
  const std::vector<std::uint32_t>& tri = mesh.triangles;
  const std::vector<std::int32_t>& he = mesh.halfedges;
  const std::size_t vertices = p.size() / 2;
  if (tri.size() % 3 != 0) return "triangles length is not a multiple of 3";
  if (he.size() != tri.size()) return "halfedges and triangles differ in length";
  if (mesh.constrained.size() != tri.size()) return "constrained and triangles differ in length";
  const std::size_t triangles = tri.size() / 3;

  for (std::size_t e = 0; e < tri.size(); ++e)
    if (tri[e] >= vertices)
      return describe("half-edge ", e, " names vertex ", tri[e], " of ", vertices);

  // Half-edges are symmetric and join the same two vertices in opposite directions.
  for (std::size_t e = 0; e < he.size(); ++e) {
    const std::int32_t f = he[e];
    if (f < 0) continue;
    if (static_cast<std::size_t>(f) >= he.size() || he[f] != static_cast<std::int32_t>(e))
      return describe("half-edge ", e, " has twin ", f, " whose twin is not ", e);
    if (tri[e] != tri[nextOf(f)] || tri[nextOf(e)] != tri[f])
      return describe("half-edges ", e, " and ", f, " do not join the same vertices");
    if (mesh.constrained[e] != mesh.constrained[f])
      return describe("half-edge ", e, " and its twin disagree on being constrained");
  }

  // Every triangle is strictly counter-clockwise.
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    if (orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1]) !=
        Sign::Positive)
      return describe("triangle ", t, " (", a, ", ", b, ", ", c, ") is not counter-clockwise");
  }

  // The boundary is one closed loop without reflex turns: the convex hull.
  std::vector<std::int64_t> outgoing(vertices, -1);
  std::size_t boundary = 0;
  for (std::size_t e = 0; e < he.size() && options.hull; ++e) {
    if (he[e] >= 0) continue;
    ++boundary;
    if (outgoing[tri[e]] >= 0) return describe("vertex ", tri[e], " has two boundary edges out");
    outgoing[tri[e]] = static_cast<std::int64_t>(e);
  }
  if (triangles > 0 && options.hull) {
    // Walking the boundary from one edge must come back after exactly `boundary` edges
    // (one loop, not several), turning left or going straight at every vertex.
    std::size_t start = 0;
    while (he[start] >= 0) ++start;
    std::size_t e = start, length = 0;
    do {
      const std::uint32_t a = tri[e], b = tri[nextOf(e)];
      const std::int64_t next = outgoing[b];
      if (next < 0) return describe("the boundary stops at vertex ", b);
      const std::uint32_t c = tri[nextOf(static_cast<std::size_t>(next))];
      if (orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1]) ==
          Sign::Negative)
        return describe("the boundary turns right at vertex ", b, ": the hull is not convex");
      e = static_cast<std::size_t>(next);
      ++length;
    } while (e != start && length <= boundary);
    if (length != boundary)
      return describe("the boundary's ", boundary, " edges form more than one loop");

    // Areas in long double: its exponent range keeps products of subnormal coordinates
    // from underflowing to zero (a floating check on top of the exact ones above).
    long double sum2 = 0, scale = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
      const std::uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
      const long double abx = (long double)p[2 * b] - p[2 * a],
                        aby = (long double)p[2 * b + 1] - p[2 * a + 1];
      const long double acx = (long double)p[2 * c] - p[2 * a],
                        acy = (long double)p[2 * c + 1] - p[2 * a + 1];
      sum2 += abx * acy - aby * acx;
      scale += std::fabs(abx * acy) + std::fabs(aby * acx);
    }
    long double hull2 = 0, hullScale = 0;
    e = start;
    for (std::size_t steps = 0; steps < boundary; ++steps) {
      const std::uint32_t a = tri[e], b = tri[nextOf(e)];
      // Relative to the first vertex, to keep large offsets from swamping the area.
      const std::uint32_t o = tri[start];
      const long double ax = (long double)p[2 * a] - p[2 * o],
                        ay = (long double)p[2 * a + 1] - p[2 * o + 1];
      const long double bx = (long double)p[2 * b] - p[2 * o],
                        by = (long double)p[2 * b + 1] - p[2 * o + 1];
      hull2 += ax * by - bx * ay;
      hullScale += std::fabs(ax * by) + std::fabs(bx * ay);
      e = static_cast<std::size_t>(outgoing[b]);
    }
    if (std::fabs(hull2 - sum2) > 1e-9L * (scale + hullScale))
      return describe("triangle areas sum to ", double(sum2 / 2), " but the hull's area is ",
                      double(hull2 / 2));
  }

  // Euler: T = 2V - h - 2 over the vertices the triangles use.
  if (triangles > 0 && options.hull) {
    std::vector<std::uint8_t> used(vertices, 0);
    for (const std::uint32_t v : tri) used[v] = 1;
    std::size_t v = 0;
    for (const std::uint8_t u : used) v += u;
    if (triangles != 2 * v - boundary - 2)
      return describe("Euler: ", triangles, " triangles, expected 2*", v, " - ", boundary, " - 2");
    // Every vertex is in the triangulation unless all points are collinear.
    if (v != vertices) return describe(vertices - v, " vertices are in no triangle");
  }

  // Every input point is the vertex it was mapped to.
  if (options.inputXY && options.inputToVertex) {
    const std::vector<double>& in = *options.inputXY;
    const std::vector<std::uint32_t>& map = *options.inputToVertex;
    if (map.size() * 2 != in.size()) return "inputToVertex has the wrong length";
    for (std::size_t i = 0; i < map.size(); ++i) {
      const std::uint32_t v = map[i];
      if (v >= vertices) return describe("input point ", i, " maps to missing vertex ", v);
      if (p[2 * v] != in[2 * i] || p[2 * v + 1] != in[2 * i + 1])
        return describe("input point ", i, " maps to vertex ", v, " at another place");
    }
  }

  // No two vertices are equal (duplicates are merged).
  {
    std::vector<std::uint32_t> order(vertices);
    for (std::uint32_t i = 0; i < vertices; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&p](std::uint32_t a, std::uint32_t b) {
      return p[2 * a] != p[2 * b] ? p[2 * a] < p[2 * b] : p[2 * a + 1] < p[2 * b + 1];
    });
    for (std::size_t i = 1; i < order.size(); ++i)
      if (p[2 * order[i]] == p[2 * order[i - 1]] && p[2 * order[i] + 1] == p[2 * order[i - 1] + 1])
        return describe("vertices ", order[i - 1], " and ", order[i], " are equal");
  }

  // Every unconstrained interior edge is locally Delaunay.
  if (options.delaunay) {
    for (std::size_t e = 0; e < he.size(); ++e) {
      const std::int32_t f = he[e];
      if (f < static_cast<std::int32_t>(e) || mesh.constrained[e]) continue;
      const std::uint32_t a = tri[e], b = tri[nextOf(e)], c = tri[nextOf(nextOf(e))];
      const std::uint32_t d = tri[nextOf(nextOf(static_cast<std::uint32_t>(f)))];
      if (incircle(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], p[2 * d],
                   p[2 * d + 1]) == Sign::Positive)
        return describe("edge ", a, "-", b, " is not locally Delaunay (vertex ", d, " in circle)");
    }
  }
  return "";
}

std::vector<std::array<std::uint32_t, 3>> triangleSet(const Mesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> set(mesh.triangles.size() / 3);
  for (std::size_t i = 0; i < set.size(); ++i) {
    const std::uint32_t* t = mesh.triangles.data() + 3 * i;
    const int k = static_cast<int>(std::min_element(t, t + 3) - t);
    set[i] = {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
  }
  std::sort(set.begin(), set.end());
  return set;
}

}  // namespace geocdt::testing
