#include "one_shot.h"

#include <utility>
#include <vector>

#include "guard.h"
#include "progress.h"

namespace geocdt::wasm {

MeshOptions meshOptions(Keep keep, FillRule fill, bool insideFlags, bool segmentSources,
                        const Input& input) {
  MeshOptions options;
  options.keep = keep;
  options.fill = fill;
  options.insideFlags = insideFlags;
  options.segmentSources = segmentSources;
  options.regions = input.hasPolygons();
  options.polylinePolygons = input.polylinePolygons();
  return options;
}

RefineOptions refineOptions(Keep keep, FillRule fill, double minAngle, double maxArea,
                            double maxSteinerPoints) {
  RefineOptions r;
  r.keep = keep;
  r.fill = fill;
  r.minAngle = minAngle;
  r.maxArea = maxArea;
  r.maxSteinerPoints = static_cast<std::uint64_t>(maxSteinerPoints);
  return r;
}

bool triangulateInto(Output& out, Input& input, Keep keep, FillRule fill, bool insideFlags,
                     bool segmentSources, std::uint32_t valuesPerPoint, std::uint32_t threads,
                     emscripten::val onProgress, bool refine, double minAngle, double maxArea,
                     double maxSteinerPoints) {
  out.clear();
  ProgressRelay relay;
  const std::size_t points = input.pointCount();
  relay.start(std::move(onProgress), points + input.linePointCount());
  Options options;
  options.valuesPerPoint = valuesPerPoint;
  options.threads = threads;
  if (relay.active()) options.progress = relay.hook();  // else the core never calls out
  const bool ok = guarded(
      out,
      [&] {
        const MeshOptions exportOptions =
            meshOptions(keep, fill, insideFlags, segmentSources, input);
        const std::vector<double> values = std::move(input.values);
        const double* pointValues = values.empty() ? nullptr : values.data();
        const double* lineValues =
            values.empty() ? nullptr : values.data() + points * std::size_t{valuesPerPoint};
        // Points first, then all polylines at once (one spatially sorted batch of their
        // points, then their segments), as geocdt::triangulate() does; done here through the
        // class so that the statistics can be read before release() clears them.
        const std::size_t lineCount = input.lineCount();
        out.inputToVertex.resize(points + input.linePointCount());
        Triangulation triangulation(options);
        // The core takes the input buffer over as its coordinate array: no second copy.
        Status status = triangulation.insertPoints(std::move(input.points),
                                                   out.inputToVertex.data(), pointValues);
        relay.batch(points);
        // The polylines' coordinates go in the same way, freed once their points are in.
        if (status.ok() && lineCount > 0)
          status = triangulation.insertPolylines(std::move(input.lineCoords),
                                                 input.lineOffsets.data(), lineCount,
                                                 out.inputToVertex.data() + points, lineValues);
        input.clear();  // the core holds its own copy: the export runs without this one
        if (status.ok() && refine)
          status =
              triangulation.refine(refineOptions(keep, fill, minAngle, maxArea, maxSteinerPoints));
        if (!status.ok()) {
          out.clear();  // a failed call hands back no arrays
          return status;
        }
        out.stats = triangulation.stats();
        out.mesh = triangulation.release(exportOptions);
        return status;
      },
      "out of memory: the triangulation needs more than the 4 GB a WebAssembly module can "
      "address");
  input.clear();
  relay.finish();
  return ok;
}

}  // namespace geocdt::wasm
