#pragma once
// Inserts one constraint segment into a triangulation, after Anglada: walk along it from
// one end; a vertex lying on it splits it; a constrained edge crossing it is split at the
// crossing point (computed from the original input segments, validated exactly, snapped to a
// vertex only when it equals one); the unconstrained edges crossed are flipped away (Sloan)
// and Delaunay is restored around them by Lawson flips.
#include <cstdint>
#include <deque>
#include <vector>

#include "delaunay.h"
#include "edge_map.h"

namespace geocdt {

class SegmentInserter {
 public:
  explicit SegmentInserter(Delaunay& d) : d_(d) {}

  // Inserts u -> v carrying src. On failure the status names nothing: the caller adds the
  // polyline and segment.
  Status insert(std::uint32_t u, std::uint32_t v, const EdgeSource& src);

 private:
  struct Piece {
    std::uint32_t a, b;
    EdgeSource src;
  };
  struct Walk {
    std::uint32_t reached = kGhost;  // the vertex where the walk stopped on the segment
    std::int32_t existing = -1;      // a half-edge a -> reached when it already exists
    std::int32_t blocking = -1;      // a constrained half-edge crossing the segment
  };

  Walk walk(std::uint32_t a, std::uint32_t b);
  std::int32_t edgeOutOf(std::uint32_t a);
  std::int32_t findEdge(std::uint32_t u, std::uint32_t v);  // half-edge u -> v, or -1
  void markConstrained(std::int32_t e, const EdgeSource& src);
  bool flipIn(std::uint32_t a, std::uint32_t w, const EdgeSource& src);
  // Resolves a crossing with constrained half-edge h; returns the vertex where the piece
  // must now pass, or kGhost when the crossed constraint was re-routed instead.
  std::uint32_t resolveCrossing(const Piece& piece, std::int32_t h);

  Delaunay& d_;
  std::vector<Piece> pieces_;
  struct QueuedEdge {
    std::uint32_t u, v;
    std::int32_t hint;  // where u -> v was last seen; flips elsewhere may move it
  };
  std::vector<std::int32_t> crossed_, touched_;
  std::deque<QueuedEdge> queue_;
  std::int32_t hint_ = -1;
  EdgeMap<std::uint32_t> met_;  // input segment pair -> the vertex where they cross  // a half-edge
                                // out of where the next piece likely starts
};

}  // namespace geocdt
