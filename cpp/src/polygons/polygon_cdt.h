#pragma once
// The constrained Delaunay triangulation of one polygon's rings, for the polygons that make up
// nearly all of a map tile: no grid, no sort, no allocation once its scratch arrays have
// grown. The points go in along the rings, each located by a walk from the triangle of the
// one before (its neighbour on the ring); the ring segments go in by flips, as the core's
// SegmentInserter does, split at any vertex exactly on them; a flood from the ghost triangles
// counts the windings. Every decision is an exact predicate.
//
// It refuses, and leaves the polygon to the general engine, wherever it would need more than
// that: two ring segments that cross (a new vertex), more flips than it budgets for (an
// insertion order that ring order makes quadratic), an edge that rings run along more than 63
// times, or any broken expectation. Refusing costs only the work done so far.
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"
#include "mesh/topology.h"

namespace geocdt {

class PolygonCdt {
 public:
  // The polygon's points are xy[0 .. 2n), its rings the local offsets ringStarts[0 ..
  // ringCount] (ringStarts[0] = 0, ringStarts[ringCount] = n). On success appends the inside
  // triangles, counter-clockwise, as indices base + (local index of a point) to out and
  // returns true; returns false (out as it was) when the polygon needs the general engine.
  bool triangulate(const double* xy, std::uint32_t n, const std::uint32_t* ringStarts,
                   std::uint32_t ringCount, FillRule fill, std::uint32_t base,
                   std::vector<std::uint32_t>& out);

 private:
  bool insertPoints();
  bool insertPoint(std::uint32_t k);
  // Visibility walk from last_ to (x, y): a half-edge of where it lies and what that is
  // (0 face or outside, 1 edge, 2 vertex), or -1 when the walk fails.
  template <bool kIntegers>
  std::int32_t locate(double x, double y, int& kind) const;
  void splitFace(std::int32_t t, std::uint32_t p);
  void splitEdge(std::int32_t e, std::uint32_t p);
  // kIntegers: the polygon's coordinates are small integers (exact/small_integer_predicates.h).
  template <bool kIntegers>
  void legalize(std::uint32_t p);
  void pushLawson(std::int32_t e);

  bool insertSegments();
  bool insertSegment(std::uint32_t u, std::uint32_t v);
  // One more ring traversal along half-edge e (see traverse in the .cpp); false past 63.
  bool traverse(std::int32_t e);
  // Walks from u (start: a half-edge out of it) toward v, collecting the half-edges crossed
  // into crossed_, to the first vertex on the segment: v, or one exactly on it (existing:
  // the half-edge u -> it when it is a neighbour of u). kGhost where a constrained edge
  // crosses the way (rings that cross) or the walk fails.
  std::uint32_t walkSegment(std::uint32_t u, std::uint32_t v, std::int32_t start,
                            std::int32_t& existing);
  // Flips the crossed edges away until u -> w is an edge, constrains it, and restores the
  // constrained Delaunay property around the flips.
  bool flipIn(std::uint32_t u, std::uint32_t w);
  bool restoreDelaunay();
  bool isLocallyDelaunay(std::int32_t e) const;
  void flip(std::int32_t e);
  std::int32_t findEdge(std::uint32_t u, std::uint32_t v) const {
    return topo_.edgeAround(edgeOut_[u], v);
  }

  void countWindings(FillRule fill, std::uint32_t base, std::vector<std::uint32_t>& out);

  const double* p_ = nullptr;
  std::uint32_t n_ = 0;
  const std::uint32_t* ringStarts_ = nullptr;
  std::uint32_t ringCount_ = 0;

  Topology topo_;
  std::int32_t slots_ = 0;  // used slots of topo_
  std::int32_t last_ = 0;   // the triangle of the last insertion
  bool integers_ = false;   // small integer coordinates: the cheaper exact predicates
  std::uint64_t flips_ = 0, flipBudget_ = 0;
  std::vector<std::uint32_t> order_;     // the insertion order of a large polygon's points
  std::vector<std::uint32_t> vertexOf_;  // local point -> the local point it is the vertex of
  std::vector<std::int32_t> edgeOut_;    // vertex -> a half-edge out of it (during segments)
  std::vector<std::int32_t> lawson_;
  std::size_t lawsonTop_ = 0;
  std::vector<std::int32_t> stack_;    // edges to check after a segment's flips
  std::vector<std::int32_t> crossed_;  // half-edges a segment crosses
  struct Queued {
    std::uint32_t u, v;
    std::int32_t hint;
  };
  std::vector<Queued> queue_;          // Sloan's FIFO, with a moving head
  std::vector<std::int32_t> touched_;  // triangles a segment's flips rewrote
  std::vector<std::int32_t> winding_;  // per slot
  std::vector<std::int32_t> flood_;
};

}  // namespace geocdt
