#include "voronoi.h"

#include <vector>

#include "guard.h"

namespace geocdt::wasm {

bool voronoiInto(Output& out, Input& input, VoronoiClip clip, double xmin, double ymin, double xmax,
                 double ymax, FillRule fill, std::uint32_t threads, std::uint32_t lloydIterations,
                 double lloydTolerance) {
  out.clear();
  VoronoiOptions options;
  options.clip = clip;
  options.box[0] = xmin;
  options.box[1] = ymin;
  options.box[2] = xmax;
  options.box[3] = ymax;
  options.fill = fill;
  options.threads = threads;
  options.lloydIterations = lloydIterations;
  options.lloydTolerance = lloydTolerance;
  const bool ok = guarded(
      out,
      [&] {
        const std::vector<PolylineView> rings = input.polylines();
        return voronoi(input.points.data(), input.pointCount(), rings.data(), rings.size(), options,
                       out.cells);
      },
      "out of memory: the cells need more than the 4 GB a WebAssembly module can address");
  input.clear();
  return ok;
}

}  // namespace geocdt::wasm
