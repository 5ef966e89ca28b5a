#include "raster_file.h"

#include <cstring>
#include <fstream>

namespace geocdt::testing {

RasterFile readRaster(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4];
  std::uint32_t size[2];
  RasterFile r;
  if (!in.read(magic, 4) || std::memcmp(magic, "GRS1", 4) != 0 ||
      !in.read(reinterpret_cast<char*>(size), sizeof size))
    return r;
  std::vector<double> heights(static_cast<std::size_t>(size[0]) * size[1]);
  if (!in.read(reinterpret_cast<char*>(heights.data()),
               static_cast<std::streamsize>(heights.size() * sizeof(double))))
    return r;
  r.heights = std::move(heights);
  r.width = size[0];
  r.height = size[1];
  return r;
}

RasterFile cropRaster(const RasterFile& r, std::uint32_t left, std::uint32_t top,
                      std::uint32_t width, std::uint32_t height) {
  RasterFile out;
  out.width = width;
  out.height = height;
  out.heights.resize(static_cast<std::size_t>(width) * height);
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i)
      out.heights[static_cast<std::size_t>(j) * width + i] =
          r.heights[static_cast<std::size_t>(top + j) * r.width + left + i];
  return out;
}

}  // namespace geocdt::testing
