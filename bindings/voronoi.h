#pragma once
// The call behind JS voronoi(): the sites (Input::points) and the rings (Input's polylines) in,
// the cells (Output::cells) out.
#include "geocdt/voronoi.h"
#include "input.h"
#include "output.h"

namespace geocdt::wasm {

// box: xmin, ymin, xmax, ymax for VoronoiClip::Box (as JS checked them); threads:
// VoronoiOptions::threads. Returns whether it succeeded; the failure is in out.status.
bool voronoiInto(Output& out, Input& input, VoronoiClip clip, double xmin, double ymin, double xmax,
                 double ymax, FillRule fill, std::uint32_t threads, std::uint32_t lloydIterations,
                 double lloydTolerance);

}  // namespace geocdt::wasm
