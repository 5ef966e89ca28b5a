#pragma once
// The one-shot call behind JS triangulate(): points, then polylines, in one go.
#include <emscripten/val.h>

#include "input.h"
#include "output.h"

namespace geocdt::wasm {

// The core's options; input gives the polygons (region labels when it has any).
// segmentSources: the input segments of each constrained edge (Mesh::segmentSources).
MeshOptions meshOptions(Keep keep, FillRule fill, bool insideFlags, bool segmentSources,
                        const Input& input);

// Triangulates what JS wrote into input (which is freed afterwards). The result, or the
// failure, lands in out: with region labels when the input has polygons, with
// valuesPerPoint values per vertex when it has values. onProgress: a JS function (phase,
// fraction), or undefined. threads: Options::threads (1 in the single-threaded build, where
// no thread can start). With refine (see refineOptions), the triangulation is refined
// before export. Returns whether it succeeded.
bool triangulateInto(Output& out, Input& input, Keep keep, FillRule fill, bool insideFlags,
                     bool segmentSources, std::uint32_t valuesPerPoint, std::uint32_t threads,
                     emscripten::val onProgress, bool refine, double minAngle, double maxArea,
                     double maxSteinerPoints);

// The core's refinement options from what JS checked: maxArea 0 and maxSteinerPoints 0 for
// none.
RefineOptions refineOptions(Keep keep, FillRule fill, double minAngle, double maxArea,
                            double maxSteinerPoints);

}  // namespace geocdt::wasm
