// Moving a vertex within its star. Where the new place sees every edge of the star's border
// strictly from inside (the star's kernel), the star's triangles stay counter-clockwise with
// the vertex there: the triangulation is valid as it is, and only edges whose quad holds the
// vertex, its spokes and the border, can have stopped being Delaunay. Lawson flips from those
// edges make it Delaunay again (constrained edges stay), with no removal, location or
// insertion: what a drag or an animation frame mostly asks for.
#include "delaunay/delaunay.h"
#include "geocdt/predicates.h"

namespace geocdt {

bool Delaunay::shiftVertex(std::uint32_t v, std::int32_t out, double x, double y) {
  const double* p = xy.data();
  // Around v counter-clockwise: e = v -> a in triangle (v, a, b), then v -> b.
  std::int32_t e = out;
  do {
    const std::uint32_t a = topo.tri[nextEdge(e)], b = topo.tri[prevEdge(e)];
    if (a == kGhost || b == kGhost) return false;  // a hull vertex
    if (orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y) != Sign::Positive)
      return false;
    e = topo.adj[prevEdge(e)];
  } while (e != out);
  xy[2 * static_cast<std::size_t>(v)] = x;
  xy[2 * static_cast<std::size_t>(v) + 1] = y;
  stack_.clear();
  do {
    stack_.push_back(e);            // the spoke v -> a
    stack_.push_back(nextEdge(e));  // the border edge a -> b
    e = topo.adj[prevEdge(e)];
  } while (e != out);
  restoreDelaunay();
  return true;
}

}  // namespace geocdt
