// The choice between the two diagonals of a quad (terrain/diagonal_fit.h) against a brute
// force over every pixel of the raster: the pixels strictly inside the quad (exact
// orientation tests), each interpolated by barycentric weights in the triangle of each mesh
// that holds it. Where the largest errors differ, the function must pick the smaller; where
// no pixel is inside, the edge stays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/predicates.h"
#include "point_generators.h"
#include "terrain/diagonal_fit.h"
#include "terrain/raster_sampler.h"

namespace geocdt::terrain {
namespace {

struct Raster {
  std::uint32_t width, height;
  std::vector<double> heights;
  std::vector<std::uint8_t> valid;
};

Raster makeRaster(const std::string& kind, std::uint32_t width, std::uint32_t height,
                  testing::Random& random) {
  Raster r{width, height, std::vector<double>(std::size_t{width} * height), {}};
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i) {
      const double wave = 30 * std::sin(i * 0.21) * std::cos(j * 0.17) + 0.5 * j;
      double& z = r.heights[std::size_t{j} * width + i];
      z = kind == "integers" ? std::floor(random.uniform() * 5) : wave + 10 * random.uniform();
    }
  if (kind == "no data") {
    r.valid.resize(r.heights.size());
    for (std::size_t p = 0; p < r.valid.size(); ++p) {
      r.valid[p] = random.uniform() < 0.85;
      if (!r.valid[p]) r.heights[p] = -9999;
    }
  }
  return r;
}

// The height at (x, y) of the plane through u, v, w, by barycentric weights.
double interpolate(const Corner& u, const Corner& v, const Corner& w, double x, double y) {
  const double area = (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x);
  const double wu = ((v.x - x) * (w.y - y) - (v.y - y) * (w.x - x)) / area;
  const double wv = ((w.x - x) * (u.y - y) - (w.y - y) * (u.x - x)) / area;
  return wu * u.z + wv * v.z + (1 - wu - wv) * w.z;
}

bool leftOf(const Corner& u, const Corner& v, double x, double y) {
  return orient2d(u.x, u.y, v.x, v.y, x, y) == Sign::Positive;
}

TEST(DiagonalFit, PicksTheDiagonalWithTheSmallerLargestError) {
  testing::Random random(93);
  int picked[2] = {0, 0}, empty = 0, decided = 0;
  for (const char* kind : {"integers", "rough", "no data"}) {
    const Raster r = makeRaster(kind, 40, 30, random);
    const RasterSampler raster(r.heights.data(), r.width, r.height, r.valid);
    std::vector<std::uint8_t> skip(r.heights.size());
    for (std::uint8_t& s : skip) s = random.uniform() < 0.1;
    for (int k = 0; k < 4000; ++k) {
      // Four points on a circle, counter-clockwise a, d, b, p; on pixels half of the time
      // (then no longer quite on it), small and large.
      const double cx = 3 + random.uniform() * 34, cy = 3 + random.uniform() * 24;
      const double radius = 0.7 + random.uniform() * (k % 3 == 0 ? 2 : 12);
      double angles[4];
      for (double& t : angles) t = random.uniform() * 2 * M_PI;
      std::sort(angles, angles + 4);
      Corner c[4];
      for (int i = 0; i < 4; ++i) {
        c[i].x = std::clamp(cx + radius * std::cos(angles[i]), 0.0, 39.0);
        c[i].y = std::clamp(cy + radius * std::sin(angles[i]), 0.0, 29.0);
        if (k % 2 == 0) c[i].x = std::round(c[i].x), c[i].y = std::round(c[i].y);
        c[i].z = random.uniform() * 60 - 10;
        if (std::string(kind) == "integers") c[i].z = std::floor(random.uniform() * 5);
      }
      const Corner &a = c[0], &d = c[1], &b = c[2], &p = c[3];
      bool convex = true;
      for (int i = 0; i < 4; ++i)
        convex = convex && leftOf(c[i], c[(i + 1) % 4], c[(i + 2) % 4].x, c[(i + 2) % 4].y);
      if (!convex) continue;
      double viaAb = 0, viaPd = 0;
      bool inner = false;
      for (std::uint32_t j = 0; j < r.height; ++j)
        for (std::uint32_t i = 0; i < r.width; ++i) {
          const std::size_t pixel = std::size_t{j} * r.width + i;
          const double x = i, y = j;
          if (skip[pixel] || (!r.valid.empty() && !r.valid[pixel])) continue;
          if (!(leftOf(a, d, x, y) && leftOf(d, b, x, y) && leftOf(b, p, x, y) &&
                leftOf(p, a, x, y)))
            continue;
          inner = true;
          const double h = r.heights[pixel];
          const double zAb =
              leftOf(b, a, x, y) ? interpolate(b, a, d, x, y) : interpolate(a, b, p, x, y);
          const double zPd =
              leftOf(p, d, x, y) ? interpolate(d, b, p, x, y) : interpolate(a, d, p, x, y);
          viaAb = std::max(viaAb, std::fabs(h - zAb));
          viaPd = std::max(viaPd, std::fabs(h - zPd));
        }
      const bool other = otherDiagonalFitsBetter(a, b, d, p, raster, skip.data());
      if (std::fabs(viaAb - viaPd) > 1e-9 * (1 + viaAb)) {
        ASSERT_EQ(other, viaPd < viaAb) << kind << " quad " << k << ": " << viaAb << " " << viaPd;
        ++decided;
      } else if (!inner) {
        ASSERT_FALSE(other) << kind << " quad " << k << ": no pixel inside, yet a flip";
        ++empty;
      }
      ++picked[other];
    }
  }
  // Both answers, often, and quads with no pixel inside.
  EXPECT_GT(decided, 3000);
  EXPECT_GT(empty, 300);
  EXPECT_GT(picked[0], 1000);
  EXPECT_GT(picked[1], 1000);
}

}  // namespace
}  // namespace geocdt::terrain
