#pragma once
// A constrained Delaunay triangulation built by incremental insertion.
//
// Layout (delaunator's): triangle t has vertices triangles[3t..3t+2], counter-clockwise
// with y up; half-edge e runs from triangles[e] to triangles[next(e)] and belongs to
// triangle e / 3; halfedges[e] is its twin, or -1 on the convex hull.
//
// Internally the hull is closed by a ghost vertex at infinity, so every half-edge has a
// twin and the result is the exact Delaunay triangulation covering the convex hull. Users
// never see ghost triangles: mesh() and release() return only real ones.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geocdt/status.h"

namespace geocdt {

enum class InsertionOrder : std::uint8_t {
  Input,    // the paper's: insert in the order given
  Hilbert,  // spatially sorted along a Hilbert curve
  Brio,     // biased randomized rounds, each Hilbert-sorted
};

// Where the walk of each insertion starts. locate() and the first point of every batch
// always start from the grid, which every insertion keeps up to date.
enum class LocateStart : std::uint8_t {
  Grid,          // the dynamic uniform grid's cell hint (Skvortsov)
  LastTriangle,  // the triangle of the previous insertion
};

// When constraint crossings are snap-rounded (see snapRounding below).
enum class SnapRounding : std::uint8_t {
  WhenNeeded,  // only where computed crossings would break the guarantee (tangles)
  Always,      // every call: each call then rebuilds the triangulation (for tests, mostly)
};

struct Options {
  InsertionOrder order = InsertionOrder::Hilbert;
  LocateStart start = LocateStart::LastTriangle;
  // The grid doubles per axis when inserted points exceed gridDensity * m * m. Measured on
  // 1M uniform points: 8 keeps walks at 4.2-4.5 steps (2 gives 5.3, 16 gives 6) with a cell
  // per 4-8 points, about 1 byte per point.
  double gridDensity = 8.0;
  // Crossings are computed from the input segments and checked to fit; where that would
  // move a constraint farther than the guarantee allows, the constraints are snap-rounded
  // instead (README, "How it works").
  SnapRounding snapRounding = SnapRounding::WhenNeeded;
};

enum class FillRule : std::uint8_t { EvenOdd, NonZero };
enum class Keep : std::uint8_t { All, Inside };

struct MeshOptions {
  Keep keep = Keep::All;              // Inside drops triangles outside every ring
  FillRule fill = FillRule::EvenOdd;  // how rings decide inside
  bool insideFlags = false;           // fill Mesh::inside
};

// What a triangulation hands out: plain arrays the caller owns.
struct Mesh {
  std::vector<double> points;             // x0, y0, x1, y1, ... per vertex
  std::vector<std::uint32_t> triangles;   // 3 per triangle
  std::vector<std::int32_t> halfedges;    // 1 per half-edge
  std::vector<std::uint8_t> constrained;  // 1 per half-edge on an input constraint
  // Provenance: constraintEdges lists one half-edge per constrained edge; the polylines it
  // came from are sources[sourceOffsets[i] .. sourceOffsets[i + 1]).
  std::vector<std::uint32_t> constraintEdges;
  std::vector<std::uint32_t> sourceOffsets;
  std::vector<std::uint32_t> sources;
  std::vector<std::uint8_t> inside;  // 1 per triangle when MeshOptions::insideFlags
};

// A polyline given as 2 * count doubles. A ring repeats its first point at its end.
struct PolylineView {
  const double* xy = nullptr;
  std::size_t count = 0;
};

struct Location {
  enum class Kind : std::uint8_t {
    Empty,    // fewer than three non-collinear vertices: there are no triangles
    Outside,  // strictly outside the convex hull
    Face,     // strictly inside triangle
    Edge,     // on the edge between vertices[0] and vertices[1] (inside the hull)
    Vertex,   // equal to vertex vertices[0]
  };
  Kind kind = Kind::Empty;
  std::int64_t triangle = -1;  // index into mesh().triangles / 3, or -1 when outside/empty
  std::uint32_t vertices[3] = {0, 0, 0};
};

struct Stats {
  std::uint64_t inserted = 0;    // points that became vertices
  std::uint64_t duplicates = 0;  // points equal to an existing vertex
  std::uint64_t walkSteps = 0;   // triangles visited by point location
  std::uint64_t locates = 0;     // point locations performed
  std::uint64_t flips = 0;
  std::uint64_t walkFallbacks = 0;  // visibility walks that gave way to a straight walk
  std::uint32_t gridSize = 0;       // current m of the m x m grid
  std::uint64_t crossings = 0;      // vertices added where constraints cross
  std::uint64_t polylines = 0;
  std::uint64_t segments = 0;  // constraint segments inserted
  // Times the constraints were snap-rounded because computed crossings would have broken
  // the guarantee (tangles of vertices a few ulps apart; never on real data so far).
  std::uint64_t snapRoundings = 0;
};

class Triangulation {
 public:
  explicit Triangulation(const Options& options = {});
  ~Triangulation();
  Triangulation(Triangulation&&) noexcept;
  Triangulation& operator=(Triangulation&&) noexcept;

  // Inserts count points (xy holds 2*count doubles). vertexIds, if not null, receives
  // count ids: the vertex each point became or equals. Nothing is inserted when any
  // coordinate is invalid; the status names the first offending point.
  Status insertPoints(const double* xy, std::size_t count, std::uint32_t* vertexIds = nullptr);

  // Inserts a polyline as constraints: its points, then its segments, split where they
  // cross earlier constraints. Its polyline id is polylineCount() before the call.
  // vertexIds, if not null, receives count ids. Nothing is inserted on invalid input.
  Status insertPolyline(const double* xy, std::size_t count, std::uint32_t* vertexIds = nullptr);
  // Inserts several polylines at once: all their points in one spatially sorted batch,
  // then their segments in order. vertexIds receives one id per point of every polyline.
  Status insertPolylines(const PolylineView* polylines, std::size_t count,
                         std::uint32_t* vertexIds = nullptr);
  std::size_t polylineCount() const;

  Location locate(double x, double y) const;

  std::size_t vertexCount() const;
  std::size_t triangleCount() const;  // real triangles
  const std::vector<double>& points() const;
  const Stats& stats() const;

  Mesh mesh(const MeshOptions& options = {}) const;  // a compact copy, no ghost triangles
  Mesh release(const MeshOptions& options = {});     // the same; leaves this empty

 private:
  // insertPoints without checking the coordinates again (insertPolylines checked them).
  Status insertCheckedPoints(const double* xy, std::size_t count, std::uint32_t* vertexIds);
  struct State;
  std::unique_ptr<State> state_;
};

// One shot: points first, then polylines in order. inputToVertex, if not null, gets one
// vertex id per input point (points first, then each polyline's points).
Status triangulate(const double* xy, std::size_t count, const PolylineView* polylines,
                   std::size_t polylineCount, const Options& options,
                   const MeshOptions& meshOptions, Mesh& out,
                   std::vector<std::uint32_t>* inputToVertex = nullptr);

}  // namespace geocdt
