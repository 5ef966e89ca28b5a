#pragma once
// Whether a cell lies inside the domain, for the cells that no boundary piece crosses: such a
// cell is wholly inside or wholly outside. Rings: by the winding number of one of its corners
// (vertex_windings.h). A box or the sites' hull, one convex loop: by its site, which lies inside
// its own cell and, the cell being uncut, not on the boundary (a site on it would put a piece in
// its cell); and a cell holding the whole loop, which never leaves it, is outside.
#include <cstdint>
#include <vector>

#include "voronoi/site_diagram.h"

namespace geocdt {

class CellSides {
 public:
  static CellSides ofWindings(const SiteDiagram& diagram, std::vector<std::int8_t> windings) {
    CellSides s(diagram, Kind::Windings);
    s.windings_ = std::move(windings);
    return s;
  }
  static CellSides ofBox(const SiteDiagram& diagram, const double box[4]) {
    CellSides s(diagram, Kind::Box);
    for (int i = 0; i < 4; ++i) s.box_[i] = box[i];
    return s;
  }
  static CellSides ofHull(const SiteDiagram& diagram) { return CellSides(diagram, Kind::Hull); }

  // A cell with no piece of boundary in it.
  bool uncutInside(std::uint32_t v) const {
    switch (kind_) {
      case Kind::Windings: return windings_[diagram_->outEdge(v) / 3] != 0;
      case Kind::Box: {
        const XY p = diagram_->point(v);
        return p.x > box_[0] && p.x < box_[2] && p.y > box_[1] && p.y < box_[3];
      }
      case Kind::Hull: return true;  // every site lies in the hull, uncut ones strictly
    }
    return false;
  }
  // A cell whose only pieces are loops that never leave it: where its edges are.
  bool loopsOnlyInside(std::uint32_t v) const {
    return kind_ == Kind::Windings && windings_[diagram_->outEdge(v) / 3] != 0;
  }

 private:
  enum class Kind : std::uint8_t { Windings, Box, Hull };
  CellSides(const SiteDiagram& diagram, Kind kind) : diagram_(&diagram), kind_(kind) {}

  const SiteDiagram* diagram_;
  Kind kind_;
  std::vector<std::int8_t> windings_;
  double box_[4] = {0, 0, 0, 0};
};

}  // namespace geocdt
