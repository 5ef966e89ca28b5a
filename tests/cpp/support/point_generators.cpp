#include "point_generators.h"

#include <cmath>

namespace geocdt::testing {

double Random::gaussian() {
  const double u = 1.0 - uniform(), v = uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
}

std::vector<double> uniformPoints(std::size_t n, std::uint64_t seed) {
  Random r(seed);
  std::vector<double> xy(2 * n);
  for (double& v : xy) v = r.uniform();
  return xy;
}

std::vector<double> gaussianClusters(std::size_t n, std::uint64_t seed) {
  Random r(seed);
  std::vector<double> xy;
  xy.reserve(2 * n);
  const std::size_t clusters = 1 + n / 1000;
  std::vector<double> centres(2 * clusters);
  for (double& c : centres) c = r.uniform();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = r.next() % clusters;
    const double spread = 0.002 + 0.02 * static_cast<double>(k % 7) / 7.0;
    xy.push_back(centres[2 * k] + spread * r.gaussian());
    xy.push_back(centres[2 * k + 1] + spread * r.gaussian());
  }
  return xy;
}

std::vector<double> latticePoints(std::size_t side) {
  std::vector<double> xy;
  xy.reserve(2 * side * side);
  for (std::size_t j = 0; j < side; ++j)
    for (std::size_t i = 0; i < side; ++i) {
      xy.push_back(static_cast<double>(i));
      xy.push_back(static_cast<double>(j));
    }
  return xy;
}

std::vector<double> circlePoints(std::size_t n) {
  std::vector<double> xy;
  xy.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
    xy.push_back(std::cos(a));
    xy.push_back(std::sin(a));
  }
  return xy;
}

std::vector<double> collinearPoints(std::size_t n, std::uint64_t seed) {
  Random r(seed);
  std::vector<double> xy;
  xy.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    // Integers on the line y = 3x + 1: exactly collinear in doubles.
    const double t = static_cast<double>(r.next() % 100000);
    xy.push_back(t);
    xy.push_back(3 * t + 1);
  }
  return xy;
}

std::vector<double> transformed(const std::vector<double>& xy, double scale, double dx, double dy) {
  std::vector<double> out(xy.size());
  for (std::size_t i = 0; i < xy.size(); i += 2) {
    out[i] = xy[i] * scale + dx;
    out[i + 1] = xy[i + 1] * scale + dy;
  }
  return out;
}

}  // namespace geocdt::testing
