#pragma once
// Inserts one constraint segment into a triangulation, after Anglada: walk along it from
// one end; a vertex lying on it splits it; a constrained edge crossing it is split at the
// crossing point (computed from the original input segments, validated exactly, snapped to a
// vertex only when it equals one); the unconstrained edges crossed are flipped away (Sloan)
// and Delaunay is restored around them by Lawson flips.
#include <cstdint>
#include <deque>
#include <vector>

#include "base/chunks.h"
#include "delaunay/delaunay.h"
#include "delaunay/vertex_edges.h"
#include "mesh/edge_map.h"

namespace geocdt {

// How a constrained edge that the segment crosses is met.
enum class Crossings : std::uint8_t {
  // At the crossing of the two input segments, computed and checked to fit (the usual way,
  // which can get lost in tangles of vertices a few ulps apart: it then gives up).
  Computed,
  // At the snap-rounded crossing of the two edges: for the links of snap-rounded chains,
  // which should never cross, so this only mends what the rounding grid's seams leave.
  Snapped,
};

// What insert() did.
enum class Outcome : std::uint8_t {
  Inserted,
  GaveUp,  // the Computed way went round in circles: the caller snap-rounds instead
  Broken,  // a broken invariant: error() says which
};

class SegmentInserter {
 public:
  // Segments start from their end vertices' half-edges in ends, which the inserter keeps
  // up to date where it changes the triangles.
  SegmentInserter(Delaunay& d, VertexEdges& ends, Crossings crossings = Crossings::Computed)
      : d_(d), ends_(ends), crossings_(crossings) {}

  // Inserts u -> v carrying src.
  Outcome insert(std::uint32_t u, std::uint32_t v, const EdgeSource& src);
  const Status& error() const { return error_; }
  // The input segments whose constraints met a crossing, or passed through a vertex on them,
  // since the last clearTouchedSegments(): the only ones whose chains may have left their
  // segment or met another chain where their segments do not meet.
  const std::vector<std::uint32_t>& touchedSegments() const { return touchedSegments_; }
  void clearTouchedSegments() { touchedSegments_.clear(); }

 private:
  struct Piece {
    std::uint32_t a, b;
    EdgeSource src;
  };
  struct Walk {
    std::uint32_t reached = kGhost;  // the vertex where the walk stopped on the segment
    std::int32_t existing = -1;      // a half-edge a -> reached when it already exists
    std::int32_t blocking = -1;      // a constrained half-edge crossing the segment
    std::uint32_t via = kGhost;      // a vertex exactly on `onto`, off the piece (below)
  };

  // walk, chainBendsAt, flipIn and the crossings' functions below are functions of their own:
  // inlined, insert() grew so large that V8 optimised it late in a first call, which ran it
  // in baseline code meanwhile (bench/EXPERIMENTS.md, F21).
  // onto: the piece's input segment when a lies off it (a rounded crossing), else null; the
  // walk then stops at a vertex exactly on it, ahead of a and not past b, if it meets one.
  GEOCDT_NOINLINE Walk walk(std::uint32_t a, std::uint32_t b, const InputSegment* onto);
  std::int32_t edgeOutOf(std::uint32_t a);
  // Whether a constrained edge at v holds a segment that does not pass through v exactly
  // (ends included): a chain bent through v.
  GEOCDT_NOINLINE bool chainBendsAt(std::uint32_t v);
  // Whether piece.a lies off the piece's input segment, written to g (false without one).
  bool offSegment(const Piece& piece, InputSegment& g) const;
  // Whether vertex v lies exactly on g, ahead of (px, py) along it and not past (qx, qy).
  bool onAndBetween(const InputSegment& g, std::uint32_t v, double px, double py, double qx,
                    double qy) const;
  // A half-edge out of piece.a, which lies off the input segment g (a crossing rounded it
  // there), to the nearest vertex exactly on g ahead of it and not past piece.b; else -1.
  // Going back onto the segment there keeps this chain on a collinear chain inserted
  // before, which then names both, instead of passing it on the other side.
  GEOCDT_NOINLINE std::int32_t edgeBackOntoSegment(const Piece& piece, const InputSegment& g);
  std::int32_t findEdge(std::uint32_t u, std::uint32_t v);  // half-edge u -> v, or -1
  void markConstrained(std::int32_t e, const EdgeSource& src);
  GEOCDT_NOINLINE bool flipIn(std::uint32_t a, std::uint32_t w, const EdgeSource& src);
  // A piece crossing constrained half-edge h = r -> l, whose triangles' apexes are c1 and c2,
  // and the input segments ab and cd of the two.
  struct Crossing {
    Piece piece;
    std::int32_t h;
    std::uint32_t r, l, c1, c2;
    InputSegment ab, cd;
    std::uint64_t pair;  // the two input segments' key

    // Whether (x, y) lies beyond vertex u along g's direction (sign), between lo and hi.
    static int beyond(const double* p, const InputSegment& g, double x, double y, std::uint32_t u);
    static bool between(const double* p, const InputSegment& g, double x, double y,
                        std::uint32_t lo, std::uint32_t hi);
    // Whether (x, y) lies between the piece's ends along ab and the edge's along cd.
    bool fits(const double* p, double x, double y) const;
  };
  // Resolves a crossing with constrained half-edge h (computed_crossing.cpp); returns the
  // vertex where the piece must now pass, or kGhost when the crossed constraint was
  // re-routed instead. Its steps: split the crossed edge at the rounded crossing, route
  // both through one vertex, or meet at an end (whose (x, y) is the crossing last tried).
  GEOCDT_NOINLINE std::uint32_t resolveCrossing(const Piece& piece, std::int32_t h);
  std::uint32_t split(const Crossing& c, double x, double y);
  std::uint32_t meetAtAnEnd(const Crossing& c, double x, double y);
  // The same in Crossings::Snapped mode (snap_rounding.cpp): the piece (on top of the stack)
  // and the crossed link are replaced by their bent links. False with error_ set when no
  // vertex keeps the guarantee (never seen) or the crossing could not be inserted.
  GEOCDT_NOINLINE bool snapCrossing(const Piece& piece, std::int32_t h);
  // A vertex at (x, y): a new one, or the one already there; failed when location failed.
  std::uint32_t addCrossingVertex(double x, double y, bool& failed);
  // The constrained edge r-l, if it still is one, becomes the pieces r -> w -> l to insert.
  void bendThrough(std::uint32_t r, std::uint32_t l, std::uint32_t w);
  // The same through path[1 .. count - 2], from r = path[0] to l = path[count - 1].
  void bendAlong(const std::uint32_t* path, std::size_t count);
  // Whether bending link u -> v through (wx, wy) passes over a vertex: one in the closed
  // triangle u, w, v other than its corners (snap_rounding.cpp).
  bool bendSweepsAVertex(std::uint32_t u, double wx, double wy, std::uint32_t v);
  // Link u -> v of segment g bent through w, with the vertices that would otherwise change
  // sides of it (those between g and u -> w or w -> v) on the way (snap_rounding.cpp).
  std::vector<std::uint32_t> bentLink(const InputSegment& g, std::uint32_t u, std::uint32_t w,
                                      std::uint32_t v);
  Outcome broken(const char* what);

  Delaunay& d_;
  VertexEdges& ends_;
  Crossings crossings_;
  Status error_;
  std::vector<std::uint32_t> touchedSegments_;
  std::vector<Piece> pieces_;
  struct QueuedEdge {
    std::uint32_t u, v;
    std::int32_t hint;  // where u -> v was last seen; flips elsewhere may move it
  };
  std::vector<std::int32_t> crossed_, touched_;
  std::deque<QueuedEdge> queue_;
  std::int32_t hint_ = -1;      // a half-edge out of where the next piece likely starts
  EdgeMap<std::uint32_t> met_;  // input segment pair -> the vertex where they cross
};

}  // namespace geocdt
