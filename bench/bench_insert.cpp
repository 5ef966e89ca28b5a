// One insertPoints call, for profilers: valgrind --tool=callgrind counts its instructions,
// and two builds of it run in alternation compare their times (see EXPERIMENTS.md).
// Usage: bench_insert [points] [uniform|clusters] [brio|hilbert|input] [copy|adopt]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"
#include "point_sets.h"

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const std::string points = argc > 2 ? argv[2] : "uniform";
  const std::string order = argc > 3 ? argv[3] : "brio";
  const bool adopt = argc > 4 && std::strcmp(argv[4], "adopt") == 0;
  std::vector<double> xy =
      points == "clusters" ? bench::clustersOfManySpreads(n, 5) : bench::uniformPointsMt19937(n, 3);
  geocdt::Options options;
  options.order = order == "hilbert" ? geocdt::InsertionOrder::Hilbert
                  : order == "input" ? geocdt::InsertionOrder::Input
                                     : geocdt::InsertionOrder::Brio;
  const auto start = std::chrono::steady_clock::now();
  geocdt::Triangulation t(options);
  const geocdt::Status s = adopt ? t.insertPoints(std::move(xy)) : t.insertPoints(xy.data(), n);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!s.ok()) {
    std::fprintf(stderr, "bench_insert: %s\n", s.message.c_str());
    return 1;
  }
  const geocdt::Stats& stats = t.stats();
  std::printf("%zu %s points, %s order, %s: %.1f ms, %.3f flips and %.3f walk steps a point\n", n,
              points.c_str(), order.c_str(), adopt ? "buffer taken over" : "copied", ms,
              static_cast<double>(stats.flips) / static_cast<double>(n),
              static_cast<double>(stats.walkSteps) / static_cast<double>(stats.locates));
  return 0;
}
