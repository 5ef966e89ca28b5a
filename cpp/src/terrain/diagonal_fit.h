#pragma once
// Four vertices on one circle make two Delaunay triangulations of their quad; on a raster's
// lattice that is common (a quarter of the edges of a 1 m mesh of a DEM). Greedy insertion
// takes the diagonal that fits the heights better, and so needs fewer vertices for the same
// bound (bench/EXPERIMENTS.md, TN44).
#include <cstdint>

#include "terrain/raster_sampler.h"
#include "terrain/triangle_scan.h"

namespace geocdt::terrain {

// Whether diagonal p-d fits the raster better than a-b in the convex quad a, d, b, p
// (counter-clockwise): a smaller largest error over the pixels strictly inside the quad (the
// pixels skip marks and those without data left out). Where those are equal, or no pixel is
// inside, a-b stays. A choice between two valid meshes, so rounding may decide it.
bool otherDiagonalFitsBetter(const Corner& a, const Corner& b, const Corner& d, const Corner& p,
                             const RasterSampler& raster, const std::uint8_t* skip);

}  // namespace geocdt::terrain
