#pragma once
// Constraints under editing: a segment taken off its chain, a vertex removed from the chains
// that pass through it, and what is left inserted again.
//
// A segment's chain is found by following the constrained edges that name it from its first
// vertex; the segment leaves each of them, and an edge that names nothing more becomes free.
// A vertex that chains pass through (a crossing, a point lying on a segment, a Steiner
// point) takes them with it: the two edges of each chain at it are joined into one piece,
// from the vertex before to the vertex after, which is inserted again once every vertex due
// to go is gone, so that a crossing is computed again from the input segments, exactly as
// inserting them afresh does.
#include <cstdint>
#include <vector>

#include "constraints/segment_inserter.h"
#include "delaunay/delaunay.h"
#include "delaunay/vertex_edges.h"
#include "mesh/edge_map.h"

namespace geocdt {

class ConstraintEditor {
 public:
  ConstraintEditor(Delaunay& d, VertexEdges& ends) : d_(d), ends_(ends) {}

  // Takes segment s off every edge of its chain (or off the pending segments while there are
  // no triangles); edges left with nothing are freed and go on the flip stack (restore()
  // flips them). The chain's vertices, ends included, are appended to `vertices`.
  void detachSegment(std::uint32_t s, std::vector<std::uint32_t>& vertices);
  void restore() { d_.restoreDelaunay(); }

  // Removes vertex v from the triangulation: every chain through it is joined into a piece
  // that skips it. Fails (a broken invariant) when v ends a segment still there, or when a
  // segment's edges at v do not pair up (unpaired()).
  Status removeVertex(std::uint32_t v, bool moving = false);
  // Whether a removal met a segment with other than two edges at the vertex: in a tangle a
  // few ulps wide, where chains share stretches, an edge may name a segment whose chain only
  // touches it. Such chains are not spliced; the caller inserts the constraints again.
  bool unpaired() const { return unpaired_; }

  // Queues segment s to be inserted whole (one of its ends moved).
  void queueSegment(std::uint32_t s);

  // Inserts the pieces and segments queued, or hands them to the pending segments while
  // there are no triangles. GaveUp: the caller snap-rounds (see SegmentInserter).
  Outcome insertQueued();
  const Status& error() const { return error_; }
  // The input segments whose new chains met a crossing or passed a vertex on them.
  const std::vector<std::uint32_t>& touchedSegments() const { return touched_; }
  bool queued() const { return live_ > 0; }

 private:
  struct Piece {
    std::uint32_t u, w;
    EdgeSource src;  // one pair: its segment, polyline and winding from u to w
    bool live;
  };
  // One end of a chain at a removed vertex: the vertex beyond and the winding toward it.
  struct Link {
    std::uint32_t segment, polyline, other;
    std::int32_t winding;  // the pair's winding from the removed vertex to `other`
  };

  void addPiece(std::uint32_t u, std::uint32_t w, const EdgeSource& src);
  // The links of chains at v: those of its constrained edges (taken off the store and freed)
  // and those of queued pieces ending at v (which die). Returns whether an edge was freed.
  bool takeLinks(std::uint32_t v, std::int32_t out);
  void takePendingLinks(std::uint32_t v);
  Status joinLinks(std::uint32_t v);

  Delaunay& d_;
  VertexEdges& ends_;
  Status error_;
  std::vector<Piece> pieces_;
  std::size_t live_ = 0;
  // Pieces by end vertex: the head of a list through nextAtEnd_ (two entries a piece).
  EdgeMap<std::int32_t> firstAtEnd_;
  std::vector<std::int32_t> nextAtEnd_;
  std::vector<Link> links_;
  bool unpaired_ = false;
  std::vector<std::uint32_t> touched_;
  // A chain walk's scratch: vertices seen (with a half-edge out of each) and edges found.
  std::vector<std::pair<std::uint32_t, std::int32_t>> frontier_;
  std::vector<std::int32_t> found_;
  EdgeMap<std::uint8_t> seen_;
};

}  // namespace geocdt
