// Editing in place, natively: removals and moves of free points against triangulating the
// points, and removals of polylines at two mesh sizes. Runs alternate within one process;
// medians are printed with the targets (issue: editing in place).
//
//   bench_editing [points] [runs]        (default 1,000,000 points, 3 runs)
//
// - 100,000 removals from the mesh, one call each, in random order: at most 0.5x the time of
//   triangulating the points (aim: 0.25x).
// - 100,000 moves of free points to random places: at most 1.0x that time.
// - 100,000 small moves of free points (up to a quarter of the mean spacing, as a drag or an
//   animation frame moves them; no target): most stay within their star and take flips only.
// - Removing a polyline costs its length and crossings, not the mesh size: 200 polylines of
//   20 points, crossing each other, removed one by one from meshes of points / 10 and points
//   vertices of the same density (the larger spreads wider); the time per crossing removed at
//   the larger size within 1.5x the smaller's (more memory, more cache misses).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "geocdt/triangulation.h"

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<double> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1000);
  std::vector<double> xy(2 * n);
  for (double& v : xy) v = u(random);
  return xy;
}

struct PointRun {
  double triangulate, removals, moves, smallMoves, batch;
};

// Triangulates n points, then removes `edits` of them, moves `edits` others to random places
// and `edits` more a little, one call each; then removes `edits` more in one removePoints call.
PointRun pointRun(const std::vector<double>& xy, std::size_t edits, std::uint64_t seed) {
  const std::size_t n = xy.size() / 2;
  geocdt::Triangulation t;
  std::vector<std::uint32_t> ids(n);
  const auto a = Clock::now();
  if (!t.insertPoints(xy.data(), n, ids.data()).ok()) std::abort();
  const auto b = Clock::now();
  std::mt19937_64 random(seed);
  std::shuffle(ids.begin(), ids.end(), random);
  std::uniform_real_distribution<double> u(0, 1000);
  std::vector<double> places(2 * edits);
  for (double& v : places) v = u(random);
  const double reach = 250 / std::sqrt(static_cast<double>(n));  // a quarter of the spacing
  std::uniform_real_distribution<double> offset(-reach, reach);
  std::vector<double> nudges(2 * edits);
  for (std::size_t k = 0; k < edits; ++k) {
    nudges[2 * k] = xy[2 * ids[2 * edits + k]] + offset(random);
    nudges[2 * k + 1] = xy[2 * ids[2 * edits + k] + 1] + offset(random);
  }
  const auto c = Clock::now();
  for (std::size_t k = 0; k < edits; ++k)
    if (!t.removePoint(ids[k]).ok()) std::abort();
  const auto d = Clock::now();
  for (std::size_t k = 0; k < edits; ++k)
    if (!t.movePoint(ids[edits + k], places[2 * k], places[2 * k + 1]).ok()) std::abort();
  const auto e = Clock::now();
  for (std::size_t k = 0; k < edits; ++k)
    if (!t.movePoint(ids[2 * edits + k], nudges[2 * k], nudges[2 * k + 1]).ok()) std::abort();
  const auto f = Clock::now();
  if (!t.removePoints(ids.data() + 3 * edits, edits).ok()) std::abort();
  const auto g = Clock::now();
  return {milliseconds(a, b), milliseconds(c, d), milliseconds(d, e), milliseconds(e, f),
          milliseconds(f, g)};
}

struct LineRun {
  double milliseconds;
  std::uint64_t crossings;
};

// 200 polylines of 20 points across [100, 900]^2 in a mesh of n points at 0.1 a square unit
// (a larger mesh spreads wider): the time to remove them all, one call each, and the
// crossings they had made. The polylines meet the same density of points at any size.
LineRun lineRun(std::size_t n, std::uint64_t seed) {
  geocdt::Triangulation t;
  std::vector<double> xy = uniform(n, seed);
  const double side = std::sqrt(static_cast<double>(n) * 10);
  for (double& v : xy) v *= side / 1000;
  if (!t.insertPoints(xy.data(), n).ok()) std::abort();
  std::mt19937_64 random(seed + 1);
  std::uniform_real_distribution<double> u(100, 900);
  // Alternately near-horizontal and near-vertical zigzags: each crosses about half the others.
  for (int k = 0; k < 200; ++k) {
    const double base = u(random);
    std::vector<double> line;
    for (int i = 0; i < 20; ++i) {
      const double along = 100 + 800 * i / 19.0, across = base + (u(random) - 500) * 0.01;
      line.push_back(k % 2 ? across : along);
      line.push_back(k % 2 ? along : across);
    }
    if (!t.insertPolyline(line.data(), line.size() / 2).ok()) std::abort();
  }
  const std::uint64_t crossings = t.stats().crossings;
  const auto a = Clock::now();
  for (std::size_t k = 0; k < 200; ++k)
    if (!t.removePolyline(k).ok()) std::abort();
  const auto b = Clock::now();
  return {milliseconds(a, b), crossings};
}

const char* verdict(bool met) { return met ? "met" : "MISSED"; }

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::size_t edits = n / 10;
  const std::vector<double> xy = uniform(n, 1);
  std::vector<double> triangulate, removals, moves, smallMoves, removalRatio, moveRatio,
      smallMoveRatio, batch, batchRatio;
  std::vector<double> smallLines, largeLines;
  std::uint64_t smallCrossings = 0, largeCrossings = 0;
  for (int run = 0; run < runs; ++run) {
    const PointRun p = pointRun(xy, edits, 10 + run);
    triangulate.push_back(p.triangulate);
    removals.push_back(p.removals);
    moves.push_back(p.moves);
    removalRatio.push_back(p.removals / p.triangulate);
    moveRatio.push_back(p.moves / p.triangulate);
    smallMoves.push_back(p.smallMoves);
    smallMoveRatio.push_back(p.smallMoves / p.triangulate);
    batch.push_back(p.batch);
    batchRatio.push_back(p.batch / p.triangulate);
    const LineRun small = lineRun(n / 10, 20 + run), large = lineRun(n, 20 + run);
    smallLines.push_back(small.milliseconds / static_cast<double>(small.crossings));
    largeLines.push_back(large.milliseconds / static_cast<double>(large.crossings));
    smallCrossings = small.crossings;
    largeCrossings = large.crossings;
  }
  const double rr = median(removalRatio), mr = median(moveRatio);
  const double lineRatio = median(largeLines) / median(smallLines);
  std::printf("%zu points, %d runs (medians)\n", n, runs);
  std::printf("  triangulating: %.1f ms\n", median(triangulate));
  std::printf("  %zu removals, one call each: %.1f ms = %.3fx (target <= 0.5x, aim 0.25x): %s\n",
              edits, median(removals), rr, verdict(rr <= 0.5));
  std::printf("  %zu moves of free points: %.1f ms = %.3fx (target <= 1.0x): %s\n", edits,
              median(moves), mr, verdict(mr <= 1.0));
  std::printf("  %zu small moves (up to a quarter of the spacing): %.1f ms = %.3fx (no target)\n",
              edits, median(smallMoves), median(smallMoveRatio));
  std::printf("  %zu more removals in one removePoints call: %.1f ms = %.3fx (no target)\n", edits,
              median(batch), median(batchRatio));
  std::printf(
      "  removing 200 polylines: %.2f us a crossing at %zu points (%llu crossings), %.2f us at "
      "%zu (%llu): %.2fx (target: within 1.5x): %s\n",
      1000 * median(smallLines), n / 10, static_cast<unsigned long long>(smallCrossings),
      1000 * median(largeLines), n, static_cast<unsigned long long>(largeCrossings), lineRatio,
      verdict(lineRatio <= 1.5));
  return 0;
}
