// The scan by blocks (terrain/triangle_scan.cpp, terrain/height_blocks.h) finds what the scan
// row by row finds: the same largest error and the same pixel (the first in row order among
// ties), on rasters where ties are the rule (small integers), smooth and rough ones, far from
// zero, with NaN pixels, pixels without data and skipped pixels, for triangles of every size,
// corners on pixels or between them, slivers included, and from fewer pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "point_generators.h"
#include "terrain/height_blocks.h"
#include "terrain/raster_sampler.h"
#include "terrain/triangle_scan.h"

namespace geocdt::terrain {
namespace {

struct Raster {
  std::string kind;
  std::uint32_t width, height;
  std::vector<double> heights;
  std::vector<std::uint8_t> valid;
};

Raster makeRaster(const std::string& kind, std::uint32_t width, std::uint32_t height,
                  std::uint64_t seed) {
  testing::Random random(seed);
  Raster r{kind, width, height, std::vector<double>(std::size_t{width} * height), {}};
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i) {
      double& z = r.heights[std::size_t{j} * width + i];
      const double wave = 40 * std::sin(i * 0.07) * std::cos(j * 0.05) + 0.3 * i;
      if (kind == "integers") z = std::floor(random.uniform() * 4);
      if (kind == "smooth") z = wave;
      if (kind == "rough") z = wave + 25 * random.uniform();
      if (kind == "far") z = 1e7 + std::round(wave * 8) / 8;
      if (kind == "terraces") z = 10 * std::floor(wave / 10);
      if (kind == "nan") z = random.uniform() < 0.1 ? std::nan("") : std::round(wave);
    }
  if (kind == "no data") {
    r.heights = makeRaster("rough", width, height, seed).heights;
    r.valid.resize(r.heights.size());
    for (std::size_t p = 0; p < r.valid.size(); ++p) {
      r.valid[p] = random.uniform() < 0.8;
      if (!r.valid[p]) r.heights[p] = random.uniform() < 0.5 ? -9999 : 5000;
    }
  }
  return r;
}

TEST(TriangleScan, BlocksFindWhatTheRowsFind) {
  testing::Random random(71);
  std::uint64_t byRows = 0, byBlocks = 0, blockScans = 0;
  for (const char* kind : {"integers", "smooth", "rough", "far", "terraces", "nan", "no data"}) {
    for (const auto [width, height] : {std::pair{150u, 120u}, {37u, 61u}, {9u, 9u}}) {
      const Raster r = makeRaster(kind, width, height, 5 + width);
      const RasterSampler raster(r.heights.data(), width, height, r.valid);
      const HeightBlocks blocks(raster);
      std::vector<std::uint8_t> skip(r.heights.size());
      for (std::uint8_t& s : skip) s = random.uniform() < 0.05;
      ScanScratch scratch;
      for (int k = 0; k < 3000; ++k) {
        // Corners on pixels (as greedy insertion's), or anywhere (breaklines, crossings);
        // now and then a sliver along a row, a column or a diagonal.
        Corner c[3];
        for (Corner& p : c) {
          p.x = random.uniform() * (width - 1);
          p.y = random.uniform() * (height - 1);
          if (k % 2 == 0) {
            p.x = std::round(p.x);
            p.y = std::round(p.y);
          }
          p.z = random.uniform() * 80 - 20 + (std::string(kind) == "far" ? 1e7 : 0);
          if (std::string(kind) == "integers") p.z = std::floor(random.uniform() * 4);
        }
        // Level triangles on small integers: equal errors everywhere, the first pixel wins.
        if (std::string(kind) == "integers" && k % 3 == 0) c[1].z = c[2].z = c[0].z;
        if (k % 7 == 0) c[2] = {c[1].x + 0.5, c[0].y + 1e-9, c[2].z};
        if (k % 11 == 0)
          c[2] = {c[0].x + 3 * (c[1].x - c[0].x), c[0].y + 3 * (c[1].y - c[0].y) + 1, 0};
        // Half the scans take even small triangles by blocks.
        scratch.fromArea = k % 4 < 2 ? 0 : kBlockScanArea;
        const ScanResult rows = scanTriangle(c[0], c[1], c[2], raster, skip.data());
        const ScanResult bl =
            scanTriangle(c[0], c[1], c[2], raster, skip.data(), &blocks, &scratch);
        ASSERT_EQ(bl.pixel, rows.pixel) << kind << " " << width << " triangle " << k;
        ASSERT_EQ(bl.error, rows.error) << kind << " " << width << " triangle " << k;
        ASSERT_LE(bl.scanned, rows.scanned);
        byRows += rows.scanned;
        byBlocks += bl.scanned;
        blockScans += bl.scanned < rows.scanned;
      }
    }
  }
  // The blocks pass over pixels: a third of them at least, here.
  EXPECT_LT(3 * byBlocks, 2 * byRows) << byBlocks << " of " << byRows;
  EXPECT_GT(blockScans, 10000u);
}

}  // namespace
}  // namespace geocdt::terrain
