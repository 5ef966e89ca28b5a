#pragma once
// Breaklines as the mesh takes them: in pixel positions, cut to the raster's rectangle (a
// line leaving it and coming back gives two pieces), closed lines cut in two so that they
// bound no area, and a height for every point: the one given, else the raster's.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"
#include "terrain/pixel_frame.h"
#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

struct BreaklinePieces {
  std::vector<double> xy;  // pixel positions; piece k has points offsets[k] .. offsets[k + 1]
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> breakline;  // per piece: the breakline it comes from
  std::vector<double> z;                 // per point
  std::vector<std::uint8_t> given;       // per point: 1 when its height was given
  std::vector<double> original;          // per point: the caller's x, y; NaN where cut

  std::size_t count() const { return breakline.size(); }
  std::size_t points() const { return z.size(); }
};

// lines: in the caller's frame; heights: one per point of all lines, NaN (or null for all)
// for the raster's height.
BreaklinePieces cutBreaklines(const PolylineView* lines, std::size_t count, const double* heights,
                              const PixelFrame& frame, const RasterSampler& raster);

}  // namespace geocdt::terrain
