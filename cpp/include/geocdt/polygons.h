#pragma once
// Polygons for rendering: every polygon of a batch triangulated alone, as the constrained
// Delaunay triangulation of its rings, keeping only the triangles inside them.
//
// Input is GeoArrow's polygon layout: ring r is the points ringOffsets[r] .. ringOffsets[r + 1]
// of xy (x, y interleaved), and polygon p is the rings polygonOffsets[p] .. polygonOffsets[p +
// 1], its shell first (the fill rule decides inside, so the order of rings does not matter).
// A ring may be closed (its last point repeats its first) or open; rings of fewer than three
// points bound nothing. Polygons never see each other's edges.
//
// Output: triangles, 3 point indices each, counter-clockwise with y up. An index below the
// number of input points is that input point (equal points of one polygon may share one
// index: the first of them); a higher one, pointCount + i, is extra point i, a crossing of
// two ring segments, whose x, y are extraPoints[2i], extraPoints[2i + 1]. Polygon p's
// triangles are triangleOffsets[p] .. triangleOffsets[p + 1] (in triangles, not indices).
//
// Exact: every answer comes from the exact predicates. Small polygons without crossings take
// a path with no per-call setup (scratch arrays reused from polygon to polygon); any polygon
// that path cannot prove it handles (rings that cross, a vertex on another ring's segment,
// more flips than it budgets for) goes to geocdt::Triangulation. With threads > 1, ranges of
// polygons run side by side; the output is the same as one thread's.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt {

struct PolygonBatch {
  const double* xy = nullptr;  // 2 * pointCount doubles
  std::size_t pointCount = 0;
  const std::uint32_t* ringOffsets = nullptr;  // ringCount + 1 entries, each <= pointCount
  std::size_t ringCount = 0;
  const std::uint32_t* polygonOffsets = nullptr;  // polygonCount + 1 entries, each <= ringCount
  std::size_t polygonCount = 0;
};

struct PolygonOptions {
  FillRule fill = FillRule::EvenOdd;
  // Threads for a large batch (ranges of polygons side by side); 1 runs on the calling thread.
  std::uint32_t threads = 1;
};

struct PolygonTriangles {
  std::vector<std::uint32_t> triangles;        // 3 indices per triangle
  std::vector<double> extraPoints;             // x, y of each extra point
  std::vector<std::uint32_t> triangleOffsets;  // polygonCount + 1 entries
};

// What a batch did: how many polygons each path took.
struct PolygonStats {
  std::uint64_t smallPath = 0;  // triangulated by the path with no per-call setup
  std::uint64_t general = 0;    // sent to geocdt::Triangulation
  std::uint64_t crossings = 0;  // extra points
  std::uint32_t threads = 1;    // threads that ran the batch
};

// Checks the layout (offsets that never decrease and stay in range) and the coordinates of
// the points that rings use (finite, |coordinate| <= kMaxCoordinate), then triangulates. On
// invalid input nothing is written and the status names the polygon, and its ring and point
// where there is one: Status::index is the polygon, Status::segment the ring (a batch-wide
// index into ringOffsets); the message says the rest.
Status triangulatePolygons(const PolygonBatch& batch, const PolygonOptions& options,
                           PolygonTriangles& out, PolygonStats* stats = nullptr);

}  // namespace geocdt
