#pragma once
// Deterministic point sets for tests: each returns x0, y0, x1, y1, ...
#include <cstdint>
#include <vector>

namespace geocdt::testing {

std::vector<double> uniformPoints(std::size_t n, std::uint64_t seed);
std::vector<double> gaussianClusters(std::size_t n, std::uint64_t seed);
std::vector<double> latticePoints(std::size_t side);  // side x side integer grid
std::vector<double> circlePoints(std::size_t n);      // on a circle, rounded to doubles
std::vector<double> collinearPoints(std::size_t n, std::uint64_t seed);
// Each point times `scale`, then offset: exact when scale is a power of two.
std::vector<double> transformed(const std::vector<double>& xy, double scale, double dx, double dy);

// A small deterministic generator (xorshift64*), one per test, no global state.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}
  std::uint64_t next() {
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return state_ * 0x2545F4914F6CDD1Dull;
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double gaussian();

 private:
  std::uint64_t state_;
};

}  // namespace geocdt::testing
