#include "terrain.h"

#include <utility>
#include <vector>

#include "guard.h"

namespace geocdt::wasm {

bool triangulateRasterInto(Output& out, Input& input, double width, double height,
                           const RasterOptions& o) {
  out.clear();
  const bool ok = guarded(
      out,
      [&] {
        TerrainOptions options;
        options.maxError = o.maxError;
        options.maxTriangles = static_cast<std::uint64_t>(o.maxTriangles);
        options.maxVertices = static_cast<std::uint64_t>(o.maxVertices);
        options.hasNoData = o.hasNoData;
        options.noDataValue = o.noData;
        options.minAngle = o.minAngle;
        options.decimate = o.decimate;
        options.hasBbox = o.hasBbox;
        options.minX = o.minX;
        options.minY = o.minY;
        options.maxX = o.maxX;
        options.maxY = o.maxY;
        const RasterView raster{input.raster.data(), static_cast<std::uint32_t>(width),
                                static_cast<std::uint32_t>(height)};
        const std::vector<PolylineView> breaklines = input.polylines();
        const Status status = triangulateRaster(
            raster, breaklines.data(), breaklines.size(),
            input.values.empty() ? nullptr : input.values.data(), options, out.mesh, &out.terrain);
        if (!status.ok()) out.clear();
        return status;
      },
      "out of memory: the mesh needs more than the 4 GB a WebAssembly module can address");
  input.clear();
  return ok;
}

}  // namespace geocdt::wasm
