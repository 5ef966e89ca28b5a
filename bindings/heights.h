#pragma once
// Heights (z) through a triangulation: the caller gives one per input point, and every vertex
// of the result gets one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::wasm {

// z holds a height per input point: the `points` ones, then the polylines' points. A vertex
// that input points became takes the first of their heights that is not NaN; a vertex added
// where constraints cross, the height interpolated linearly along the input segment through
// it that mesh.vertexSegments names (by its projection on the segment, so a crossing moved by
// rounding still gets a height between the segment's ends); NaN where there is none.
std::vector<double> vertexHeights(const Mesh& mesh, const std::vector<std::uint32_t>& inputToVertex,
                                  const std::vector<double>& z, std::size_t pointCount);

}  // namespace geocdt::wasm
