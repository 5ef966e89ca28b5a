#pragma once
// The one-shot call behind JS triangulate(): points, then polylines, in one go.
#include <cstddef>
#include <cstdint>

#include "output.h"

namespace geocdt::wasm {

// keep: 0 all, 1 inside; fill: 0 even-odd, 1 nonzero (web/api.js maps the names).
MeshOptions meshOptions(int keep, int fill, bool insideFlags);

// xy holds 2 * count doubles. The polylines are concatenated in lineXY, with lineCounts[i]
// points each. The result (or the failure) lands in out. Returns whether it succeeded.
bool triangulateInto(Output& out, std::uintptr_t xy, std::size_t count, std::uintptr_t lineXY,
                     std::uintptr_t lineCounts, std::size_t lineCount, int keep, int fill,
                     bool insideFlags);

}  // namespace geocdt::wasm
