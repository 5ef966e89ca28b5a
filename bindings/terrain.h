#pragma once
// The call behind JS triangulateRaster(): a TIN from a heightmap.
#include "input.h"
#include "output.h"

namespace geocdt::wasm {

// The options of triangulateRaster() as JS checked them; maxTriangles and maxVertices 0 for
// no limit, minAngle 0 for no refinement.
struct RasterOptions {
  double maxError = 0, maxTriangles = 0, maxVertices = 0;
  bool hasNoData = false;
  double noData = 0, minAngle = 0;
  bool decimate = false;
  bool hasBbox = false;
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
};

// Triangulates the width x height heights JS wrote into input.raster, with the breaklines in
// input's polylines and their heights in input.values (or none); the input is freed. The
// mesh, or the failure, lands in out; returns whether it succeeded.
bool triangulateRasterInto(Output& out, Input& input, double width, double height,
                           const RasterOptions& options);

}  // namespace geocdt::wasm
