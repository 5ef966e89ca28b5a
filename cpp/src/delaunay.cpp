// Insertion of one point: split its triangle or edge, then Lawson flips until every edge
// around it is (constrained) Delaunay, with the ghost triangles' in-circle rule at the hull.
#include "delaunay.h"

#include <array>

#include "geocdt/predicates.h"

namespace geocdt {

void Delaunay::clear() {
  xy.clear();
  topo.clear();
  constraints.clear();
  pending_.clear();
  stack_.clear();
  built_ = false;
  last_ = -1;
  grid_ = PointGrid();
  stats = Stats();
}
std::uint32_t Delaunay::insertVertex(std::uint32_t v) {
  const double x = xy[2 * v], y = xy[2 * v + 1];
  // The first point of a batch has no useful last triangle, nor has any point of a small
  // batch (its points lie far apart): the grid knows better.
  const bool fromGrid = options_.start == LocateStart::Grid || batchStart_ || smallBatch_;
  batchStart_ = false;
  const Hit h = locate(x, y, fromGrid);
  switch (h.kind) {
    case Hit::Kind::Vertex: ++stats.duplicates; return topo.tri[h.edge];
    case Hit::Kind::Face:
    case Hit::Kind::Outside: insertInFace(h.edge / 3, v); break;
    case Hit::Kind::Edge:
      if (topo.fixed[h.edge]) {
        // On a constrained edge: its halves carry what it carried. Inside a batch, v's id is
        // still a working one, so the store learns of it when the batch ends.
        const std::array<std::uint32_t, 3> split{topo.tri[h.edge], topo.tri[nextEdge(h.edge)], v};
        if (inBatch_) {
          splits_.push_back(split);
        } else {
          constraints.split(split[0], split[1], split[2]);
        }
      }
      splitEdge(h.edge, v);
      break;
    case Hit::Kind::Empty:
    case Hit::Kind::Failed:
      error_ = {
          StatusCode::InternalError,
          "point location failed for vertex " + std::to_string(v) + ": a broken triangulation", v};
      return kGhost;
  }
  ++stats.inserted;
  grid_.grow(stats.inserted);
  return v;
}

std::int32_t Delaunay::insertInFace(std::int32_t t, std::uint32_t v) {
  const std::int32_t e0 = 3 * t;
  const std::uint32_t a = topo.tri[e0], b = topo.tri[e0 + 1], c = topo.tri[e0 + 2];
  const std::int32_t n1 = topo.adj[e0 + 1], n2 = topo.adj[e0 + 2];
  const std::uint8_t f1 = topo.fixed[e0 + 1], f2 = topo.fixed[e0 + 2];
  const std::int32_t t1 = topo.addTriangle(b, c, v);
  const std::int32_t t2 = topo.addTriangle(c, a, v);
  topo.setTriangle(t, a, b, v);
  topo.link(3 * t1, n1);
  topo.fixed[3 * t1] = f1;
  topo.link(3 * t2, n2);
  topo.fixed[3 * t2] = f2;
  topo.link(e0 + 1, 3 * t1 + 2);
  topo.link(3 * t1 + 1, 3 * t2 + 2);
  topo.link(3 * t2 + 1, e0 + 2);
  topo.fixed[e0 + 1] = topo.fixed[e0 + 2] = 0;
  last_ = t;
  stack_.push_back(e0);
  stack_.push_back(3 * t1);
  stack_.push_back(3 * t2);
  legalize();
  return edgeFrom(t, v);
}

std::int32_t Delaunay::splitEdge(std::int32_t e, std::uint32_t v) {
  // e = a->b in (a, b, c); f = b->a in (b, a, d).
  const std::int32_t f = topo.adj[e];
  const std::int32_t e1 = nextEdge(e), e2 = prevEdge(e), f1 = nextEdge(f), f2 = prevEdge(f);
  const std::uint32_t a = topo.tri[e], b = topo.tri[f], c = topo.tri[e2], d = topo.tri[f2];
  const std::int32_t ne1 = topo.adj[e1], ne2 = topo.adj[e2], nf1 = topo.adj[f1], nf2 = topo.adj[f2];
  const std::uint8_t fe = topo.fixed[e], fe1 = topo.fixed[e1], fe2 = topo.fixed[e2];
  const std::uint8_t ff1 = topo.fixed[f1], ff2 = topo.fixed[f2];
  const std::int32_t tA = e / 3, tB = f / 3;
  // (c, a, v) and (a, d, v) keep the old slots; (b, c, v) and (d, b, v) are new.
  topo.setTriangle(tA, c, a, v);
  topo.setTriangle(tB, a, d, v);
  const std::int32_t tC = topo.addTriangle(b, c, v);
  const std::int32_t tD = topo.addTriangle(d, b, v);
  const std::int32_t A = 3 * tA, B = 3 * tB, C = 3 * tC, D = 3 * tD;
  topo.link(A, ne2);
  topo.fixed[A] = fe2;
  topo.link(B, nf1);
  topo.fixed[B] = ff1;
  topo.link(C, ne1);
  topo.fixed[C] = fe1;
  topo.link(D, nf2);
  topo.fixed[D] = ff2;
  topo.link(A + 1, B + 2);  // a->v with v->a
  topo.link(A + 2, C + 1);  // v->c with c->v
  topo.link(C + 2, D + 1);  // v->b with b->v
  topo.link(D + 2, B + 1);  // v->d with d->v
  topo.fixed[A + 1] = topo.fixed[B + 2] = fe;
  topo.fixed[C + 2] = topo.fixed[D + 1] = fe;
  topo.fixed[A + 2] = topo.fixed[C + 1] = topo.fixed[D + 2] = topo.fixed[B + 1] = 0;
  last_ = tA;
  stack_.push_back(A);
  stack_.push_back(B);
  stack_.push_back(C);
  stack_.push_back(D);
  legalize();
  return edgeFrom(tA, v);
}

std::int32_t Delaunay::edgeFrom(std::int32_t t, std::uint32_t v) const {
  for (int k = 0; k < 3; ++k)
    if (topo.tri[3 * t + k] == v) return 3 * t + k;
  return -1;
}

bool Delaunay::beyondGhostEdge(std::int32_t r, std::uint32_t v) const {
  const double* p = xy.data();
  const std::uint32_t u = topo.tri[r], w = topo.tri[nextEdge(r)];
  return orient2d(p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1], p[2 * v], p[2 * v + 1]) ==
         Sign::Positive;
}

bool Delaunay::isLocallyDelaunay(std::int32_t e) const {
  const std::int32_t f = topo.adj[e];
  const std::uint32_t x = topo.tri[e], y = topo.tri[nextEdge(e)];
  const std::uint32_t v = topo.tri[prevEdge(e)], d = topo.tri[prevEdge(f)];
  if (v == kGhost || d == kGhost || x == kGhost || y == kGhost) {
    if (v == kGhost) return true;  // both sides ghost-facing: the hull rule is checked from d
    // The neighbour (y, x, d) is a ghost triangle: v must not lie beyond its real edge.
    const std::int32_t r = d == kGhost ? f : (x == kGhost ? prevEdge(f) : nextEdge(f));
    return !beyondGhostEdge(r, v);
  }
  const double* p = xy.data();
  return incircle(p[2 * y], p[2 * y + 1], p[2 * x], p[2 * x + 1], p[2 * d], p[2 * d + 1], p[2 * v],
                  p[2 * v + 1]) != Sign::Positive;
}

void Delaunay::legalize() {
  while (!stack_.empty()) {
    const std::int32_t e = stack_.back();
    stack_.pop_back();
    if (topo.fixed[e] || isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo.adj[e];
    topo.flip(e);
    ++stats.flips;
    stack_.push_back(e);
    stack_.push_back(nextEdge(f));
  }
}

void Delaunay::restoreDelaunay() {
  while (!stack_.empty()) {
    const std::int32_t e = stack_.back();
    stack_.pop_back();
    if (topo.fixed[e] || isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo.adj[e];
    topo.flip(e);
    ++stats.flips;
    stack_.push_back(e);
    stack_.push_back(nextEdge(e));
    stack_.push_back(f);
    stack_.push_back(nextEdge(f));
  }
}

}  // namespace geocdt
