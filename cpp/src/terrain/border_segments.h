#pragma once
// The border's simplification: the edges of the mesh's boundary (the raster's edges, or the
// edges around the area with data) lie on grid lines, and the pixels on them are measured
// against the line between the edge's two ends only, never against a triangle. So the
// vertices a border gets depend on its own pixels alone: the same in two tiles that share
// it. Each segment's candidate is its pixel farthest from that line; splitting there until
// every pixel is within the bound gives the same vertices in whatever order it goes.
#include <cstdint>
#include <vector>

#include "terrain/raster_sampler.h"

namespace geocdt::terrain {

struct BorderSegment {
  std::uint32_t a, b;  // vertex ids of its ends
  double error = 0;
  std::int64_t pixel = -1;  // the pixel farthest from the line (the first along the line)
};

class BorderSegments {
 public:
  void clear() { segments_.clear(); }
  std::size_t size() const { return segments_.size(); }
  BorderSegment& operator[](std::size_t i) { return segments_[i]; }
  const BorderSegment& operator[](std::size_t i) const { return segments_[i]; }
  // A new segment between vertices a and b; returns its index.
  std::uint32_t add(std::uint32_t a, std::uint32_t b) {
    segments_.push_back({a, b});
    return static_cast<std::uint32_t>(segments_.size() - 1);
  }

  // Fills segment i's candidate from the pixels strictly between its ends (positions in xy,
  // heights in z). A segment off the grid lines (none is, by construction) has none.
  // Returns the pixels measured.
  std::uint64_t scan(std::uint32_t i, const double* xy, const double* z,
                     const RasterSampler& raster);

 private:
  std::vector<BorderSegment> segments_;
};

}  // namespace geocdt::terrain
