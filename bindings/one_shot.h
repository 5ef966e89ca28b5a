#pragma once
// The one-shot call behind JS triangulate(): points, then polylines, in one go.
#include <emscripten/val.h>

#include "input.h"
#include "output.h"

namespace geocdt::wasm {

MeshOptions meshOptions(Keep keep, FillRule fill, bool insideFlags);

// Triangulates what JS wrote into input (which is freed afterwards). The result, or the
// failure, lands in out. onProgress: a JS function (phase, fraction), or undefined. Returns
// whether it succeeded.
bool triangulateInto(Output& out, Input& input, Keep keep, FillRule fill, bool insideFlags,
                     emscripten::val onProgress);

}  // namespace geocdt::wasm
