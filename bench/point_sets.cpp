#include "point_sets.h"

#include <cmath>
#include <random>

namespace bench {

std::vector<double> uniformPointsMt19937(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> xy(2 * n);
  for (double& v : xy) v = unit(rng);
  return xy;
}

std::vector<double> clustersOfManySpreads(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  constexpr int kClusters = 64;
  double cx[kClusters], cy[kClusters], sigma[kClusters];
  for (int c = 0; c < kClusters; ++c) {
    cx[c] = 0.1 + 0.8 * unit(rng);
    cy[c] = 0.1 + 0.8 * unit(rng);
    sigma[c] = 0.05 * std::pow(0.01, unit(rng));  // spreads from 5e-4 to 5e-2
  }
  std::vector<double> xy(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(rng() % kClusters);
    xy[2 * i] = cx[c] + sigma[c] * normal(rng);
    xy[2 * i + 1] = cy[c] + sigma[c] * normal(rng);
  }
  return xy;
}

geocdt::testing::PolylineSet randomSegments(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  geocdt::testing::PolylineSet set;
  for (std::size_t i = 0; i < count; ++i) {
    const double segment[4] = {unit(rng), unit(rng), unit(rng), unit(rng)};
    set.add(segment, 2);
  }
  return set;
}

}  // namespace bench
