#include "terrain/profile.h"

#include <algorithm>
#include <numeric>

#include "terrain/border_segments.h"
#include "terrain/candidate_queue.h"

namespace geocdt::terrain {

Profile simplifyProfile(const RasterSampler& raster, const MesherLimits& limits) {
  const bool row = raster.height() == 1;
  const std::uint32_t n = row ? raster.width() : raster.height();
  std::vector<double> xy, z;
  const auto addVertex = [&](std::uint32_t k) {
    xy.push_back(row ? k : 0.0);
    xy.push_back(row ? 0.0 : k);
    z.push_back(raster.at(k));  // pixel k along the line is pixel k of the raster
    return static_cast<std::uint32_t>(z.size() - 1);
  };
  BorderSegments segments;
  Profile p;
  // The runs of pixels with data: their ends are vertices, the pixels between wait.
  for (std::uint32_t k = 0; k < n;) {
    if (!raster.valid(k)) {
      ++k;
      continue;
    }
    std::uint32_t end = k;
    while (end + 1 < n && raster.valid(end + 1)) ++end;
    const std::uint32_t a = addVertex(k);
    if (end > k) segments.add(a, addVertex(end));
    k = end + 1;
  }
  CandidateQueue queue;
  const auto measure = [&](std::uint32_t s) {
    p.scannedPixels += segments.scan(s, xy.data(), z.data(), raster);
    if (segments[s].pixel >= 0 && segments[s].error > limits.maxError) {
      queue.set(s, segments[s].error);
    } else {
      queue.remove(s);
    }
  };
  for (std::uint32_t s = 0; s < segments.size(); ++s) measure(s);
  while (!queue.empty()) {
    if (limits.maxVertices > 0 && z.size() + std::uint64_t{1} > limits.maxVertices) break;
    const std::uint32_t s = queue.top();
    const std::uint32_t b = segments[s].b;
    const std::uint32_t v = addVertex(static_cast<std::uint32_t>(segments[s].pixel));
    segments[s].b = v;
    const std::uint32_t next = segments.add(v, b);
    measure(s);
    measure(next);
  }
  for (std::uint32_t s = 0; s < segments.size(); ++s)
    p.maxError = std::max(p.maxError, segments[s].error);
  // In order along the line.
  std::vector<std::uint32_t> order(z.size());
  std::iota(order.begin(), order.end(), 0);
  const int axis = row ? 0 : 1;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t u, std::uint32_t v) { return xy[2 * u + axis] < xy[2 * v + axis]; });
  for (const std::uint32_t v : order) {
    p.xy.push_back(xy[2 * v]);
    p.xy.push_back(xy[2 * v + 1]);
    p.z.push_back(z[v]);
  }
  return p;
}

}  // namespace geocdt::terrain
