#include "geocdt_runs.h"

#include "cgal_reference.h"
#include "heap_counter.h"

namespace bench {
namespace {

std::string describe(const geocdt::Status& status) {
  std::string text = status.message;
  if (status.index != geocdt::kNoIndex) text += " (index " + std::to_string(status.index);
  if (status.segment != geocdt::kNoIndex) text += ", segment " + std::to_string(status.segment);
  if (status.index != geocdt::kNoIndex) text += ")";
  return text.empty() ? "error status without a message" : text;
}

}  // namespace

bool geocdtDelaunay(const std::vector<double>& xy, const geocdt::Options& options, Sample& sample,
                    std::string& error) {
  const std::size_t heapBefore = heapInUse();
  resetHeapPeak();
  const std::uint64_t start = nowNanos();
  geocdt::Triangulation triangulation(options);
  const geocdt::Status status = triangulation.insertPoints(xy.data(), xy.size() / 2);
  sample.pointSeconds = secondsSince(start);
  sample.peakBytes = heapPeak() - heapBefore;
  if (!status.ok()) {
    error = describe(status);
    return false;
  }
  const geocdt::Stats& stats = triangulation.stats();
  sample.walkSteps = stats.walkSteps;
  sample.locates = stats.locates;
  sample.flips = stats.flips;
  sample.vertices = triangulation.vertexCount();
  sample.triangles = triangulation.triangleCount();
  return true;
}

bool geocdtDelaunayAdopted(const std::vector<double>& xy, Sample& sample, std::string& error) {
  const std::size_t heapBefore = heapInUse();
  resetHeapPeak();
  std::vector<double> buffer(xy);
  std::vector<std::uint32_t> ids(xy.size() / 2);
  const std::uint64_t start = nowNanos();
  geocdt::Triangulation triangulation;
  const geocdt::Status status = triangulation.insertPoints(std::move(buffer), ids.data());
  if (!status.ok()) {
    error = describe(status);
    return false;
  }
  const geocdt::Stats stats = triangulation.stats();
  const geocdt::Mesh mesh = triangulation.release();
  sample.pointSeconds = secondsSince(start);
  sample.peakBytes = heapPeak() - heapBefore;
  sample.walkSteps = stats.walkSteps;
  sample.locates = stats.locates;
  sample.flips = stats.flips;
  sample.vertices = mesh.points.size() / 2;
  sample.triangles = mesh.triangles.size() / 3;
  return true;
}

bool geocdtDelaunayThenLate(const std::vector<double>& xy, const std::vector<double>& late,
                            const std::vector<double>& queries, const geocdt::Options& options,
                            Sample& sample, std::string& error) {
  std::uint64_t start = nowNanos();
  geocdt::Triangulation triangulation(options);
  geocdt::Status status = triangulation.insertPoints(xy.data(), xy.size() / 2);
  sample.pointSeconds = secondsSince(start);
  if (!status.ok()) {
    error = describe(status);
    return false;
  }
  const geocdt::Stats before = triangulation.stats();
  sample.walkSteps = before.walkSteps;
  sample.locates = before.locates;
  start = nowNanos();
  status = triangulation.insertPoints(late.data(), late.size() / 2);
  sample.edgeSeconds = secondsSince(start);
  if (!status.ok()) {
    error = describe(status);
    return false;
  }
  sample.lateWalkSteps = triangulation.stats().walkSteps - before.walkSteps;
  sample.lateLocates = triangulation.stats().locates - before.locates;
  std::uint64_t found = 0;
  start = nowNanos();
  for (std::size_t i = 0; i + 1 < queries.size(); i += 2) {
    found += triangulation.locate(queries[i], queries[i + 1]).kind == geocdt::Location::Kind::Face;
  }
  sample.extraSeconds = secondsSince(start);
  sample.vertices = triangulation.vertexCount();
  sample.triangles = found;  // queries that landed strictly inside a triangle
  return true;
}

bool geocdtConstrained(const std::vector<double>& freePoints,
                       const geocdt::testing::PolylineSet& polylines, ConstrainedCalls calls,
                       Sample& sample, std::string& error, const geocdt::Options& options) {
  std::vector<double> points = freePoints;
  if (calls == ConstrainedCalls::PointsThenPolylines) {
    points.insert(points.end(), polylines.xy.begin(), polylines.xy.end());
  }
  const std::vector<geocdt::PolylineView> views = polylines.views();

  const std::size_t heapBefore = heapInUse();
  resetHeapPeak();
  std::uint64_t start = nowNanos();
  geocdt::Triangulation triangulation(options);
  geocdt::Status status = triangulation.insertPoints(points.data(), points.size() / 2);
  sample.pointSeconds = secondsSince(start);
  if (!status.ok()) {
    error = "insertPoints: " + describe(status);
    return false;
  }
  start = nowNanos();
  status = triangulation.insertPolylines(views.data(), views.size());
  sample.edgeSeconds = secondsSince(start);
  sample.peakBytes = heapPeak() - heapBefore;
  if (!status.ok()) {
    error = "insertPolylines: " + describe(status);
    return false;
  }
  const geocdt::Stats& stats = triangulation.stats();
  sample.crossings = stats.crossings;
  sample.walkSteps = stats.walkSteps;
  sample.locates = stats.locates;
  sample.flips = stats.flips;
  sample.vertices = triangulation.vertexCount();
  const geocdt::Mesh mesh = triangulation.mesh();
  sample.triangles = mesh.triangles.size() / 3;
  countBadTriangles(mesh.points, mesh.triangles, sample);
  return true;
}

}  // namespace bench
