#pragma once
// The pixel of a triangle farthest from the triangle's plane: the candidate that greedy
// insertion puts in next. A row at a time, from edge to edge: each pixel costs a load, a
// multiply-add and a compare. A large triangle goes block by block instead, and passes over
// the blocks whose heights cannot beat the largest error found (height_blocks.h).
#include <cstdint>
#include <vector>

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

class HeightBlocks;

// Triangles this large (in square pixels) and larger are scanned by blocks; below, the
// blocks' bounds cost about what they save (bench/EXPERIMENTS.md, TN43). The fuzz build
// lowers it, so that its small rasters go through the blocks too.
#ifndef GEOCDT_TERRAIN_BLOCK_SCAN_AREA
#define GEOCDT_TERRAIN_BLOCK_SCAN_AREA 512
#endif
constexpr double kBlockScanArea = GEOCDT_TERRAIN_BLOCK_SCAN_AREA;

// What a scan by blocks reuses from call to call.
struct ScanScratch {
  double fromArea = kBlockScanArea;  // (tests lower it, to take small triangles by blocks)
  struct Block {
    double bound;  // of its pixels' errors
    std::uint32_t column, row;
  };
  std::vector<Block> blocks;
  std::vector<std::int32_t> spans;  // per row: its first and last column
  std::vector<std::uint8_t> found;  // per block row: whether spans holds its rows
};

// Scans the pixels in the closed triangle abc (any orientation, not degenerate), skipping
// those whose byte in skip is set (vertices, and pixels of the mesh's boundary, which
// border segments take care of). Where an edge passes exactly through pixels, both
// triangles beside it scan them. An edge is intersected with a row from its end lower in
// (y, x) order whichever triangle asks, so that a pixel that rounding puts just outside one
// of the two is inside the other: every pixel the mesh covers is scanned by some triangle.
// With blocks and scratch, a triangle of scratch->fromArea or more is scanned block by block:
// the same result, from fewer pixels.
ScanResult scanTriangle(Corner a, Corner b, Corner c, const RasterSampler& raster,
                        const std::uint8_t* skip, const HeightBlocks* blocks = nullptr,
                        ScanScratch* scratch = nullptr);

}  // namespace geocdt::terrain
