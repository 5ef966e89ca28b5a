#include "voronoi/boundary_walk.h"

#include "voronoi/crossing_point.h"
#include "voronoi/perturbation.h"

namespace geocdt {
namespace {

class Walker {
 public:
  Walker(const Domain& domain, SiteDiagram& diagram, BoundaryWalk& out)
      : domain_(domain), diagram_(diagram), out_(out) {}

  Status walkLoop(std::uint32_t loop) {
    const std::uint32_t begin = domain_.loopOffsets[loop], end = domain_.loopOffsets[loop + 1];
    cell_ = diagram_.nearest(domain_.points[begin]);
    const auto firstPiece = static_cast<std::int32_t>(out_.pieces.size());
    openPiece(-1, loop, begin);
    out_.pieces.back().count = 1;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t next = k + 1 == end ? begin : k + 1;
      const Status s = walkSegment(k, next, loop);
      if (!s.ok()) return s;
      if (next != begin) ++out_.pieces.back().count;
    }
    return closeLoop(firstPiece);
  }

 private:
  void openPiece(std::int32_t entry, std::uint32_t loop, std::uint32_t first) {
    Piece p;
    p.cell = diagram_.origin(cell_);
    p.entry = entry;
    p.loop = loop;
    p.first = first;
    out_.pieces.push_back(p);
  }

  // The segment from point `from` to point `to`, from the current cell to the one holding
  // `to`: each cell's exit is the bisector, among those `to` lies beyond, that the segment
  // meets first.
  Status walkSegment(std::uint32_t from, std::uint32_t to, std::uint32_t loop) {
    const XY p = domain_.points[from], q = domain_.points[to];
    for (std::uint32_t steps = 0; steps <= diagram_.vertexCount(); ++steps) {
      const XY c = diagram_.point(diagram_.origin(cell_));
      std::int32_t exit = -1;
      XY exitSite;
      std::int32_t f = cell_;
      do {
        const std::uint32_t t = diagram_.target(f);
        if (t != kGhost) {
          const XY site = diagram_.point(t);
          if (nearerTo(c, site, q) && (exit < 0 || crossesFirst(c, site, exitSite, p, q))) {
            exit = f;
            exitSite = site;
          }
        }
        f = diagram_.turn(f);
      } while (f != cell_);
      if (exit < 0) return Status::success();
      cross(exit, c, exitSite, from, to, loop);
    }
    return {StatusCode::InternalError,
            "voronoi: a boundary segment did not reach the cell of its end"};
  }

  void cross(std::int32_t edge, XY c, XY t, std::uint32_t from, std::uint32_t to,
             std::uint32_t loop) {
    const CrossingPoint point = crossingPoint(c, t, domain_.points[from], domain_.points[to]);
    Crossing x;
    x.edge = edge;
    x.at = point.at;
    x.error = point.error;
    x.from = from;
    x.to = to;
    const auto index = static_cast<std::int32_t>(out_.crossings.size());
    x.leaving = static_cast<std::int32_t>(out_.pieces.size()) - 1;
    x.entering = x.leaving + 1;
    out_.crossings.push_back(x);
    out_.pieces.back().exit = index;
    ++out_.windingStep[edge];
    --out_.windingStep[diagram_.twin(edge)];
    cell_ = diagram_.twin(edge);
    openPiece(index, loop, to);
  }

  // The last piece ends where the first began (in the cell of the loop's first vertex): they
  // become one, kept in the first one's place.
  Status closeLoop(std::int32_t firstPiece) {
    Piece& first = out_.pieces[firstPiece];
    if (static_cast<std::int32_t>(out_.pieces.size()) == firstPiece + 1) return Status::success();
    const Piece last = out_.pieces.back();
    if (last.cell != first.cell)
      return {StatusCode::InternalError, "voronoi: a boundary loop did not close in its cell"};
    first.entry = last.entry;
    first.first = last.first;
    first.count += last.count;
    out_.crossings[last.entry].entering = firstPiece;
    out_.pieces.pop_back();
    return Status::success();
  }

  const Domain& domain_;
  SiteDiagram& diagram_;
  BoundaryWalk& out_;
  std::int32_t cell_ = -1;  // a half-edge out of the current cell's site
};

}  // namespace

Status walkBoundary(const Domain& domain, SiteDiagram& diagram, BoundaryWalk& out) {
  out.crossings.clear();
  out.pieces.clear();
  out.windingStep.assign(diagram.topo().tri.size(), 0);
  Walker walker(domain, diagram, out);
  for (std::uint32_t loop = 0; loop < domain.loopCount(); ++loop) {
    const Status s = walker.walkLoop(loop);
    if (!s.ok()) return s;
  }
  return Status::success();
}

}  // namespace geocdt
