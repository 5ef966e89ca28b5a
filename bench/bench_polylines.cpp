// One triangulate() call on a .gpl dataset, for profilers and for checking that a change
// leaves the output as it was: valgrind --tool=callgrind counts its instructions, and the
// hash covers every array of the mesh with inside flags and regions.
// Usage: bench_polylines FILE.gpl [constrained|points|always] [hash]
//   constrained (default): the polylines as constraints, in one call;
//   points: the same points with no constraints, for the cost of the constraints alone;
//   always: constrained, snap-rounded in every call (snap rounding's cost on real data).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"
#include "heap_counter.h"
#include "polyline_file.h"

namespace {

// FNV-1a over the bytes of each array, with its length, in a fixed order.
class Hash {
 public:
  template <typename T>
  void add(const std::vector<T>& v) {
    const std::uint64_t n = v.size();
    bytes(&n, sizeof n);
    bytes(v.data(), v.size() * sizeof(T));
  }
  std::uint64_t value() const { return h_; }

 private:
  void bytes(const void* data, std::size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
  }
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_polylines FILE.gpl [constrained|points|always] [hash]\n");
    return 2;
  }
  geocdt::testing::PolylineSet set;
  const std::string error = geocdt::testing::readPolylineFile(argv[1], set);
  if (!error.empty()) {
    std::fprintf(stderr, "bench_polylines: %s\n", error.c_str());
    return 1;
  }
  const bool pointsOnly = argc > 2 && std::strcmp(argv[2], "points") == 0;
  geocdt::Options options;
  if (argc > 2 && std::strcmp(argv[2], "always") == 0)
    options.snapRounding = geocdt::SnapRounding::Always;
  const bool hash = argc > 3 && std::strcmp(argv[3], "hash") == 0;
  const std::vector<geocdt::PolylineView> views = set.views();
  geocdt::MeshOptions meshOptions;
  if (hash) {
    meshOptions.insideFlags = true;
    meshOptions.regions = true;
    for (std::size_t i = 0; i < views.size(); ++i)
      meshOptions.polylinePolygons.push_back(static_cast<std::int32_t>(i));
  }
  const std::size_t heapBefore = bench::heapInUse();
  bench::resetHeapPeak();
  const auto start = std::chrono::steady_clock::now();
  geocdt::Triangulation t(options);
  std::vector<std::uint32_t> ids(set.pointCount());
  const geocdt::Status s = pointsOnly ? t.insertPoints(set.xy.data(), set.pointCount(), ids.data())
                                      : t.insertPolylines(views.data(), views.size(), ids.data());
  const geocdt::Stats stats = t.stats();
  const geocdt::Mesh mesh = s.ok() ? t.release(meshOptions) : geocdt::Mesh();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double peak = static_cast<double>(bench::heapPeak() - heapBefore);
  if (!s.ok()) {
    std::fprintf(stderr, "bench_polylines: %s\n", s.message.c_str());
    return 1;
  }
  const double n = static_cast<double>(set.pointCount());
  std::printf(
      "%s, %s: %zu points, %.1f ms, %zu triangles, %llu crossings, %.2f walk steps a locate "
      "(%llu locates), %.2f flips a point, heap peak %.1f B per input point\n",
      argv[1], pointsOnly ? "points only" : "constrained", set.pointCount(), ms,
      mesh.triangles.size() / 3, static_cast<unsigned long long>(stats.crossings),
      static_cast<double>(stats.walkSteps) / static_cast<double>(stats.locates ? stats.locates : 1),
      static_cast<unsigned long long>(stats.locates), static_cast<double>(stats.flips) / n,
      peak / n);
  if (hash) {
    Hash h;
    h.add(mesh.points);
    h.add(mesh.triangles);
    h.add(mesh.halfedges);
    h.add(mesh.constrained);
    h.add(mesh.constraintEdges);
    h.add(mesh.sourceOffsets);
    h.add(mesh.sources);
    h.add(mesh.inside);
    h.add(mesh.regions);
    h.add(ids);
    std::printf("hash %016llx\n", static_cast<unsigned long long>(h.value()));
  }
  return 0;
}
