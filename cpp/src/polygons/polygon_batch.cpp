// triangulatePolygons(): the batch checked, cut into ranges of polygons that the threads take
// in turn, each range triangulated polygon after polygon, and the ranges' arrays joined in
// polygon order.
#include <algorithm>
#include <atomic>

#include "base/in_parallel.h"
#include "geocdt/polygons.h"
#include "out_of_memory.h"
#include "polygons/batch_check.h"
#include "polygons/polygon_range.h"

namespace geocdt {

namespace {

// Below this many points a batch runs on one thread: starting one costs more than it saves.
constexpr std::size_t kParallelPoints = std::size_t{1} << 15;
// Ranges a thread, taken in turn: equal numbers of points are not equal work (tiles of
// different extents take different predicates), and small ranges even it out.
constexpr std::uint32_t kRangesPerThread = 32;

// What one range produced; range 0 writes straight into the caller's arrays.
struct RangeOutput {
  std::vector<std::uint32_t> triangles;
  std::vector<double> extras;
  PolygonStats stats;
  Status status;
};

std::size_t firstPointOf(const PolygonBatch& b, std::size_t p) {
  return b.ringOffsets[b.polygonOffsets[p]];
}

// Cuts the polygons into `ranges` ranges of about equal numbers of points: range i is
// polygons bounds[i] .. bounds[i + 1] (some empty when polygons are few).
std::vector<std::size_t> cut(const PolygonBatch& b, std::uint32_t ranges) {
  std::vector<std::size_t> bounds(ranges + 1, b.polygonCount);
  bounds[0] = 0;
  const std::size_t first = firstPointOf(b, 0), total = firstPointOf(b, b.polygonCount) - first;
  for (std::uint32_t i = 1; i < ranges; ++i) {
    const std::size_t target = first + total * i / ranges;
    std::size_t lo = bounds[i - 1], hi = b.polygonCount;
    while (lo < hi) {  // the first polygon that starts at or after target
      const std::size_t mid = lo + (hi - lo) / 2;
      if (firstPointOf(b, mid) < target) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    bounds[i] = lo;
  }
  return bounds;
}

void addStats(PolygonStats& to, const PolygonStats& from) {
  to.smallPath += from.smallPath;
  to.general += from.general;
  to.crossings += from.crossings;
}

// Appends range i's arrays to out, its extra points renumbered after those before it and its
// triangle offsets moved past the triangles before it.
void join(const PolygonBatch& b, const std::vector<std::size_t>& bounds, std::size_t i,
          RangeOutput& part, PolygonTriangles& out) {
  const auto trianglesBefore = static_cast<std::uint32_t>(out.triangles.size() / 3);
  const auto extrasBefore = static_cast<std::uint32_t>(out.extraPoints.size() / 2);
  std::uint32_t* ends = out.triangleOffsets.data() + 1;
  for (std::size_t p = bounds[i]; p < bounds[i + 1]; ++p) ends[p] += trianglesBefore;
  if (extrasBefore > 0 && !part.extras.empty()) {
    for (std::uint32_t& v : part.triangles)
      if (v >= b.pointCount) v += extrasBefore;
  }
  out.triangles.insert(out.triangles.end(), part.triangles.begin(), part.triangles.end());
  out.extraPoints.insert(out.extraPoints.end(), part.extras.begin(), part.extras.end());
  std::vector<std::uint32_t>().swap(part.triangles);
  std::vector<double>().swap(part.extras);
}

Status runBatch(const PolygonBatch& b, const PolygonOptions& options, PolygonTriangles& out,
                PolygonStats& stats) {
  out.triangleOffsets.assign(b.polygonCount + 1, 0);
  if (b.polygonCount == 0) return Status::success();
  const std::size_t points = firstPointOf(b, b.polygonCount) - firstPointOf(b, 0);
  std::uint32_t threads = 1;
  if (kThreadsBuilt && options.threads > 1 && points >= kParallelPoints)
    threads = static_cast<std::uint32_t>(
        std::min<std::size_t>({options.threads, b.polygonCount, points / (kParallelPoints / 2)}));
  const std::uint32_t ranges = threads == 1 ? 1 : threads * kRangesPerThread;
  const std::vector<std::size_t> bounds = cut(b, ranges);
  std::vector<RangeOutput> parts(ranges);
  // About one triangle a point (fewer on tiles: rings close on a repeated point): room for
  // that at once, so that the arrays rarely grow. Range 0 writes into the caller's array,
  // which gets room for every range's, so that joining the others moves nothing.
  const auto reserve = [&](std::size_t i, std::vector<std::uint32_t>& triangles) {
    const std::size_t last = i == 0 ? b.polygonCount : bounds[i + 1];
    triangles.reserve(3 * (firstPointOf(b, last) - firstPointOf(b, bounds[i])));
  };
  std::atomic<std::uint32_t> next{0};
  stats.threads = inParallel(threads, [&](std::uint32_t) {
    PolygonRange range;  // its scratch memory kept from range to range
    for (std::uint32_t i = next++; i < ranges; i = next++) {
      RangeOutput& part = parts[i];
      std::vector<std::uint32_t>& triangles = i == 0 ? out.triangles : part.triangles;
      std::vector<double>& extras = i == 0 ? out.extraPoints : part.extras;
      reserve(i, triangles);
      part.status = range.run(b, options.fill, bounds[i], bounds[i + 1], triangles, extras,
                              out.triangleOffsets.data() + 1 + bounds[i], part.stats);
    }
  });
  for (std::size_t i = 0; i < ranges; ++i) {  // the first failure in polygon order
    if (!parts[i].status.ok()) return parts[i].status;
    addStats(stats, parts[i].stats);
  }
  if (ranges > 1) {
    std::size_t total = out.triangles.size(), extras = out.extraPoints.size();
    for (std::size_t i = 1; i < ranges; ++i) {
      total += parts[i].triangles.size();
      extras += parts[i].extras.size();
    }
    out.triangles.reserve(total);
    out.extraPoints.reserve(extras);
    for (std::size_t i = 1; i < ranges; ++i) join(b, bounds, i, parts[i], out);
  }
  return Status::success();
}

}  // namespace

Status triangulatePolygons(const PolygonBatch& batch, const PolygonOptions& options,
                           PolygonTriangles& out, PolygonStats* stats) {
  out = PolygonTriangles();
  Status s = checkPolygonBatch(batch);
  if (!s.ok()) return s;
  PolygonStats counted;
  s = catchOutOfMemory([&] { return runBatch(batch, options, out, counted); },
                       [&] { out = PolygonTriangles(); });
  if (!s.ok()) out = PolygonTriangles();
  if (stats) *stats = counted;
  return s;
}

}  // namespace geocdt
