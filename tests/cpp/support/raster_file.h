#pragma once
// Raster files shared by the tests and the benchmarks (scripts/datasets/usgs_dems.mjs writes
// them): "GRS1", uint32 width, uint32 height, then float64 heights row by row, little-endian.
#include <cstdint>
#include <string>
#include <vector>

namespace geocdt::testing {

struct RasterFile {
  std::vector<double> heights;
  std::uint32_t width = 0, height = 0;
};

// The raster in path; empty (width 0) when the file is missing or broken.
RasterFile readRaster(const std::string& path);

// The size x size pixels at column `left`, row `top` (a tile).
RasterFile cropRaster(const RasterFile& r, std::uint32_t left, std::uint32_t top,
                      std::uint32_t width, std::uint32_t height);

}  // namespace geocdt::testing
