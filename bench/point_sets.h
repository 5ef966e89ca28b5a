#pragma once
// Synthetic inputs of the benchmarks, as flat x, y arrays. Deterministic for a given seed.
// Drawn with std::mt19937_64 and the standard distributions, unlike the tests' generators
// (tests/cpp/support/point_generators.h, a portable generator of their own): the names say
// which is which. Lattices come from there (testing::latticePoints).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polyline_file.h"

namespace bench {

// n points uniform in the unit square.
std::vector<double> uniformPointsMt19937(std::size_t n, std::uint64_t seed);

// n points in 64 gaussian clusters whose spreads range from 5e-4 to 5e-2 inside the unit
// square: dense spots next to empty space, which a uniform grid handles worst.
std::vector<double> clustersOfManySpreads(std::size_t n, std::uint64_t seed);

// Segments between random points of the unit square: long on average, with about
// 0.12 * count^2 crossings among them (two such segments cross with probability 25/108).
geocdt::testing::PolylineSet randomSegments(std::size_t count, std::uint64_t seed);

}  // namespace bench
