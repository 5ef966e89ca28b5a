#pragma once
// Incremental Delaunay insertion: point location by the dynamic grid and a visibility walk,
// triangle or edge split, then Lawson flips. The hull is closed by a ghost vertex, so points
// outside the hull need no special case beyond the ghost's in-circle rule.
#include <array>
#include <cstdint>
#include <vector>

#include "constraint_store.h"
#include "geocdt/status.h"
#include "geocdt/triangulation.h"
#include "point_grid.h"
#include "topology.h"

namespace geocdt {

// Where a point lies in the triangulation.
struct Hit {
  enum class Kind : std::uint8_t { Empty, Face, Edge, Vertex, Outside, Failed };
  Kind kind = Kind::Empty;
  // Face: a half-edge of the containing triangle. Edge: a half-edge of that edge.
  // Vertex: a half-edge starting at the vertex. Outside: the real half-edge of a ghost
  // triangle that the point lies strictly beyond.
  std::int32_t edge = -1;
};

class Delaunay {
 public:
  explicit Delaunay(const Options& options) : options_(options) {}

  std::vector<double> xy;  // 2 per vertex
  Topology topo;
  ConstraintStore constraints;
  Stats stats;

  bool built() const { return built_; }
  const Options& options() const { return options_; }
  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(xy.size() / 2); }

  // Inserts count points (2 * count doubles, already validated). ids[i] receives the vertex
  // that point i became or equals. New vertices are numbered in input order after the
  // existing ones, duplicates removed.
  Status insertBatch(const double* input, std::uint32_t count, std::uint32_t* ids);

  // Inserts vertex v (already in xy); returns v or the existing vertex at its place.
  // Returns kGhost when location failed (an internal error, described by lastError()).
  std::uint32_t insertVertex(std::uint32_t v);

  // Locates (x, y), starting from the grid's cell or from the last triangle.
  Hit locate(double x, double y, bool fromGrid);
  // Splits triangle slot t (real or ghost) at new vertex v and restores Delaunay.
  // Both return a half-edge starting at v.
  std::int32_t insertInFace(std::int32_t t, std::uint32_t v);
  // Splits the edge of half-edge e at vertex v lying strictly inside it; the halves of a
  // constrained edge stay constrained.
  std::int32_t splitEdge(std::int32_t e, std::uint32_t v);
  std::int32_t edgeFrom(std::int32_t t, std::uint32_t v) const;  // -1 if v is not in t
  // Flips non-constrained edges on the stack until each is locally Delaunay. legalize()
  // assumes every entry has the newly inserted vertex opposite it, so a flip only exposes two
  // new edges; restoreDelaunay() takes any edges and checks all four around each flip.
  void legalize();
  void restoreDelaunay();
  std::vector<std::int32_t>& flipStack() { return stack_; }

  bool isLocallyDelaunay(std::int32_t e) const;  // e's quad, whatever the fixed flags
  void setLastTriangle(std::int32_t t) { last_ = t; }
  const Status& lastError() const { return error_; }
  std::uint32_t gridSize() const { return grid_.size(); }
  void dropGrid() { grid_ = PointGrid(); }  // its memory, before the arrays are handed out
  void clear();

 private:
  bool build(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  Status insertPending(std::uint32_t base, std::uint32_t count,
                       const std::vector<std::uint32_t>& order, std::uint32_t* ids);
  void dedupCollinear(std::uint32_t base, const std::vector<std::uint32_t>& order,
                      std::uint32_t* ids);
  // Both return the new id of each working id base + k.
  std::vector<std::uint32_t> compactSmallBatch(std::uint32_t base, std::uint32_t count,
                                               std::uint32_t* ids);
  std::vector<std::uint32_t> renumberBatch(const double* input, std::uint32_t base,
                                           std::uint32_t count, std::vector<std::uint32_t>& order,
                                           std::uint32_t* ids);
  void refreshGrid();
  Hit walk(double x, double y, std::int32_t t);
  Hit scan(double x, double y) const;
  std::int32_t startTriangle(double x, double y, bool fromGrid);
  bool beyondGhostEdge(std::int32_t e, std::uint32_t v) const;

  Options options_;
  PointGrid grid_;
  bool built_ = false;
  bool batchStart_ = false;
  bool smallBatch_ = false;
  bool inBatch_ = false;
  std::vector<std::array<std::uint32_t, 3>> splits_;  // constrained edges split in a batch
  std::int32_t last_ = -1;
  std::vector<std::uint32_t> pending_;  // vertices waiting for a non-collinear triple
  std::vector<std::int32_t> stack_;
  Status error_;
};

}  // namespace geocdt
