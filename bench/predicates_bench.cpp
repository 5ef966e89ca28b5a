// Nanoseconds per call of the predicates on the inputs that take each path: random inputs
// (the filter decides), exactly degenerate grid inputs with exact differences, near-
// degenerate inputs whose differences round, tiny inputs that must be rescaled, and mixed
// magnitudes that need big integers.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geocdt/predicates.h"

namespace {

constexpr int kCases = 4096;  // a power of two: the loop index wraps with a mask
using Rng = std::mt19937_64;

double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }
double symmetric(Rng& rng) { return 2.0 * unit(rng) - 1.0; }
int pick(Rng& rng, int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }

enum class Kind { Random, GridDegenerate, RoundedNearDegenerate, Tiny, Mixed };

// kCases orientation triples, 6 doubles each.
std::vector<double> orient_cases(Kind kind) {
  Rng rng(42);
  std::vector<double> v(6 * kCases);
  for (int i = 0; i < kCases; ++i) {
    double* p = &v[6 * i];
    switch (kind) {
      case Kind::Random:
        for (int j = 0; j < 6; ++j) p[j] = symmetric(rng);
        break;
      case Kind::GridDegenerate:
      case Kind::Tiny: {  // three lattice points on a line, at 1e-300 for Tiny
        const double scale = kind == Kind::Tiny ? 1e-300 : 1.0;
        const double ox = pick(rng, 1000), oy = pick(rng, 1000);
        const double sx = pick(rng, 21) - 10, sy = pick(rng, 21) - 10;
        for (int j = 0; j < 3; ++j) {
          const int k = pick(rng, 9) - 4;
          p[2 * j] = (ox + k * sx) * scale;
          p[2 * j + 1] = (oy + k * sy) * scale;
        }
        break;
      }
      case Kind::RoundedNearDegenerate:  // on a line through the origin: differences round
        for (int j = 0; j < 3; ++j) {
          const double t = symmetric(rng);
          p[2 * j] = 0.1 + 0.7 * t;
          p[2 * j + 1] = -0.3 + 0.4 * t;
        }
        break;
      case Kind::Mixed:  // a and c far out on a line through the origin, b tiny
        p[0] = 1e150 * symmetric(rng);
        p[1] = 1e150 * symmetric(rng);
        p[2] = 1e-300 * symmetric(rng);
        p[3] = 1e-300 * symmetric(rng);
        p[4] = -p[0];
        p[5] = -p[1];
        break;
    }
  }
  return v;
}

// kCases in-circle quadruples, 8 doubles each.
std::vector<double> incircle_cases(Kind kind) {
  Rng rng(43);
  std::vector<double> v(8 * kCases);
  for (int i = 0; i < kCases; ++i) {
    double* p = &v[8 * i];
    switch (kind) {
      case Kind::Random:
        for (int j = 0; j < 8; ++j) p[j] = symmetric(rng);
        break;
      case Kind::GridDegenerate:
      case Kind::Tiny: {  // the corners of a lattice rectangle, at 1e-300 for Tiny
        const double scale = kind == Kind::Tiny ? 1e-300 : 1.0;
        const double x0 = pick(rng, 1000), y0 = pick(rng, 1000);
        const double x1 = x0 + 1 + pick(rng, 5), y1 = y0 + 1 + pick(rng, 5);
        const double corners[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
        for (int j = 0; j < 8; ++j) p[j] = corners[j] * scale;
        break;
      }
      case Kind::RoundedNearDegenerate: {  // on a circle around the origin
        for (int j = 0; j < 4; ++j) {
          const double angle = 6.283185307179586 * (j + 0.5 * unit(rng)) / 4;
          p[2 * j] = 0.3 * std::cos(angle) + 0.01;
          p[2 * j + 1] = 0.3 * std::sin(angle) - 0.02;
        }
        break;
      }
      case Kind::Mixed: {  // three axis points at 1e150, the fourth moved off by ~1e-300
        const double axis[4][2] = {{1e150, 0}, {0, 1e150}, {-1e150, 0}, {0, -1e150}};
        const int skip = pick(rng, 4);
        for (int j = 0; j < 4; ++j) {
          p[2 * j] = axis[(skip + 1 + j) % 4][0];
          p[2 * j + 1] = axis[(skip + 1 + j) % 4][1];
        }
        double& zero = p[6] == 0 ? p[6] : p[7];
        zero = 1e-300 * symmetric(rng);
        break;
      }
    }
  }
  return v;
}

void BM_orient2d(benchmark::State& state) {
  const std::vector<double> v = orient_cases(static_cast<Kind>(state.range(0)));
  int i = 0;
  for (auto _ : state) {
    const double* p = &v[6 * i];
    benchmark::DoNotOptimize(geocdt::orient2d(p[0], p[1], p[2], p[3], p[4], p[5]));
    i = (i + 1) & (kCases - 1);
  }
}

void BM_incircle(benchmark::State& state) {
  const std::vector<double> v = incircle_cases(static_cast<Kind>(state.range(0)));
  int i = 0;
  for (auto _ : state) {
    const double* p = &v[8 * i];
    benchmark::DoNotOptimize(geocdt::incircle(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]));
    i = (i + 1) & (kCases - 1);
  }
}

void kinds(benchmark::internal::Benchmark* b) {
  b->ArgName("kind");  // 0 random, 1 grid degenerate, 2 rounded near-degenerate, 3 tiny, 4 mixed
  for (int k = 0; k <= 4; ++k) b->Arg(k);
}

}  // namespace

BENCHMARK(BM_orient2d)->Apply(kinds);
BENCHMARK(BM_incircle)->Apply(kinds);

BENCHMARK_MAIN();
