#pragma once
// The order of the greedy insertion once the mesh outgrows the cache: square tiles of pixels
// in Morton order, the largest error first inside each, a triangle going with the first tile
// it touches. Greedy insertion otherwise jumps to the largest error anywhere, a cache miss per
// triangle it touches in a mesh of megabytes; tile by tile, the triangles it touches were made
// moments before. The order changes which vertices go in, never the bound they meet
// (bench/EXPERIMENTS.md, TN30, TN35).
#include <algorithm>
#include <cstdint>
#include <vector>

// The fuzz build takes tiles of 4 x 4 pixels from 32 triangles on, so that its small rasters
// go through this order too.
#ifndef GEOCDT_TERRAIN_TILE_SHIFT
#define GEOCDT_TERRAIN_TILE_SHIFT 6
#endif
#ifndef GEOCDT_TERRAIN_TILES_FROM
#define GEOCDT_TERRAIN_TILES_FROM 8000
#endif

namespace geocdt::terrain {

class TileOrder {
 public:
  static constexpr std::uint32_t kTileShift = GEOCDT_TERRAIN_TILE_SHIFT;  // 64 x 64 pixels
  // Strict greedy order until the mesh has this many triangles (under 1 MB of mesh and queue).
  static constexpr std::uint64_t kFromTriangles = GEOCDT_TERRAIN_TILES_FROM;

  TileOrder(std::uint32_t width, std::uint32_t height)
      : width_(width), height_(height), across_(width == 0 ? 0 : ((width - 1) >> kTileShift) + 1) {
    const std::uint32_t down = height == 0 ? 0 : ((height - 1) >> kTileShift) + 1;
    std::vector<std::uint64_t> keys;  // Morton code << 32 | tile
    for (std::uint32_t ty = 0; ty < down; ++ty)
      for (std::uint32_t tx = 0; tx < across_; ++tx)
        keys.push_back(std::uint64_t{spread(tx) | spread(ty) << 1} << 32 | (ty * across_ + tx));
    std::sort(keys.begin(), keys.end());
    rank_.resize(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k)
      rank_[keys[k] & 0xFFFFFFFFu] = static_cast<std::uint32_t>(k);
  }

  // The rank of the tile holding (x, y), clamped into the raster, below the number of tiles:
  // lower ranks go first. Ranks grow with x and with y (Morton codes do), so the first tile a
  // box touches is the one holding its lower corner.
  std::uint32_t rankAt(double x, double y) const {
    const auto i = static_cast<std::uint32_t>(std::clamp(x, 0.0, width_ - 1.0)) >> kTileShift;
    const auto j = static_cast<std::uint32_t>(std::clamp(y, 0.0, height_ - 1.0)) >> kTileShift;
    return rank_[j * across_ + i];
  }

 private:
  // The low 16 bits of v on the even bits of the result.
  static std::uint32_t spread(std::uint32_t v) {
    v &= 0xFFFFu;
    v = (v | v << 8) & 0x00FF00FFu;
    v = (v | v << 4) & 0x0F0F0F0Fu;
    v = (v | v << 2) & 0x33333333u;
    v = (v | v << 1) & 0x55555555u;
    return v;
  }

  double width_, height_;            // pixels
  std::uint32_t across_;             // tiles in a row
  std::vector<std::uint32_t> rank_;  // per tile, row by row
};

}  // namespace geocdt::terrain
