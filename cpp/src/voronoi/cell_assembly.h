#pragma once
// The clipped cell of a site that the boundary enters. Counter-clockwise along the cell's
// edges, the crossings alternate: after a piece of boundary leaves the cell, the cell's edge
// runs inside the domain (the domain is on the boundary's left) until the next piece enters.
// So from each piece, its exit, the cell's edge to the next entry, that piece, and so on close
// a ring counter-clockwise around part of the cell. Loops that never leave the cell are islands
// (counter-clockwise) or holes (clockwise); a hole goes to the innermost ring around it.
#include <cstdint>
#include <vector>

#include "geocdt/status.h"
#include "voronoi/boundary_walk.h"
#include "voronoi/cell_polygons.h"
#include "voronoi/cell_sides.h"
#include "voronoi/domain.h"
#include "voronoi/site_diagram.h"

namespace geocdt {

class CellAssembler {
 public:
  CellAssembler(const Domain& domain, const SiteDiagram& diagram, const BoundaryWalk& walk,
                const CellSides& sides)
      : domain_(domain), diagram_(diagram), walk_(walk), sides_(sides) {}

  // Appends the polygons of cell v, whose pieces are walk.pieces[pieces[0 .. count)], to out.
  Status assemble(std::uint32_t v, const std::int32_t* pieces, std::size_t count,
                  CellPolygons& out);

 private:
  struct Event {
    std::int32_t piece;     // index into pieces_
    std::int32_t crossing;  // index into walk.crossings
    std::int32_t rank;      // of its edge around the cell
    bool exit;
  };
  struct Ring {
    std::uint32_t begin, end;  // in scratch_, not closed
    double area;
    XY low, high;
    std::int32_t container = -1;  // holes: the ring that holds them
  };

  void collectEdges(std::uint32_t v);
  std::int32_t rankOf(std::int32_t outEdge) const;
  bool eventBefore(const Event& a, const Event& b) const;
  Status sortEvents();
  Status traceRings();
  void emitCorners(std::int32_t fromRank, std::int32_t toRank, bool allAround);
  void emitPiece(const Piece& p);
  void addLoops();
  void addWholeCell(std::uint32_t v);
  std::uint32_t finishRing(std::uint32_t begin);
  bool holds(const Ring& outer, const Ring& inner) const;
  void placeHoles();
  void write(CellPolygons& out) const;

  const Domain& domain_;
  const SiteDiagram& diagram_;
  const BoundaryWalk& walk_;
  const CellSides& sides_;

  XY site_;
  std::vector<std::int32_t> edges_;  // out-edges of the cell's site, counter-clockwise
  std::vector<const Piece*> pieces_;
  std::vector<Event> events_;
  std::vector<std::int32_t> exitAt_;  // position of each piece's exit among events_
  std::vector<XY> scratch_;
  std::vector<Ring> rings_;
  std::vector<std::uint8_t> isOuter_;
};

}  // namespace geocdt
