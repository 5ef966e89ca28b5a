#pragma once
// Synthetic inputs of the benchmarks, as flat x, y arrays. Deterministic for a given seed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polyline_file.h"

namespace bench {

// n points uniform in the unit square.
std::vector<double> uniformPoints(std::size_t n, std::uint64_t seed);

// n points in gaussian clusters of very different sizes inside the unit square: dense
// spots next to empty space, which a uniform grid handles worst.
std::vector<double> gaussianClusters(std::size_t n, std::uint64_t seed);

// side x side integer lattice points, row by row: massively cocircular.
std::vector<double> lattice(std::size_t side);

// Segments between random points of the unit square: long on average, with about
// 0.12 * count^2 crossings among them (two such segments cross with probability 25/108).
geocdt::testing::PolylineSet randomSegments(std::size_t count, std::uint64_t seed);

}  // namespace bench
