#pragma once
// The length of (x, y) from IEEE operations alone (each rounded the same on every platform),
// where std::hypot differs between C libraries in the last bit: decisions built on it (a
// chain's choice, a vertex's snapping) must come out alike natively and in WebAssembly.
// Within about two ulps; no overflow or underflow short of the result's own.
#include <cmath>
#include <utility>

namespace geocdt {

inline double euclideanNorm(double x, double y) {
  double a = std::fabs(x), b = std::fabs(y);
  if (a < b) std::swap(a, b);
  if (a == 0 || std::isinf(a)) return a;
  const double r = b / a;
  return a * std::sqrt(1 + r * r);
}

}  // namespace geocdt
