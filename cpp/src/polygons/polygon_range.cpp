#include "polygons/polygon_range.h"

#include <string>

#include "polygons/tiny_ring.h"

namespace geocdt {

namespace {

// Polygons with more points go straight to the general engine, whose spatial sort and grid
// pay for themselves there (bench/EXPERIMENTS.md, polygons).
constexpr std::uint32_t kSmallPathMost = 1u << 20;

}  // namespace

Status PolygonRange::run(const PolygonBatch& batch, FillRule fill, std::size_t first,
                         std::size_t last, std::vector<std::uint32_t>& triangles,
                         std::vector<double>& extras, std::uint32_t* ends, PolygonStats& stats) {
  const std::uint32_t* rings = batch.ringOffsets;
  const auto extraBase = static_cast<std::uint32_t>(batch.pointCount);
  for (std::size_t p = first; p < last; ++p) {
    const std::uint32_t r0 = batch.polygonOffsets[p], r1 = batch.polygonOffsets[p + 1];
    const std::uint32_t start = rings[r0], n = rings[r1] - start;
    if (n > 0) {
      ringStarts_.resize(r1 - r0 + 1);
      for (std::uint32_t r = r0; r <= r1; ++r) ringStarts_[r - r0] = rings[r] - start;
      const double* xy = batch.xy + 2 * static_cast<std::size_t>(start);
      if ((r1 - r0 == 1 && triangulateTinyRing(xy, n, start, triangles)) ||
          (n <= kSmallPathMost &&
           small_.triangulate(xy, n, ringStarts_.data(), r1 - r0, fill, start, triangles))) {
        ++stats.smallPath;
      } else {
        const std::size_t before = extras.size();
        Status s = general_.triangulate(xy, n, ringStarts_.data(), r1 - r0, fill, start, extraBase,
                                        triangles, extras);
        if (!s.ok()) {
          s.message = "polygon " + std::to_string(p) + ": " + s.message;
          s.index = p;
          s.segment = kNoIndex;
          return s;
        }
        ++stats.general;
        stats.crossings += (extras.size() - before) / 2;
      }
    }
    ends[p - first] = static_cast<std::uint32_t>(triangles.size() / 3);
  }
  return Status::success();
}

}  // namespace geocdt
