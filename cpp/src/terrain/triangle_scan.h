#pragma once
// The pixel of a triangle farthest from the triangle's plane: the candidate that greedy
// insertion puts in next. A row at a time, from edge to edge: each pixel costs a load, a
// multiply-add and a compare.
#include <cstdint>

#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

// Spans reach this far (in pixels) past their edges' computed crossings: a pixel on an edge,
// which rounding may put a little outside both triangles beside it (a sliver's two edges can
// cross a row in the wrong order), is then scanned by both. Rounding errs far less (a few
// ulps of the raster's size), and a pixel that close to an edge is on it: the plane it is
// measured against is the neighbour's, extended by nothing that shows. The mesher inserts a
// pixel that close to a constrained edge onto the edge.
constexpr double kEdgeReach = 0x1p-20;

struct Corner {
  double x, y, z;
};

// The plane through three corners, z = base + gx x + gy y, as the scans evaluate it.
struct Plane {
  double base, gx, gy;
  double at(double x, double y) const { return (base + gy * y) + gx * x; }
};

// The plane of triangle abc, from its corners in the order the scans take them (by y, then
// x), so that a pixel measured here gets the scan's very number. False when abc is flat.
bool planeOf(Corner a, Corner b, Corner c, Plane& plane);

struct ScanResult {
  double error = 0;         // |height - plane| at pixel, 0 when no pixel differs
  std::int64_t pixel = -1;  // the first such pixel in row order, or -1
  std::uint64_t scanned = 0;
};

// Scans the pixels in the closed triangle abc (any orientation, not degenerate), skipping
// those whose byte in skip is set (vertices, and pixels of the mesh's boundary, which
// border segments take care of). Where an edge passes exactly through pixels, both
// triangles beside it scan them. An edge is intersected with a row from its end lower in
// (y, x) order whichever triangle asks, so that a pixel that rounding puts just outside one
// of the two is inside the other: every pixel the mesh covers is scanned by some triangle.
ScanResult scanTriangle(Corner a, Corner b, Corner c, const RasterSampler& raster,
                        const std::uint8_t* skip);

}  // namespace geocdt::terrain
