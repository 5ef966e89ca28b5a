#pragma once
// The mesh made in pixel positions, turned into the caller's: points in the bbox's frame
// (breakline points at the very coordinates given), triangles counter-clockwise there,
// heights as values, vertices of no triangle dropped, and provenance naming breaklines.
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"
#include "terrain/pixel_frame.h"

namespace geocdt::terrain {

struct FrameInput {
  std::vector<double> z;         // per vertex
  std::vector<double> original;  // per vertex: the caller's x, y, or NaN (2 per vertex)
  // Per polyline of the core: the number the result's sources give it.
  std::vector<std::uint32_t> sourceOf;
  bool dropUnused = false;  // drop the vertices no triangle has (outside the area with data)
};

void frameMesh(Mesh& m, FrameInput in, const PixelFrame& frame);

}  // namespace geocdt::terrain
