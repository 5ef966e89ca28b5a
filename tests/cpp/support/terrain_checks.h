#pragma once
// Checks of a terrain mesh (triangulateRaster's, in pixel positions: no bbox) against its
// raster, independent of the mesher: every pixel is found in the triangles by exact
// orientation tests and interpolated barycentrically in long double (along the edge, for a
// pixel exactly on one).
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

struct RasterErrors {
  double maxError = 0;          // over the pixels some triangle holds
  std::uint64_t uncovered = 0;  // pixels with data that should be covered and are not
  std::uint64_t pixels = 0;     // pixels checked
  std::string problem;          // the first uncovered pixel, or a triangle outside the data
};

// valid: one byte per pixel (1: data), or empty for all. With no-data pixels, the mesh must
// cover exactly the grid cells whose four corners have data: each pixel of such a cell must be
// in a triangle, and each triangle's centroid in such a cell. exempt: one byte per pixel (1:
// covered, but left out of maxError), or empty for none.
RasterErrors rasterErrors(const Mesh& mesh, const std::vector<double>& heights, std::uint32_t width,
                          std::uint32_t height, const std::vector<std::uint8_t>& valid = {},
                          const std::vector<std::uint8_t>& exempt = {});

// The distance from (x, y) to the segment from (ax, ay) to (bx, by), in floating point.
double distanceToSegment(double x, double y, double ax, double ay, double bx, double by);

// The pixels under vertices of the mesh that lie on one of the lines (x, y pairs) and whose
// height is not the pixel's: a breakline point with a given height on a pixel position, or a
// point interpolated along such a line. The surface there is the line's, and maxError cannot
// hold: rasterErrors' exempt mask.
std::vector<std::uint8_t> underGivenHeights(const Mesh& mesh, const std::vector<double>& heights,
                                            std::uint32_t width, std::uint32_t height,
                                            const std::vector<std::vector<double>>& lines);

}  // namespace geocdt::testing
