#include "one_shot.h"

#include <vector>

#include "guard.h"

namespace geocdt::wasm {

MeshOptions meshOptions(int keep, int fill, bool insideFlags) {
  MeshOptions options;
  options.keep = keep == 1 ? Keep::Inside : Keep::All;
  options.fill = fill == 1 ? FillRule::NonZero : FillRule::EvenOdd;
  options.insideFlags = insideFlags;
  return options;
}

bool triangulateInto(Output& out, std::uintptr_t xy, std::size_t count, std::uintptr_t lineXY,
                     std::uintptr_t lineCounts, std::size_t lineCount, int keep, int fill,
                     bool insideFlags) {
  out.clear();
  return guarded(
      out,
      [&] {
        // Points first, then all polylines at once (one spatially sorted batch of their
        // points, then their segments), as geocdt::triangulate() does; done here through the
        // class so that the statistics can be read before release() clears them.
        const auto* coords = reinterpret_cast<const double*>(lineXY);
        const auto* counts = reinterpret_cast<const std::uint32_t*>(lineCounts);
        std::vector<PolylineView> lines(lineCount);
        std::size_t total = count;
        for (std::size_t i = 0; i < lineCount; ++i) {
          lines[i] = {coords, counts[i]};
          coords += 2 * static_cast<std::size_t>(counts[i]);
          total += counts[i];
        }
        out.inputToVertex.resize(total);
        Triangulation triangulation;
        Status status = triangulation.insertPoints(reinterpret_cast<const double*>(xy), count,
                                                   out.inputToVertex.data());
        if (status.ok() && lineCount > 0)
          status = triangulation.insertPolylines(lines.data(), lineCount,
                                                 out.inputToVertex.data() + count);
        if (!status.ok()) {
          out.clear();  // a failed call hands back no arrays
          return status;
        }
        out.stats = triangulation.stats();
        out.mesh = triangulation.release(meshOptions(keep, fill, insideFlags));
        return status;
      },
      "out of memory: the triangulation needs more than the 4 GB a WebAssembly module can "
      "address");
}

}  // namespace geocdt::wasm
