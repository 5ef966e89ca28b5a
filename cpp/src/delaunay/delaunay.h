#pragma once
// Incremental Delaunay insertion: point location by the dynamic grid and a visibility walk,
// triangle or edge split, then Lawson flips. The hull is closed by a ghost vertex, so points
// outside the hull need no special case beyond the ghost's in-circle rule.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "base/chunks.h"
#include "delaunay/point_grid.h"
#include "delaunay/star_ring.h"
#include "geocdt/status.h"
#include "geocdt/triangulation.h"
#include "mesh/constraint_store.h"
#include "mesh/topology.h"

namespace geocdt {

class VertexEdges;

// Where a point lies in the triangulation.
struct Hit {
  enum class Kind : std::uint8_t { Empty, Face, Edge, Vertex, Outside, Failed };
  Kind kind = Kind::Empty;
  // Face: a half-edge of the containing triangle. Edge: a half-edge of that edge.
  // Vertex: a half-edge starting at the vertex. Outside: the real half-edge of a ghost
  // triangle that the point lies strictly beyond.
  std::int32_t edge = -1;
};

// A vertex added by refinement, and where it was placed (Mesh::steiner says how).
struct SteinerVertex {
  std::uint32_t vertex;
  std::uint32_t parents[3];
  double weights[3];
};

class Delaunay {
  // Storage of its own, or none when it works on a strip of another's (see xy, topo).
  std::vector<double> ownXy_;
  Topology ownTopo_;

 public:
  explicit Delaunay(const Options& options) : xy(ownXy_), topo(ownTopo_), options_(options) {}
  // A worker that triangulates one strip of owner's points into owner's arrays, in the slots
  // from firstSlot on (strip_insertion.cpp): it reads owner's xy and writes only its slots.
  Delaunay(const Options& options, Delaunay& owner, std::int32_t firstSlot)
      : xy(owner.xy), topo(owner.topo), options_(options), firstSlot_(firstSlot) {}
  Delaunay(const Delaunay&) = delete;
  Delaunay& operator=(const Delaunay&) = delete;
  // Takes other's whole state (snap rounding's fresh triangulation); both own their storage.
  // Member by member: a new member must be added there too.
  Delaunay& operator=(Delaunay&& other) noexcept;

  std::vector<double>& xy;  // 2 per vertex
  Topology& topo;
  ConstraintStore constraints;
  Stats stats;
  std::vector<SteinerVertex> steiner;

  // Four points on one circle make two Delaunay triangulations of their quad, and insertion
  // keeps the edge it finds. A caller may choose instead: asked about edge a->b, the corner d
  // beyond it and the vertex p being inserted, all four on one circle, true flips a-b to p-d.
  // Each such flip adds a spoke to p, which no later flip of the insertion takes back.
  struct CocircularChoice {
    bool (*flipToPd)(void* context, std::uint32_t a, std::uint32_t b, std::uint32_t d,
                     std::uint32_t p) = nullptr;
    void* context = nullptr;
  };
  CocircularChoice cocircular;

  bool built() const { return built_; }
  // Whether any edge is or was constrained: only then do splits and flips carry the flags;
  // without, every flag in topo.fixed is 0.
  bool constrained() const { return constraints.polylineCount > 0 || constraints.edgeCount() > 0; }
  const Options& options() const { return options_; }
  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(xy.size() / 2); }

  // Inserts count points (2 * count doubles, already validated). ids[i] receives the vertex
  // that point i became or equals. New vertices are numbered in input order after the
  // existing ones, duplicates removed.
  Status insertBatch(const double* input, std::uint32_t count, std::uint32_t* ids);
  // The same for the points of buffer, which becomes xy when there are no vertices yet
  // (no copy), else is appended and freed.
  Status insertBatch(std::vector<double>&& buffer, std::uint32_t* ids);

  // Inserts vertex v (already in xy); returns v or the existing vertex at its place.
  // Returns kGhost when location failed (an internal error, described by lastError()).
  std::uint32_t insertVertex(std::uint32_t v);

  // Inserts vertex v (already in xy) where h, a location of it, says; as insertVertex.
  std::uint32_t insertLocated(const Hit& h, std::uint32_t v);

  // Locates (x, y), starting from the grid's cell or from the last triangle.
  Hit locate(double x, double y, bool fromGrid);
  // Splits the edge of half-edge e at vertex v lying strictly inside it and restores
  // Delaunay; the halves of a constrained edge stay constrained. Returns a half-edge
  // starting at v.
  std::int32_t splitEdge(std::int32_t e, std::uint32_t v);
  // Inserts vertex v (already in xy) into a cavity by joining it to the cavity's boundary:
  // `slots` are the cavity's triangles, whose union is a disk crossed by no constrained edge
  // and star-shaped from v, and `boundary` its border's half-edges (inside it) in
  // counter-clockwise order, one more than two per slot. What Lawson flips would do, without
  // the flips, for a caller that found the cavity with its own in-circle tests (refinement's
  // Bowyer-Watson insertion). Returns the half-edge from v to the first boundary edge's start.
  std::int32_t fillStar(std::uint32_t v, const std::vector<std::int32_t>& slots,
                        const std::vector<std::int32_t>& boundary);
  // Editing (vertex_removal.cpp). Removes vertex v, none of whose edges may be constrained
  // (the caller takes its constraints first): the border of its star is cut into triangles
  // again and made Delaunay by flips, and two slots are freed. Its coordinates become NaN
  // and its id is never given again. When the vertices left are all collinear, the
  // triangulation goes back to having no triangles: its vertices wait again and its
  // constrained edges become pending segments. out: a half-edge out of v, or -1. With
  // moving, v is about to be inserted again elsewhere (reinsertVertex): not counted removed.
  // With freed, some of v's edges were constrained until the caller freed them: what was
  // hidden behind them may now be seen across the star's border, whose edges are flipped
  // too where they are no longer Delaunay. hints: a vertex-to-edge table kept across edits,
  // told where the triangles moved into the freed slots went, or null.
  Status removeVertex(std::uint32_t v, std::int32_t out = -1, bool moving = false,
                      bool freed = false, VertexEdges* hints = nullptr);
  // What removeVertex(v, out) would make of an interior vertex, without changing anything:
  // the corners of the triangles cut from its star's border, in Devillers' order (before the
  // flips that rounding or cocircular ties may still need). False for a hull vertex, one with
  // a constrained edge, or a border without an ear.
  bool plannedRemoval(std::uint32_t v, std::int32_t out, std::vector<std::uint32_t>& corners);
  // After a removal: the slots of the triangles it made, and the slots whose triangles moved
  // into the freed ones ({from, to} pairs).
  const std::vector<std::int32_t>& removalSlots() const { return ring_.made; }
  const std::vector<std::array<std::int32_t, 2>>& movedSlots() const { return ring_.moved; }
  // Moves interior vertex v to (x, y) when that lies strictly inside its star's kernel (every
  // border edge seen from the left), restoring Delaunay by flips that leave constrained edges
  // alone (vertex_shift.cpp); out: a half-edge out of v. Constrained edges at v must be whole
  // segments, which stay valid (the caller checks). False, with nothing changed, for a hull
  // vertex or a place outside the kernel.
  bool shiftVertex(std::uint32_t v, std::int32_t out, double x, double y);
  // Whether (ax, ay) lies within two cells of (bx, by) on the point-location grid (true
  // while the grid is unset): the scale of a star.
  bool withinTwoCells(double ax, double ay, double bx, double by) const {
    return grid_.empty() || grid_.near(ax, ay, bx, by);
  }
  // Inserts vertex v again, at its coordinates in xy, keeping its id (a move). Its place must
  // not hold another vertex. near: a triangle to walk from (a slot near the new place), or -1
  // for the grid. The two slots the removal kept spare take the two new triangles.
  Status reinsertVertex(std::uint32_t v, std::int32_t near = -1);
  // Into an empty triangulation: the vertices of from[0 .. 2 * count), each keeping its id,
  // but those removed (NaN), which stay removed (kept_ids.cpp). For rebuilds after edits.
  Status insertKeepingIds(const double* from, std::uint32_t count);
  bool isRemoved(std::uint32_t v) const { return std::isnan(xy[2 * static_cast<std::size_t>(v)]); }
  const std::vector<std::uint32_t>& waiting() const { return pending_; }

  // Flips non-constrained edges on the stack until each is locally Delaunay, checking all
  // four edges around each flip: for any edges, not only those around a new vertex.
  void restoreDelaunay();
  std::vector<std::int32_t>& flipStack() { return stack_; }

  bool isLocallyDelaunay(std::int32_t e) const;  // e's quad, whatever the fixed flags
  void setLastTriangle(std::int32_t t) { last_ = t; }
  std::int32_t lastTriangle() const { return last_; }  // holds the vertex inserted last
  const Status& lastError() const { return error_; }
  // The grid's side as sized for the points inserted (a stale grid is resized on first use).
  std::uint32_t gridSize() const {
    return gridStale_ ? grid_.sizeFor(stats.inserted) : grid_.size();
  }
  void dropGrid() { grid_ = PointGrid(); }  // its memory, before the arrays are handed out
  // A grid left stale by a large batch is filled from a half-edge out of each vertex (a table
  // built for editing) instead of on first use from the triangles: the vertices' coordinates
  // are read in order, where the triangles name them in no order.
  void refreshStaleGrid(const VertexEdges& edges);
  void clear();

  // A strip worker's job: triangulates the vertices order[0..count) on their own, in
  // insertion order, into the slots from firstSlot on. Duplicates are recorded in ids (by
  // vertex). Fails when the strip's points are all collinear. usedSlots() tells where it ended.
  Status insertStrip(const std::uint32_t* order, std::uint32_t count, std::uint32_t* ids);
  std::int32_t usedSlots() const { return runSlots_; }

 private:
  bool build(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Builds the first triangle from the waiting vertices and the batch's, then inserts the
  // other waiting ones; `built` gets the three corners.
  // A large batch is inserted in one run and renumbered in one pass over all triangles at
  // its end, which a small batch (a click, a polyline) must not pay.
  bool isLarge(std::uint32_t count, std::uint32_t base) const {
    return !built_ || 8 * static_cast<std::uint64_t>(count) > base;
  }
  Status insertStored(std::uint32_t count, std::uint32_t* ids, std::vector<std::uint32_t> order,
                      const double* input);
  void restoreInputOrder(std::uint32_t count, const double* input);
  // ids[the input index of vertex v] = r, the vertex it equals.
  void recordDuplicate(std::uint32_t v, std::uint32_t r);
  Status insertPending(const std::vector<std::uint32_t>& order,
                       std::array<std::uint32_t, 3>& built);
  void dedupCollinear(std::uint32_t base);
  // Inserts the batch's points in turn, from the last triangle, into arrays sized for all
  // of them up front.
  Status insertRun(const std::uint32_t* order, std::uint32_t count,
                   std::array<std::uint32_t, 3> skip);
  // Whether the batch goes to strips triangulated in parallel (strip_insertion.cpp), and
  // that path; it falls back to one thread (returns false in handled) where strips do not
  // pay or cannot be built.
  bool wantsStrips(std::uint32_t count) const;
  Status insertInStrips(std::uint32_t count, std::uint32_t* ids, bool& handled);
  template <bool kConstrained>
  GEOCDT_NOINLINE std::uint32_t insertRunVertex(std::uint32_t v);
  static constexpr std::uint32_t kRunBlock = 64;
  // Reads the x of points base + order[0..n) and returns their sum: loads that bring the
  // points into the cache while nothing waits for them.
  double touchPoints(std::uint32_t base, const std::uint32_t* order, std::uint32_t n) const;
  // Inserts v where h says (a duplicate returns the vertex it equals, a failed location
  // kGhost), keeping last_ on a triangle around it.
  template <bool kConstrained>
  std::uint32_t insertAt(const Hit& h, std::uint32_t v);
  // Both return the new id of each working id base + k.
  std::vector<std::uint32_t> compactSmallBatch(std::uint32_t base, std::uint32_t count,
                                               std::uint32_t* ids);
  std::vector<std::uint32_t> compactLargeBatch(std::uint32_t base, std::uint32_t count,
                                               std::uint32_t* ids,
                                               std::vector<std::uint32_t>&& scratch);
  void refreshGrid();
  Hit walk(double x, double y, std::int32_t t);
  Hit walkFrom(double x, double y, std::int32_t t, std::int64_t& step) const;
  Hit scan(double x, double y) const;
  std::int32_t startTriangle(double x, double y, bool fromGrid);
  bool startsNear(std::int32_t t, double x, double y) const;  // t's first real corner

  // The splits and flips, on slots already allocated: the new vertex p ends in third place
  // of every triangle around it, so that the edge facing it is the triangle's first.
  // splitFace makes slots t1, t2; splitEdgeAt makes t3, t4. Both leave the edges facing p
  // on the Lawson stack (lawson_, its used size in lawsonTop_) and return a triangle with p.
  template <bool kConstrained>
  std::int32_t splitFace(std::int32_t t, std::uint32_t p, std::int32_t t1, std::int32_t t2);
  template <bool kConstrained>
  std::int32_t splitEdgeAt(std::int32_t e, std::uint32_t p, std::int32_t t3, std::int32_t t4);
  template <bool kConstrained>
  void legalizeAround(std::uint32_t p);
  template <int k>
  void fillFan(std::uint32_t p, const std::uint32_t (&ring)[k], const std::int32_t (&outer)[k],
               const std::int32_t (&slot)[k]);
  std::int32_t addSlots(std::int32_t n);  // n zeroed slots at the end; returns the first
  // The two slots an insertion splits into: those a move's removal kept spare, else two new
  // ones at the end.
  void takeSlotPair(std::int32_t& t1, std::int32_t& t2);
  void pushLawson(std::int32_t e) {
    if (lawsonTop_ == lawson_.size()) lawson_.resize(2 * lawson_.size() + 64);
    lawson_[lawsonTop_++] = e;
  }

  Options options_;
  PointGrid grid_;
  bool gridStale_ = false;  // the cells' triangles predate a large batch: rebuild on use
  bool built_ = false;
  bool batchStart_ = false;
  bool smallBatch_ = false;
  bool inBatch_ = false;
  std::vector<std::array<std::uint32_t, 3>> splits_;  // constrained edges split in a batch
  std::int32_t last_ = -1;
  // During insertRun the arrays hold the whole batch's slots; runSlots_ of them are used.
  std::int32_t runSlots_ = -1;
  // A strip worker's first slot (its slots run from there), or -1 for an owner.
  std::int32_t firstSlot_ = -1;
  // The batch being inserted: its first vertex, the caller's ids, and while its points are
  // stored in insertion order, that order (vertex base + k is input point order[k]).
  struct Batch {
    std::uint32_t base = 0;
    std::uint32_t* ids = nullptr;
    const std::uint32_t* order = nullptr;
  } batch_;
  double touch_ = 0;  // what touchPoints() read, kept so that its loads are not dropped
  std::vector<std::uint32_t> pending_;  // vertices waiting for a non-collinear triple
  std::vector<std::int32_t> stack_;
  struct StarEdge {
    std::uint32_t start;
    std::int32_t twin;
    std::uint8_t fixed;
  };
  std::vector<StarEdge> star_;  // fillStar's boundary as it was
  std::vector<std::int32_t> lawson_;
  std::size_t lawsonTop_ = 0;
  StarRing ring_;  // a removal's scratch
  // A move's removal keeps its two freed slots for the insertion that follows, instead of
  // moving the last triangles into them: -1 when there are none.
  std::int32_t spare_[2] = {-1, -1};
  bool slotsReused_ = false;  // a removal moved or reused slots: grid hints may lie far
  Status error_;

  friend class VertexRemoval;
};

}  // namespace geocdt
