#include "voronoi/domain.h"

#include <algorithm>

namespace geocdt {
namespace {

std::int32_t nextHalfEdge(std::int32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }

// Twice the signed area of triangle abc, from differences (exact for the unit square).
double twiceArea(XY a, XY b, XY c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// The mesh's boundary: half-edges with an inside triangle on their left and an outside one
// (or none) on their right.
class MeshBoundary {
 public:
  explicit MeshBoundary(const Mesh& m) : m_(m) {}

  bool isBoundary(std::int32_t e) const {
    if (!m_.inside[e / 3]) return false;
    const std::int32_t twin = m_.halfedges[e];
    return twin < 0 || !m_.inside[twin / 3];
  }

  // The boundary half-edge after e (which ends at v): turning clockwise around v through
  // inside triangles from e's triangle, the first boundary half-edge out of v. So a loop that
  // meets others at v keeps to its own side of them.
  std::int32_t after(std::int32_t e) const {
    std::int32_t f = nextHalfEdge(e);
    while (!isBoundary(f)) f = nextHalfEdge(m_.halfedges[f]);
    return f;
  }

  XY point(std::int32_t e) const {
    const std::uint32_t v = m_.triangles[e];
    return {m_.points[2 * v], m_.points[2 * v + 1]};
  }

 private:
  const Mesh& m_;
};

void boundsOf(Domain& d) {
  if (d.points.empty()) return;
  d.minX = d.maxX = d.points[0].x;
  d.minY = d.maxY = d.points[0].y;
  for (const XY p : d.points) {
    d.minX = std::min(d.minX, p.x);
    d.maxX = std::max(d.maxX, p.x);
    d.minY = std::min(d.minY, p.y);
    d.maxY = std::max(d.maxY, p.y);
  }
}

}  // namespace

void Domain::addLoop(const std::vector<XY>& loop) {
  points.insert(points.end(), loop.begin(), loop.end());
  loopOffsets.push_back(static_cast<std::uint32_t>(points.size()));
}

Domain boxDomain(const double box[4]) {
  Domain d;
  d.addLoop({{box[0], box[1]}, {box[2], box[1]}, {box[2], box[3]}, {box[0], box[3]}});
  d.area = (box[2] - box[0]) * (box[3] - box[1]);
  boundsOf(d);
  return d;
}

Domain convexDomain(const std::vector<XY>& hull) {
  Domain d;
  if (hull.size() < 3) return d;
  d.addLoop(hull);
  for (std::size_t i = 1; i + 1 < hull.size(); ++i)
    d.area += 0.5 * twiceArea(hull[0], hull[i], hull[i + 1]);
  boundsOf(d);
  return d;
}

Status ringDomain(const PolylineView* rings, std::size_t count, FillRule fill,
                  std::uint32_t threads, Domain& out) {
  out = Domain();
  Options options;
  options.threads = threads;
  Triangulation t(options);
  const Status s = t.insertPolylines(rings, count);
  if (!s.ok()) return s;
  MeshOptions meshOptions;
  meshOptions.insideFlags = true;
  meshOptions.fill = fill;
  const Mesh m = t.release(meshOptions);
  const MeshBoundary boundary(m);
  const auto halfEdges = static_cast<std::int32_t>(m.triangles.size());
  for (std::int32_t e = 0; e < halfEdges; e += 3)
    if (m.inside[e / 3]) {
      const XY a = boundary.point(e), b = boundary.point(e + 1), c = boundary.point(e + 2);
      out.area += 0.5 * twiceArea(a, b, c);
    }
  std::vector<std::uint8_t> traced(m.triangles.size(), 0);
  std::vector<XY> loop;
  for (std::int32_t e = 0; e < halfEdges; ++e) {
    if (traced[e] || !boundary.isBoundary(e)) continue;
    loop.clear();
    for (std::int32_t f = e; !traced[f]; f = boundary.after(f)) {
      traced[f] = 1;
      loop.push_back(boundary.point(f));
    }
    out.addLoop(loop);
  }
  boundsOf(out);
  return Status::success();
}

}  // namespace geocdt
